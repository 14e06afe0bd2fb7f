//! The benchmark programs in ST, and their hand-written Rust twins (same arithmetic: REAL
//! is f32, DINT wraps, REAL_TO_DINT rounds half to even).

use std::fmt::Write;

use crate::petri::{Arc, Net, PetriPou, Place, Transition};

/// The weighing example of the Petri net issue (the sequential weighing process of
/// `docs/weighing.md`, after Franczok, PAR 2014, as a Petri net POU), shipped in `examples/`.
pub const WEIGHING: &str = include_str!("../../../examples/weighing-sequential.plcproj.json");

/// B7's project: the same controller with its plant PROGRAM (`examples/weighing-plant.plcproj.json`).
pub const WEIGHING_PLANT: &str = include_str!("../../../examples/weighing-plant.plcproj.json");

/// B1 in ST: `n` iterations of `d := REAL_TO_DINT(a * b)` with a and b changing.
pub fn b1(n: u32) -> String {
    format!(
        "PROGRAM B1
VAR i : DINT; a : REAL; b : REAL; d : DINT; acc : DINT; END_VAR
a := 0.5;
b := 1.25;
acc := 0;
FOR i := 1 TO {n} DO
    a := a + 0.25;
    b := b - 0.125;
    d := REAL_TO_DINT(a * b);
    acc := acc + d;
END_FOR;
END_PROGRAM
"
    )
}

/// B1 in Rust; returns `acc`.
pub fn b1_native(n: u32) -> i32 {
    let (mut a, mut b, mut acc) = (0.5f32, 1.25f32, 0i32);
    for _ in 0..n {
        a += 0.25;
        b -= 0.125;
        let d = (a * b).round_ties_even() as i32;
        acc = acc.wrapping_add(d);
    }
    acc
}

/// B2 in ST: fill an `n`-element INT array in descending order, bubble-sort it, checksum.
pub fn b2(n: u32) -> String {
    format!(
        "PROGRAM B2
VAR arr : ARRAY[1..{n}] OF INT; i : DINT; j : DINT; t : INT; checksum : DINT; END_VAR
FOR i := 1 TO {n} DO
    arr[i] := DINT_TO_INT({n} - i);
END_FOR;
FOR i := 1 TO {n} - 1 DO
    FOR j := 1 TO {n} - i DO
        IF arr[j] > arr[j + 1] THEN
            t := arr[j];
            arr[j] := arr[j + 1];
            arr[j + 1] := t;
        END_IF;
    END_FOR;
END_FOR;
checksum := 0;
FOR i := 1 TO {n} DO
    checksum := checksum + INT_TO_DINT(arr[i]) * i;
END_FOR;
END_PROGRAM
"
    )
}

/// B2 in Rust; returns the checksum.
pub fn b2_native(n: u32) -> i32 {
    let n = n as usize;
    let mut arr: Vec<i16> = (1..=n).map(|i| (n - i) as i16).collect();
    for i in 1..n {
        for j in 0..n - i {
            if arr[j] > arr[j + 1] {
                arr.swap(j, j + 1);
            }
        }
    }
    arr.iter()
        .enumerate()
        .fold(0i32, |acc, (i, &v)| acc.wrapping_add((v as i32).wrapping_mul(i as i32 + 1)))
}

/// B3's net: one cycle of `places` places P1 → T1 → P2 → … → P1, a token in P1, the
/// action `n := n + 1;` in every place and the guard `Go` on every transition.
pub fn b3_net(places: usize) -> PetriPou {
    let places = places.max(1);
    let mut net = Net::default();
    for k in 1..=places {
        let mut place = Place::new(format!("P{k}"), k as i64, u32::from(k == 1));
        place.actions = "n := n + 1;".into();
        net.places.push(place);
        net.transitions.push(Transition::new(format!("T{k}"), "Go"));
        net.arcs.push(Arc::new(format!("P{k}"), format!("T{k}")));
        net.arcs.push(Arc::new(format!("T{k}"), format!("P{}", k % places + 1)));
    }
    PetriPou {
        name: "B3".into(),
        declarations: "VAR_INPUT Go : BOOL; END_VAR\nVAR n : DINT; END_VAR\n".into(),
        prologue: String::new(),
        epilogue: String::new(),
        net,
        options: Default::default(),
    }
}

/// B3: the CASE OF code the Petri net generator writes for [`b3_net`] (one step variable,
/// one branch per place, one transition each), or the generator's first error.
pub fn b3(places: usize) -> Result<String, String> {
    match crate::petri::compile(&b3_net(places)) {
        Ok(compiled) => Ok(compiled.generated.st),
        Err(diags) => Err(diags.first().map_or_else(String::new, |d| d.message.clone())),
    }
}

/// B6: a generated program of about `lines` lines (declarations, assignments, IFs, a
/// function block and calls).
pub fn b6(lines: usize) -> String {
    let mut s = String::from(
        "FUNCTION_BLOCK Scale\nVAR_INPUT x : DINT; k : DINT; END_VAR\nVAR_OUTPUT y : DINT; END_VAR\ny := x * k + 1;\nEND_FUNCTION_BLOCK\n\nPROGRAM Big\nVAR\n",
    );
    for k in 0..100 {
        let _ = writeln!(s, "    x{k} : DINT := {k};");
    }
    s.push_str("    f : Scale;\n    flag : BOOL;\nEND_VAR\n");
    let mut k = 0usize;
    while s.lines().count() < lines {
        match k % 10 {
            0 => {
                let _ = writeln!(
                    s,
                    "IF x{} > x{} THEN\n    x{} := x{} - {};\nEND_IF;",
                    k % 100,
                    (k * 3) % 100,
                    (k * 5) % 100,
                    k % 100,
                    k % 17
                );
            }
            5 => {
                let _ = writeln!(
                    s,
                    "f(x := x{}, k := {});\nx{} := f.y;",
                    k % 100,
                    k % 9 + 1,
                    (k * 11) % 100
                );
            }
            _ => {
                let _ = writeln!(s, "x{} := x{} + {} * 2;", k % 100, (k * 7) % 100, k);
            }
        }
        k += 1;
    }
    s.push_str("END_PROGRAM\n");
    s
}
