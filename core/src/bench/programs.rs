//! The benchmark programs in ST, and their hand-written Rust twins (same arithmetic: REAL
//! is f32, DINT wraps, REAL_TO_DINT rounds half to even).

use std::fmt::Write;

/// The weighing example (seed 000), shipped in `examples/`.
pub const WEIGHING: &str = include_str!("../../../examples/weighing.st");

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

/// B3: the CASE OF code of a sequence of `places` places (one step variable, one branch
/// per place, one transition each), as the Petri-net generator writes it. The one place
/// B3 gets its code from: when the generator lands, this function returns its output for
/// a cycle of `places` places (input `Go` on every transition) and nothing else changes.
pub fn b3(places: usize) -> String {
    let mut s = String::from("PROGRAM B3\nVAR_INPUT Go : BOOL; END_VAR\nVAR p : INT := 1; n : DINT; END_VAR\nCASE p OF\n");
    for k in 1..=places {
        let next = if k == places { 1 } else { k + 1 };
        let _ = writeln!(
            s,
            "    {k}: (* P{k} *)\n        n := n + 1;\n        IF Go THEN p := {next}; END_IF;"
        );
    }
    s.push_str("END_CASE;\nEND_PROGRAM\n");
    s
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
