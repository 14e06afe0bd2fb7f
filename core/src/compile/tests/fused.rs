//! The fused instructions (element access, compare-and-branch): each program is checked to
//! compile to the instruction under test, then run for its values and its faults. Expected
//! values follow from docs/semantics.md by hand (wrapping in the index type, the destination's
//! bounds checked before anything on the right-hand side runs).

use crate::compile::{compile, Executable};
use crate::program::op::Op;
use crate::run::{run_source, RunOptions, RunStatus};
use crate::semantic;

/// The instructions of the main program of `src` (which must check).
fn code_of(src: &str) -> Vec<Op> {
    let analysis = semantic::analyze(src);
    let p = analysis.program.unwrap_or_else(|| panic!("{:?}", analysis.diagnostics));
    let main = p.programs().find(|&q| !p.pou(q).library).expect("a PROGRAM");
    let exe: Executable = compile(&p, main).expect("compiles");
    let entry = exe.pous[main as usize].entry as usize;
    let end = exe.out.code[entry..].iter().position(|op| matches!(op, Op::Ret)).expect("Ret");
    exe.out.code[entry..=entry + end].to_vec()
}

fn count(code: &[Op], pred: impl Fn(&Op) -> bool) -> usize {
    code.iter().filter(|op| pred(op)).count()
}

/// Runs one scan with `set` and returns the integer `var`, or the fault (message, line).
fn run1(src: &str, set: &[(&str, &str)], var: &str) -> Result<i64, (String, u32)> {
    let options = RunOptions {
        cycles: 1,
        set: set.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect(),
        ..RunOptions::default()
    };
    let report = run_source(src, &options);
    match report.status {
        RunStatus::Ok => Ok(report.vars[var].as_i64().unwrap_or_else(|| panic!("{var} not int"))),
        RunStatus::Fault => {
            let f = report.fault.expect("fault report");
            Err((f.message, f.line))
        }
        RunStatus::Error => panic!("{:?}", report.diagnostics),
    }
}

const LOAD: &str = "PROGRAM Main
VAR arr : ARRAY[1..5] OF INT := [10, 20, 30, 40, 50]; i : DINT := 1; r : INT; END_VAR
r := arr[i];
END_PROGRAM
";

#[test]
fn load_elem_reads_the_element_and_faults_out_of_range() {
    assert_eq!(count(&code_of(LOAD), |op| matches!(op, Op::LoadElem { .. })), 1);
    assert_eq!(run1(LOAD, &[("i", "1")], "r"), Ok(10));
    assert_eq!(run1(LOAD, &[("i", "5")], "r"), Ok(50));
    assert_eq!(
        run1(LOAD, &[("i", "0")], "r"),
        Err(("array index 0 is out of range 1..5".into(), 3))
    );
    assert_eq!(
        run1(LOAD, &[("i", "6")], "r"),
        Err(("array index 6 is out of range 1..5".into(), 3))
    );
}

#[test]
fn load_elem_with_a_constant_offset_wraps_in_the_index_type() {
    let src = "PROGRAM Main
VAR arr : ARRAY[1..5] OF INT := [10, 20, 30, 40, 50]; i : DINT; r : INT; END_VAR
r := arr[i + 1] + arr[i - 1] + arr[2 + i];
END_PROGRAM
";
    let code = code_of(src);
    // No separate additions: the offsets live in the element sites.
    assert_eq!(count(&code, |op| matches!(op, Op::LoadElem { .. })), 3);
    assert_eq!(count(&code, |op| matches!(op, Op::AddI32(_) | Op::SubI32(_))), 0);
    assert_eq!(run1(src, &[("i", "2")], "r"), Ok(30 + 10 + 40));
    assert_eq!(
        run1(src, &[("i", "4")], "r"),
        Err(("array index 6 is out of range 1..5".into(), 3)),
        "i + 2 = 6 is the first index out of range, checked left to right after i + 1"
    );
    // SINT index: 127 + 1 wraps to -128, which this array has.
    let wrap = "PROGRAM Main
VAR arr : ARRAY[-128..127] OF INT; i : SINT := 127; r : INT; END_VAR
arr[-128] := 7;
r := arr[i + 1];
END_PROGRAM
";
    assert_eq!(run1(wrap, &[], "r"), Ok(7));
    // USINT index: 0 - 1 wraps to 255.
    let unsigned = "PROGRAM Main
VAR arr : ARRAY[0..255] OF INT; u : USINT := 0; r : INT; END_VAR
arr[255] := 9;
r := arr[u - 1];
END_PROGRAM
";
    assert_eq!(run1(unsigned, &[], "r"), Ok(9));
    // DINT index past its maximum wraps to the minimum: out of this array's range, and
    // the message names the wrapped index, as the separate addition would give.
    let far = "PROGRAM Main
VAR arr : ARRAY[1..5] OF INT; i : DINT := 2147483647; r : INT; END_VAR
r := arr[i + 1];
END_PROGRAM
";
    assert_eq!(
        run1(far, &[], "r"),
        Err(("array index -2147483648 is out of range 1..5".into(), 3))
    );
}

#[test]
fn bounds_wider_than_the_index_type_keep_the_addition_separate() {
    // ARRAY[0..300] cannot fold `u + 1` of a USINT: 255 + 1 wraps to 0 in USINT.
    let src = "PROGRAM Main
VAR arr : ARRAY[0..300] OF INT; u : USINT := 255; r : INT; END_VAR
arr[0] := 5;
arr[256] := 6;
r := arr[u + 1];
END_PROGRAM
";
    assert_eq!(run1(src, &[], "r"), Ok(5));
}

const STORE: &str = "PROGRAM Main
VAR arr : ARRAY[1..5] OF DINT; i : DINT := 1; z : DINT; x : DINT := 7; r : DINT; END_VAR
arr[i] := x * 2;
r := arr[1] + arr[5];
arr[i] := 10 / z;
END_PROGRAM
";

#[test]
fn store_elem_writes_the_element_and_checks_the_destination_first() {
    let code = code_of(STORE);
    assert_eq!(count(&code, |op| matches!(op, Op::StoreElem { .. })), 1, "{code:?}");
    // The division can fault, so the second store settles its address first.
    assert_eq!(count(&code, |op| matches!(op, Op::ElemAddr { .. })), 1, "{code:?}");
    assert_eq!(run1(STORE, &[("i", "5"), ("z", "1")], "r"), Ok(14));
    assert_eq!(
        run1(STORE, &[("i", "9"), ("z", "1")], "r"),
        Err(("array index 9 is out of range 1..5".into(), 3))
    );
    // Index out of range and division by zero in the same statement: the index is
    // reported, as before the fusion (the destination is checked first).
    let both = STORE.replace("arr[i] := x * 2;\nr := arr[1] + arr[5];\n", "");
    assert_eq!(
        run1(&both, &[("i", "0")], "r"),
        Err(("array index 0 is out of range 1..5".into(), 3))
    );
    assert_eq!(run1(&both, &[("i", "1")], "r"), Err(("division by zero".into(), 3)));
}

const MOVE: &str = "PROGRAM Main
VAR a : ARRAY[1..3] OF INT := [1, 2, 3]; b : ARRAY[0..2] OF INT := [7, 8, 9];
    i : DINT := 1; k : DINT; r : INT; END_VAR
a[i] := b[k];
r := a[1] * 100 + a[2] * 10 + a[3];
END_PROGRAM
";

#[test]
fn move_elem_copies_and_checks_the_destination_before_the_source() {
    assert_eq!(count(&code_of(MOVE), |op| matches!(op, Op::MoveElem { .. })), 1);
    assert_eq!(run1(MOVE, &[("i", "2"), ("k", "2")], "r"), Ok(193));
    assert_eq!(
        run1(MOVE, &[("i", "4"), ("k", "7")], "r"),
        Err(("array index 4 is out of range 1..3".into(), 4))
    );
    assert_eq!(
        run1(MOVE, &[("i", "1"), ("k", "7")], "r"),
        Err(("array index 7 is out of range 0..2".into(), 4))
    );
    // The shift of a FIFO buffer: a[j] := a[j + 1] on one array.
    let fifo = "PROGRAM Main
VAR a : ARRAY[1..4] OF INT := [1, 2, 3, 4]; j : DINT; r : INT; END_VAR
FOR j := 1 TO 3 DO a[j] := a[j + 1]; END_FOR;
r := a[1] * 1000 + a[2] * 100 + a[3] * 10 + a[4];
END_PROGRAM
";
    assert_eq!(count(&code_of(fifo), |op| matches!(op, Op::MoveElem { .. })), 1);
    assert_eq!(run1(fifo, &[], "r"), Ok(2344));
}

#[test]
fn elem_addr_addresses_non_scalar_elements() {
    let src = "PROGRAM Main
VAR names : ARRAY[1..3] OF STRING[8]; i : DINT := 2; n : INT; END_VAR
names[i] := 'abc';
n := LEN(names[2]) * 10 + LEN(names[1]);
END_PROGRAM
";
    assert!(count(&code_of(src), |op| matches!(op, Op::ElemAddr { .. })) >= 1);
    assert_eq!(run1(src, &[], "n"), Ok(30));
    assert_eq!(
        run1(src, &[("i", "4")], "n"),
        Err(("array index 4 is out of range 1..3".into(), 3))
    );
}

#[cfg(feature = "bench")]
#[test]
fn bubble_sort_inner_loop_is_seven_instructions() {
    // The B2 benchmark's inner loop: two loads, one compare-and-branch, the swap from the
    // registers the comparison loaded (a move and two stores), and the FOR step.
    let src = crate::bench::programs::b2(10);
    let code = code_of(&src);
    let cmp = code.iter().position(|op| matches!(op, Op::JumpLe(_))).expect("the compare");
    let start = cmp - 2;
    let end =
        cmp + code[cmp..].iter().position(|op| matches!(op, Op::ForInc32 { .. })).expect("step");
    let body: Vec<_> = code[start..=end].iter().map(std::mem::discriminant).collect();
    let want = [
        Op::LoadElem { dst: 0, idx: 0, site: 0 },
        Op::LoadElem { dst: 0, idx: 0, site: 0 },
        Op::JumpLe(crate::program::op::Branch { a: 0, b: 0, target: 0 }),
        Op::Move { dst: 0, a: 0 },
        Op::StoreElem { idx: 0, site: 0, a: 0 },
        Op::StoreElem { idx: 0, site: 0, a: 0 },
        Op::ForInc32 { bits: 32, signed: true, v: 0, lim: 0, target: 0 },
    ];
    assert_eq!(body, want.iter().map(std::mem::discriminant).collect::<Vec<_>>(), "{code:?}");
}

/// `IF a <op> b THEN r := 1; ELSE r := 2; END_IF` for every comparison and both outcomes.
#[test]
fn compare_and_branch_takes_both_ways_for_every_relation() {
    type Relation = fn(i64, i64) -> bool;
    let cases: [(&str, Relation); 6] = [
        ("<", |a, b| a < b),
        ("<=", |a, b| a <= b),
        (">", |a, b| a > b),
        (">=", |a, b| a >= b),
        ("=", |a, b| a == b),
        ("<>", |a, b| a != b),
    ];
    for (op, holds) in cases {
        let src = format!(
            "PROGRAM Main
VAR a : DINT; b : DINT; r : INT; END_VAR
IF a {op} b THEN r := 1; ELSE r := 2; END_IF;
END_PROGRAM
"
        );
        let code = code_of(&src);
        let fused = |op: &Op| {
            matches!(
                op,
                Op::JumpLt(_)
                    | Op::JumpLe(_)
                    | Op::JumpGt(_)
                    | Op::JumpGe(_)
                    | Op::JumpEq(_)
                    | Op::JumpNe(_)
            )
        };
        assert_eq!(count(&code, fused), 1, "{op}: {code:?}");
        assert_eq!(count(&code, |op| matches!(op, Op::JumpIfNot { .. })), 0, "{op}");
        for (a, b) in [(-3i64, 5i64), (5, -3), (4, 4), (i32::MIN as i64, i32::MAX as i64)] {
            let want = if holds(a, b) { 1 } else { 2 };
            let set = [("a", a.to_string()), ("b", b.to_string())];
            let set: Vec<(&str, &str)> = set.iter().map(|(k, v)| (*k, v.as_str())).collect();
            assert_eq!(run1(&src, &set, "r"), Ok(want), "{a} {op} {b}");
        }
    }
}

#[test]
fn loops_and_negated_conditions_use_the_fused_jumps() {
    let src = "PROGRAM Main
VAR n : DINT; k : DINT; stop : BOOL; r : DINT; END_VAR
WHILE n < 10 DO n := n + 3; END_WHILE;
REPEAT k := k + 4; UNTIL k >= 10 END_REPEAT;
IF NOT stop THEN r := n * 100 + k; END_IF;
END_PROGRAM
";
    let code = code_of(src);
    assert_eq!(count(&code, |op| matches!(op, Op::JumpGe(_))), 1, "{code:?}");
    assert_eq!(count(&code, |op| matches!(op, Op::JumpLt(_))), 1, "{code:?}");
    assert_eq!(count(&code, |op| matches!(op, Op::JumpIf { .. })), 1, "{code:?}");
    assert_eq!(run1(src, &[], "r"), Ok(12 * 100 + 12));
    assert_eq!(run1(src, &[("stop", "TRUE")], "r"), Ok(0));
}

#[test]
fn an_empty_then_branch_skips_the_elsif_branches() {
    let src = "PROGRAM Main
VAR a : BOOL := TRUE; r : INT; END_VAR
IF a THEN
ELSIF TRUE THEN r := 1;
END_IF;
END_PROGRAM
";
    assert_eq!(run1(src, &[], "r"), Ok(0));
    assert_eq!(run1(src, &[("a", "FALSE")], "r"), Ok(1));
}

#[test]
fn an_if_without_else_jumps_nowhere_after_its_last_branch() {
    let src = "PROGRAM Main
VAR a : DINT; r : INT; END_VAR
IF a > 0 THEN r := 1; END_IF;
END_PROGRAM
";
    assert_eq!(count(&code_of(src), |op| matches!(op, Op::Jump { .. })), 0);
}

#[test]
fn and_not_is_one_instruction_in_every_integral_type() {
    let src = "PROGRAM Main
VAR a : BOOL; b : BOOL; x : BOOL; w : WORD := 16#F0F0; m : WORD := 16#FF00; y : WORD;
    r : DINT; END_VAR
x := a AND NOT b;
y := w AND NOT m;
r := BOOL_TO_DINT(x) * 100000 + WORD_TO_DINT(y);
END_PROGRAM
";
    assert_eq!(count(&code_of(src), |op| matches!(op, Op::AndNot(_))), 2);
    assert_eq!(count(&code_of(src), |op| matches!(op, Op::Not { .. })), 0);
    // 16#F0F0 AND NOT 16#FF00 = 16#00F0 = 240.
    for (a, b, want) in [("TRUE", "FALSE", 1), ("TRUE", "TRUE", 0), ("FALSE", "FALSE", 0)] {
        assert_eq!(run1(src, &[("a", a), ("b", b)], "r"), Ok(want * 100000 + 240), "{a} {b}");
    }
}

#[test]
fn true_and_x_is_x_but_x_is_still_evaluated() {
    let src = "FUNCTION Bump : BOOL
VAR_IN_OUT n : DINT; END_VAR
n := n + 1;
Bump := n > 1;
END_FUNCTION
PROGRAM Main
VAR n : DINT; x : BOOL; y : BOOL; r : DINT; END_VAR
x := TRUE AND Bump(n);
y := Bump(n) OR FALSE;
r := n * 100 + BOOL_TO_DINT(x) * 10 + BOOL_TO_DINT(y);
END_PROGRAM
";
    let code = code_of(src);
    assert_eq!(count(&code, |op| matches!(op, Op::And(_) | Op::Or(_))), 0, "{code:?}");
    assert_eq!(run1(src, &[], "r"), Ok(201));
}

#[test]
fn for_inc_wraps_the_control_variable_after_the_last_pass() {
    // FOR i := 125 TO 127 on a SINT: three passes, then i holds 127 + 1 wrapped (-128),
    // the first value that failed the test.
    let src = "PROGRAM Main
VAR i : SINT; u : USINT; n : DINT; r : DINT; END_VAR
FOR i := 125 TO 127 DO n := n + 1; END_FOR;
FOR u := 254 TO 255 DO n := n + 10; END_FOR;
r := n * 10000 + SINT_TO_DINT(i) * 10 + USINT_TO_DINT(u);
END_PROGRAM
";
    assert_eq!(count(&code_of(src), |op| matches!(op, Op::ForInc32 { .. })), 2);
    assert_eq!(run1(src, &[], "r"), Ok(23 * 10000 - 1280));
}

/// Runs one scan of `src` with a watchdog budget of `budget`.
fn scan_with_budget(src: &str, budget: u64) -> Result<(), crate::vm::Fault> {
    let analysis = semantic::analyze(src);
    let p = analysis.program.expect("checks");
    let main = p.programs().find(|&q| !p.pou(q).library).expect("a PROGRAM");
    let exe = compile(&p, main).expect("compiles");
    let mut m = crate::vm::Machine::new(&exe);
    m.run_scan(&exe, crate::vm::SysState::default(), budget).map_err(|e| e.fault)
}

#[test]
fn the_watchdog_charges_each_pass_of_a_loop() {
    // Each pass costs the instructions from the top of the body to the FOR step that jumps
    // back (the constant 1, the addition, the step: 3), so 1,000 passes cost 3,000: within
    // 100,000, over 1,000. An endless loop exceeds any budget.
    let counted = "PROGRAM Main
VAR i : DINT; n : DINT; END_VAR
FOR i := 1 TO 1000 DO n := n + 1; END_FOR;
END_PROGRAM
";
    assert_eq!(scan_with_budget(counted, 100_000), Ok(()));
    assert_eq!(
        scan_with_budget(counted, 1_000),
        Err(crate::vm::Fault::Watchdog { budget: 1_000 }),
        "1,000 passes cost at least 1,000"
    );
    let endless = "PROGRAM Main
VAR n : DINT; END_VAR
WHILE TRUE DO n := n + 1; END_WHILE;
END_PROGRAM
";
    assert_eq!(
        scan_with_budget(endless, 1_000_000),
        Err(crate::vm::Fault::Watchdog { budget: 1_000_000 })
    );
}

#[test]
fn compared_elements_are_reused_only_while_they_are_what_they_were() {
    // a[i] was loaded by the comparison; i := a[i] reuses it, then a[i] names another
    // element and is read again.
    let index = "PROGRAM Main
VAR a : ARRAY[1..3] OF DINT := [2, 5, 7]; i : DINT := 1; r : DINT; END_VAR
IF a[i] > 0 THEN i := a[i]; r := a[i]; END_IF;
END_PROGRAM
";
    assert_eq!(count(&code_of(index), |op| matches!(op, Op::LoadElem { .. })), 2);
    assert_eq!(run1(index, &[], "r"), Ok(5));
    // Writing an element drops every reused value: r reads the new a[i].
    let element = "PROGRAM Main
VAR a : ARRAY[1..2] OF DINT := [1, 5]; i : DINT := 1; r : DINT; END_VAR
IF a[i + 1] > a[i] THEN a[i] := a[i + 1]; r := a[i]; END_IF;
END_PROGRAM
";
    assert_eq!(run1(element, &[], "r"), Ok(5));
    // Only the branch the comparison guards: the ELSE branch loads again.
    let other = "PROGRAM Main
VAR a : ARRAY[1..2] OF DINT := [1, 5]; i : DINT := 1; r : DINT; END_VAR
IF a[i] > 3 THEN r := a[i]; ELSE i := 2; r := a[i]; END_IF;
END_PROGRAM
";
    assert_eq!(run1(other, &[], "r"), Ok(5));
}

#[test]
fn compiled_code_is_trusted_and_bad_code_is_not() {
    use crate::program::op::{Branch, R3};
    use crate::program::verify::{verify, FrameKind};
    // Every POU the compiler produced (the program, an FB, a function) passes.
    let src = "FUNCTION Twice : DINT
VAR_INPUT x : DINT; END_VAR
Twice := x * 2;
END_FUNCTION
FUNCTION_BLOCK Acc
VAR_INPUT x : DINT; END_VAR VAR_OUTPUT y : DINT; END_VAR
VAR buf : ARRAY[0..3] OF DINT; k : DINT; END_VAR
buf[k MOD 4] := x; k := k + 1; y := buf[0] + buf[1] + buf[2] + buf[3];
END_FUNCTION_BLOCK
PROGRAM Main
VAR a : Acc; i : DINT; r : DINT; END_VAR
FOR i := 1 TO 5 DO a(x := Twice(i)); END_FOR;
r := a.y;
END_PROGRAM
";
    let analysis = semantic::analyze(src);
    let p = analysis.program.expect("checks");
    let main = p.programs().find(|&q| !p.pou(q).library).expect("a PROGRAM");
    let exe = compile(&p, main).expect("compiles");
    let user: Vec<_> = exe.pous.iter().filter(|c| c.entry != u32::MAX && !c.library).collect();
    assert_eq!(user.len(), 3);
    assert!(user.iter().all(|c| c.trusted));
    assert_eq!(run1(src, &[], "r"), Ok(2 * (3 + 4 + 5 + 2)));
    // Hand-made regions: a register outside an 8-cell instance, a site past the table, a
    // jump out of the region, a region that does not end in Ret.
    let frame = FrameKind::Instance { size: 8 };
    let ok = [Op::Move { dst: 7, a: 0 }, Op::Ret];
    assert!(verify(&ok, (0, 2), 0, &[], frame));
    let bad_reg = [Op::AddI32(R3 { dst: 8, a: 0, b: 1 }), Op::Ret];
    assert!(!verify(&bad_reg, (0, 2), 0, &[], frame));
    let bad_site = [Op::LoadElem { dst: 0, idx: 1, site: 0 }, Op::Ret];
    assert!(!verify(&bad_site, (0, 2), 0, &[], frame));
    let bad_jump = [Op::JumpLe(Branch { a: 0, b: 1, target: 5 }), Op::Ret];
    assert!(!verify(&bad_jump, (0, 2), 0, &[], frame));
    let no_ret = [Op::Move { dst: 1, a: 0 }];
    assert!(!verify(&no_ret, (0, 1), 0, &[], frame));
    // A static frame reaches below its base (globals) but not past the image.
    let image = FrameKind::Static { base: 10, image: 20 };
    let below = [Op::Move { dst: u32::MAX, a: 9 }, Op::Ret]; // cells 9 and 19
    assert!(verify(&below, (0, 2), 0, &[], image));
    let past = [Op::Move { dst: 10, a: 0 }, Op::Ret]; // cell 20
    assert!(!verify(&past, (0, 2), 0, &[], image));
}
