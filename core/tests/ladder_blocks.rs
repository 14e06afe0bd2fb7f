#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Blocks on rungs beyond the standard ones: user FUNCTION_BLOCKs and FUNCTIONs on EN/ENO or
//! on a BOOL pin, second BOOL inputs wired to their own contact network, in-out pins, and
//! the validation of pins against the project's declarations (with exact locations).

mod common;

use common::*;
use plc_core::diagnostics::Code;
use plc_core::ladder::*;
use plc_core::run::{run_project, RunOptions, RunStatus};

/// A user FB that adds `Step` to `Total` on every call.
const ADDER: &str = "FUNCTION_BLOCK Adder
VAR_INPUT Step : INT; END_VAR
VAR_OUTPUT Total : INT; Big : BOOL; END_VAR
Total := Total + Step;
Big := Total >= 3;
END_FUNCTION_BLOCK
";

fn adder_rung(power_out: Option<&str>) -> Rung {
    let mut b = Block::new("Adder", Some("Acc"));
    b.height = 2;
    b.inputs = vec![Pin::operand("Step", "1")];
    b.outputs = vec![Pin::operand("Total", "n")];
    b.power_out = power_out.map(str::to_string);
    put(rung(&["[Run] B (Lamp)", ". # ."]), 0, 1, Element::Block(b))
}

const ADDER_DECLS: &str = "VAR Run : BOOL; Lamp : BOOL; n : INT; Acc : Adder; END_VAR";

#[test]
fn user_fb_on_en_runs_only_when_powered_and_eno_carries_the_power() {
    let p = pou(ADDER_DECLS, vec![adder_rung(None)]);
    let catalog = project_with(ADDER, p.clone()).catalog();
    assert!(validate_with(&p, &catalog).is_empty(), "{:?}", validate_with(&p, &catalog));
    let (view, _) = st_view(&p);
    assert_eq!(view, "IF Run THEN Acc(Step := 1); n := Acc.Total; END_IF;\nLamp := Run;\n");
    let mut s = sim_with(ADDER, &p);
    // Not powered: the FB is not called, so nothing is added.
    s.scan();
    assert_eq!((int(&s, "n"), b(&s, "Lamp"), b(&s, "LdPow_0_0_1")), (0, false, false));
    set(&mut s, "Run", true);
    s.scan();
    s.scan();
    assert_eq!((int(&s, "n"), b(&s, "Lamp"), b(&s, "LdPow_0_0_1")), (2, true, true));
    // Power off again: the call is skipped and the outputs keep their values.
    set(&mut s, "Run", false);
    s.scan();
    s.scan();
    assert_eq!((int(&s, "n"), int(&s, "Acc.Total"), b(&s, "Lamp")), (2, 2, false));
    set(&mut s, "Run", true);
    s.scan();
    assert_eq!(int(&s, "n"), 3);
    assert!(power_map(&p)
        .iter()
        .any(|(r, row, c, v)| (*r, *row, *c) == (0, 0, 1) && v == "LdPow_0_0_1"));
}

#[test]
fn a_bool_output_of_a_user_fb_can_carry_the_power_on() {
    let p = pou(ADDER_DECLS, vec![adder_rung(Some("Big"))]);
    let (view, _) = st_view(&p);
    assert!(view.ends_with("Lamp := Run AND Acc.Big;\n"), "{view}");
    let mut s = sim_with(ADDER, &p);
    set(&mut s, "Run", true);
    // Total 1, 2: not big; 3: big.
    for (scan, lamp) in [(1, false), (2, false), (3, true)] {
        s.scan();
        assert_eq!(b(&s, "Lamp"), lamp, "scan {scan}");
    }
    set(&mut s, "Run", false);
    s.scan();
    assert!(!b(&s, "Lamp"), "no power, no ENO-gated output");
}

/// CODESYS-style box: the rung's power goes into a BOOL input, and the FB runs every scan.
#[test]
fn a_user_fb_with_power_on_a_bool_input_runs_every_scan() {
    let src = "FUNCTION_BLOCK Confirm
VAR_INPUT In : BOOL; END_VAR
VAR_OUTPUT Q : BOOL; Scans : INT; END_VAR
VAR Last : BOOL; END_VAR
Q := In AND Last;
Last := In;
Scans := Scans + 1;
END_FUNCTION_BLOCK
";
    let mut b1 = Block::new("Confirm", Some("C"));
    b1.power_in = Some("In".into());
    b1.power_out = Some("Q".into());
    let r = put(rung(&["[Key] B (Lamp)"]), 0, 1, Element::Block(b1));
    let p = pou("VAR Key : BOOL; Lamp : BOOL; C : Confirm; END_VAR", vec![r]);
    let catalog = project_with(src, p.clone()).catalog();
    assert!(validate_with(&p, &catalog).is_empty(), "{:?}", validate_with(&p, &catalog));
    assert_eq!(st_view(&p).0, "C(In := Key);\nLamp := C.Q;\n");
    let mut s = sim_with(src, &p);
    s.scan();
    assert_eq!((b(&s, "Lamp"), int(&s, "C.Scans")), (false, 1), "called although unpowered");
    set(&mut s, "Key", true);
    s.scan();
    assert!(!b(&s, "Lamp"), "first scan with the key: not yet confirmed");
    s.scan();
    assert!(b(&s, "Lamp"), "second scan: confirmed");
    set(&mut s, "Key", false);
    s.scan();
    assert_eq!((b(&s, "Lamp"), int(&s, "C.Scans")), (false, 4));
}

const FUNCTIONS: &str = "FUNCTION Twice : INT
VAR_INPUT x : INT; END_VAR
Twice := x * 2;
END_FUNCTION
FUNCTION InRange : BOOL
VAR_INPUT v : INT; lo : INT; hi : INT; END_VAR
InRange := v >= lo AND v <= hi;
END_FUNCTION
";

#[test]
fn user_functions_on_en_write_their_result_and_pass_power() {
    let mut twice = Block::new("Twice", None);
    twice.inputs = vec![Pin::operand("x", "a")];
    twice.outputs = vec![Pin::operand("OUT", "y")];
    let mut range = Block::new("InRange", None);
    range.inputs = vec![Pin::operand("v", "a"), Pin::operand("lo", "2"), Pin::operand("hi", "4")];
    range.power_out = Some("OUT".into());
    let r1 = put(rung(&["[Go] B (Done)"]), 0, 1, Element::Block(twice));
    let r2 = put(rung(&["[Go] B (Lamp)"]), 0, 1, Element::Block(range));
    let p = pou("VAR Go : BOOL; a : INT; y : INT; Done : BOOL; Lamp : BOOL; END_VAR", vec![r1, r2]);
    let catalog = project_with(FUNCTIONS, p.clone()).catalog();
    assert!(validate_with(&p, &catalog).is_empty(), "{:?}", validate_with(&p, &catalog));
    let view = st_view(&p).0;
    assert!(view.contains("IF Go THEN y := Twice(x := a); END_IF;"), "{view}");
    assert!(view.contains("Lamp := (Go AND_THEN InRange(v := a, lo := 2, hi := 4));"), "{view}");
    let mut s = sim_with(FUNCTIONS, &p);
    s.write("a", "3").unwrap();
    s.scan();
    assert_eq!((int(&s, "y"), b(&s, "Done"), b(&s, "Lamp")), (0, false, false));
    set(&mut s, "Go", true);
    s.scan();
    assert_eq!((int(&s, "y"), b(&s, "Done"), b(&s, "Lamp")), (6, true, true));
    s.write("a", "5").unwrap();
    s.scan();
    assert_eq!((int(&s, "y"), b(&s, "Lamp")), (10, false));
    set(&mut s, "Go", false);
    s.write("a", "7").unwrap();
    s.scan();
    assert_eq!(int(&s, "y"), 10, "not enabled: the result is not written");
}

/// CTU with R wired to its own contact on the block's second row, as CODESYS draws it.
fn wired_counter() -> LadderPou {
    let mut ctu = Block::new("CTU", Some("C1"));
    ctu.height = 3;
    ctu.inputs = vec![Pin::wired("R", 1), Pin::operand("PV", "2")];
    ctu.outputs = vec![Pin::operand("CV", "Count")];
    let r = put(rung(&["[P:Pulse] B (Done)", "[Reset] # .", ". # ."]), 0, 1, Element::Block(ctu));
    pou("VAR Pulse : BOOL; Reset : BOOL; Done : BOOL; C1 : CTU; Count : INT; END_VAR", vec![r])
}

#[test]
fn a_second_bool_input_wired_to_its_own_contact() {
    let p = wired_counter();
    assert!(validate_with(&p, &Catalog::standard()).is_empty(), "{:?}", validate(&p));
    let view = st_view(&p).0;
    assert!(view.contains("C1(CU := LdEdge_0.Q, R := Reset, PV := 2);"), "{view}");
    let mut s = sim(&p);
    for (k, want) in [(1, false), (2, true)] {
        set(&mut s, "Pulse", true);
        s.scan();
        set(&mut s, "Pulse", false);
        s.scan();
        assert_eq!((int(&s, "Count"), b(&s, "Done")), (k, want));
    }
    // The reset contact on row 2 reaches R: the count clears while the pulses go on.
    set(&mut s, "Reset", true);
    set(&mut s, "Pulse", true);
    s.scan();
    assert_eq!((int(&s, "Count"), b(&s, "Done")), (0, false));
    set(&mut s, "Reset", false);
    set(&mut s, "Pulse", false);
    s.scan();
    set(&mut s, "Pulse", true);
    s.scan();
    assert_eq!(int(&s, "Count"), 1);
}

#[test]
fn in_out_pins_pass_the_variable_itself() {
    let src = "FUNCTION_BLOCK Accumulate
VAR_INPUT Add : INT; END_VAR
VAR_IN_OUT Sum : INT; END_VAR
Sum := Sum + Add;
END_FUNCTION_BLOCK
";
    let mut acc = Block::new("Accumulate", Some("A"));
    acc.height = 2;
    acc.inputs = vec![Pin::operand("Add", "5")];
    acc.in_outs = vec![Pin::operand("Sum", "total")];
    let r = put(rung(&["[Go] B (Lamp)", ". # ."]), 0, 1, Element::Block(acc));
    let p = pou("VAR Go : BOOL; Lamp : BOOL; total : INT := 1; A : Accumulate; END_VAR", vec![r]);
    let catalog = project_with(src, p.clone()).catalog();
    assert!(validate_with(&p, &catalog).is_empty(), "{:?}", validate_with(&p, &catalog));
    let mut s = sim_with(src, &p);
    set(&mut s, "Go", true);
    s.scan();
    s.scan();
    assert_eq!(int(&s, "total"), 11);
}

/// The diagnostics of `p` validated against `source`, as `(code, rung, row, column)`.
fn problems(source: &str, p: &LadderPou) -> Vec<(Code, usize, usize, usize)> {
    let catalog = project_with(source, p.clone()).catalog();
    validate_with(p, &catalog).iter().map(|d| (d.code, d.rung, d.row, d.column)).collect()
}

fn one_block(decls: &str, b: Block, height_rows: &[&str]) -> LadderPou {
    let mut rows = vec!["[Run] B (Lamp)"];
    rows.extend_from_slice(height_rows);
    pou(decls, vec![put(rung(&rows), 0, 1, Element::Block(b))])
}

#[test]
fn pins_are_checked_against_the_declarations_at_the_block() {
    let decls =
        "VAR Run : BOOL; Lamp : BOOL; n : INT; t : TIME; Acc : Adder; T1 : TON; F1 : TOF; END_VAR";
    let at_block = |code| vec![(code, 0, 0, 1)];
    // A pin the FB does not have.
    let mut b1 = Block::new("Adder", Some("Acc"));
    b1.inputs = vec![Pin::operand("Stp", "1")];
    assert_eq!(problems(ADDER, &one_block(decls, b1, &[])), at_block(Code::LadderUnknownPin));
    // The same pin twice.
    let mut b1 = Block::new("Adder", Some("Acc"));
    b1.inputs = vec![Pin::operand("Step", "1"), Pin::operand("step", "2")];
    assert_eq!(problems(ADDER, &one_block(decls, b1, &[])), at_block(Code::LadderUnknownPin));
    // The power input given as a pin too.
    let mut b1 = Block::new("TON", Some("T1"));
    b1.inputs = vec![Pin::operand("IN", "Run"), Pin::operand("PT", "T#1s")];
    assert_eq!(problems("", &one_block(decls, b1, &[])), at_block(Code::LadderUnknownPin));
    // A BOOL where a TIME is needed, and an INT output into a TIME variable.
    let mut b1 = Block::new("TON", Some("T1"));
    b1.inputs = vec![Pin::operand("PT", "Run")];
    assert_eq!(problems("", &one_block(decls, b1, &[])), at_block(Code::LadderPinType));
    let mut b1 = Block::new("Adder", Some("Acc"));
    b1.outputs = vec![Pin::operand("Total", "t")];
    assert_eq!(problems(ADDER, &one_block(decls, b1, &[])), at_block(Code::LadderPinType));
    // A literal that does not fit, and one that does (an integer literal into INT).
    let mut b1 = Block::new("Adder", Some("Acc"));
    b1.inputs = vec![Pin::operand("Step", "T#2s")];
    assert_eq!(problems(ADDER, &one_block(decls, b1, &[])), at_block(Code::LadderPinType));
    // The instance declared as another FB type, and a FUNCTION given an instance.
    let b1 = Block::new("TON", Some("F1"));
    let mut b1 = b1;
    b1.inputs = vec![Pin::operand("PT", "T#1s")];
    assert_eq!(problems("", &one_block(decls, b1, &[])), at_block(Code::LadderInstanceType));
    let mut b1 = Block::new("Twice", Some("T1"));
    b1.inputs = vec![Pin::operand("x", "n")];
    assert_eq!(problems(FUNCTIONS, &one_block(decls, b1, &[])), at_block(Code::LadderInstanceType));
    // An undeclared operand and an undeclared instance.
    let mut b1 = Block::new("Adder", Some("Acc"));
    b1.inputs = vec![Pin::operand("Step", "nn")];
    assert_eq!(
        problems(ADDER, &one_block(decls, b1, &[])),
        at_block(Code::LadderUndeclaredOperand)
    );
    let b1 = Block::new("Adder", Some("Acc2"));
    assert_eq!(
        problems(ADDER, &one_block(decls, b1, &[])),
        at_block(Code::LadderUndeclaredOperand)
    );
    // An unknown block type (the user POU is missing from the project).
    let b1 = Block::new("Adder", Some("Acc"));
    assert_eq!(problems("", &one_block(decls, b1, &[])), at_block(Code::LadderUnknownBlock));
}

#[test]
fn missing_pins_power_pins_and_wired_rows_are_reported_where_they_are() {
    let decls =
        "VAR Run : BOOL; Lamp : BOOL; n : INT; k : INT; A : Acc; C1 : CTU; C2 : CTUD; END_VAR";
    let src = "FUNCTION_BLOCK Acc
VAR_INPUT Step : INT; On : BOOL; END_VAR
VAR_IN_OUT Sum : INT; END_VAR
VAR_OUTPUT Q : BOOL; Level : INT; END_VAR
Sum := Sum + Step; Q := Sum > 0; Level := Sum;
END_FUNCTION_BLOCK
";
    // A VAR_IN_OUT left unconnected; a standard function missing an input.
    let b1 = Block::new("Acc", Some("A"));
    assert_eq!(problems(src, &one_block(decls, b1, &[])), vec![(Code::LadderMissingPin, 0, 0, 1)]);
    let mut b1 = Block::new("SUB", None);
    b1.inputs = vec![Pin::operand("IN1", "n")];
    b1.outputs = vec![Pin::operand("OUT", "k")];
    assert_eq!(problems(src, &one_block(decls, b1, &[])), vec![(Code::LadderMissingPin, 0, 0, 1)]);
    // Power into an INT input; ENO without EN; power out of an INT output.
    let with_sum = |b: &mut Block| b.in_outs = vec![Pin::operand("Sum", "n")];
    let mut b1 = Block::new("Acc", Some("A"));
    with_sum(&mut b1);
    b1.power_in = Some("Step".into());
    b1.power_out = Some("Q".into());
    assert_eq!(problems(src, &one_block(decls, b1, &[])), vec![(Code::LadderBadPowerPin, 0, 0, 1)]);
    let mut b1 = Block::new("Acc", Some("A"));
    with_sum(&mut b1);
    b1.power_in = Some("On".into());
    assert_eq!(problems(src, &one_block(decls, b1, &[])), vec![(Code::LadderBadPowerPin, 0, 0, 1)]);
    let mut b1 = Block::new("Acc", Some("A"));
    with_sum(&mut b1);
    b1.power_out = Some("Level".into());
    assert_eq!(problems(src, &one_block(decls, b1, &[])), vec![(Code::LadderBadPowerPin, 0, 0, 1)]);
    // Wired inputs: outside the block, sharing a row, with an operand, not BOOL.
    let counter = |inputs: Vec<Pin>| {
        let mut b = Block::new("CTU", Some("C1"));
        b.height = 3;
        b.inputs = inputs;
        b
    };
    let none: &[&str] = &[". # .", ". # ."];
    let one: &[&str] = &["[Run] # .", ". # ."];
    let two: &[&str] = &["[Run] # .", "[Run] # ."];
    let p = one_block(decls, counter(vec![Pin::wired("R", 3)]), none);
    assert_eq!(problems("", &p), vec![(Code::LadderBadWiredPin, 0, 0, 1)]);
    let p = one_block(decls, counter(vec![Pin::wired("R", 1), Pin::wired("PV", 2)]), two);
    assert_eq!(problems("", &p), vec![(Code::LadderBadWiredPin, 0, 2, 1)]);
    let mut r = Pin::wired("R", 1);
    r.operand = "Run".into();
    let p = one_block(decls, counter(vec![r]), one);
    assert_eq!(problems("", &p), vec![(Code::LadderBadWiredPin, 0, 1, 1)]);
    let mut updown = counter(vec![Pin::wired("R", 1), Pin::wired("LD", 1)]);
    updown.type_name = "CTUD".into();
    updown.instance = Some("C2".into());
    let p = one_block(decls, updown, one);
    assert_eq!(problems("", &p), vec![(Code::LadderBadWiredPin, 0, 1, 1)]);
    let p = one_block(decls, counter(vec![Pin::wired("R", 1), Pin::wired("R", 2)]), two);
    let got = problems("", &p);
    assert!(got.contains(&(Code::LadderUnknownPin, 0, 0, 1)), "{got:?}");
}

#[test]
fn wired_inputs_need_a_power_path_and_warn_when_tied_to_the_rail() {
    let decls = "VAR Run : BOOL; Lamp : BOOL; C1 : CTU; END_VAR";
    let mut ctu = Block::new("CTU", Some("C1"));
    ctu.height = 2;
    ctu.inputs = vec![Pin::wired("R", 1), Pin::operand("PV", "3")];
    // Nothing on row 2: open circuit at the pin's cell.
    let p = pou(
        decls,
        vec![put(rung(&["[Run] B (Lamp)", ". # ."]), 0, 1, Element::Block(ctu.clone()))],
    );
    assert_eq!(problems("", &p), vec![(Code::LadderOpenCircuit, 0, 1, 1)]);
    // A bare wire from the rail: a warning at the pin's cell.
    let p = pou(decls, vec![put(rung(&["[Run] B (Lamp)", "- # ."]), 0, 1, Element::Block(ctu))]);
    assert_eq!(problems("", &p), vec![(Code::LadderPinFromRail, 0, 1, 1)]);
}

#[test]
fn contact_and_coil_operands_are_checked_too() {
    let p =
        pou("VAR Run : BOOL; n : INT; END_VAR", vec![rung(&["[Run] (n)"]), rung(&["[Rn] (Run)"])]);
    assert_eq!(
        problems("", &p),
        vec![(Code::LadderPinType, 0, 0, 1), (Code::LadderUndeclaredOperand, 1, 0, 0)]
    );
}

/// `project_source` validates with the project's POUs: a block naming a POU that is not
/// there is reported at its cell by the ladder check, not later by the ST checker.
#[test]
fn run_project_reports_unknown_user_blocks_at_the_cell() {
    let b1 = Block::new("Adder", Some("Acc"));
    let p = one_block(ADDER_DECLS, b1, &[]);
    let report = run_project(&project_with("", p), &RunOptions::default());
    assert_eq!(report.status, RunStatus::Error);
    let d = &report.diagnostics[0];
    assert_eq!(d.code, "E0405");
    assert!(d.message.starts_with("POU Main, rung 1, row 1, column 2: `Adder`"), "{}", d.message);
}

/// An undeclared operand one edit from a declared variable says which one it probably
/// means, in the message and as the fix's data; the POU's own variables come first.
#[test]
fn an_undeclared_operand_gets_did_you_mean() {
    let p = pou(
        "VAR_INPUT Start, Stop : BOOL; END_VAR VAR_OUTPUT Motor : BOOL; END_VAR",
        vec![rung(&["[Start] [/Stpo] (Motr)"]), rung(&["[Pressure] (Motor)"])],
    );
    let catalog = project_with("", p.clone()).catalog();
    let found: Vec<(usize, usize, String, Option<String>)> = validate_with(&p, &catalog)
        .into_iter()
        .filter(|d| d.code == Code::LadderUndeclaredOperand)
        .map(|d| (d.rung, d.column, d.message, d.suggestion))
        .collect();
    assert_eq!(
        found,
        vec![
            (
                0,
                1,
                "this contact's operand `Stpo` is not declared; did you mean Stop?".into(),
                Some("Stop".into())
            ),
            (
                0,
                2,
                "this coil's operand `Motr` is not declared; did you mean Motor?".into(),
                Some("Motor".into())
            ),
            (1, 0, "this contact's operand `Pressure` is not declared".into(), None),
        ]
    );
    // A block pin's operand too.
    let mut b1 = Block::new("TON", Some("T1"));
    b1.inputs = vec![Pin::operand("PT", "Dealy")];
    let p = one_block("VAR Run, Lamp : BOOL; T1 : TON; Delay : TIME; END_VAR", b1, &[]);
    let catalog = project_with("", p.clone()).catalog();
    let d = validate_with(&p, &catalog);
    assert!(d.iter().any(|d| d.suggestion.as_deref() == Some("Delay")), "{d:?}");
}

#[test]
fn an_unknown_block_type_names_the_closest_block() {
    let p =
        one_block("VAR Run, Lamp : BOOL; T1 : TON; END_VAR", Block::new("TNO", Some("T1")), &[]);
    let catalog = project_with("", p.clone()).catalog();
    let d = validate_with(&p, &catalog);
    let unknown = d.iter().find(|d| d.code == Code::LadderUnknownBlock).expect("E0405");
    assert_eq!(
        unknown.message,
        "`TNO` is neither a standard block nor a FUNCTION_BLOCK or FUNCTION of the project; did you mean TON?"
    );
}
