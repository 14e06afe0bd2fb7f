#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Ladder rungs run scan by scan through the one VM, and validation locations (the LD ↔
//! ST-view equivalence property is in `ladder_st_view_property.rs`).

mod common;

use common::*;
use plc_core::diagnostics::Code;
use plc_core::ladder::*;
use plc_core::project::Project;
use plc_core::run::{project_simulator, run_project, RunOptions, RunStatus};
use plc_core::sim::Simulator;

const LATCH_DECLS: &str =
    "VAR_INPUT Start : BOOL; Stop : BOOL; END_VAR\nVAR_OUTPUT Motor : BOOL; END_VAR";

fn latch() -> LadderPou {
    pou(LATCH_DECLS, vec![rung(&["[Start] +[/Stop] (Motor)", "[Motor] . ."])])
}

#[test]
fn latch_runs_scan_by_scan_and_has_its_st_view() {
    let p = latch();
    assert!(validate(&p).is_empty(), "{:?}", validate(&p));
    let (view, map) = st_view(&p);
    assert_eq!(view.trim(), "Motor := (Start OR Motor) AND NOT Stop;");
    assert_eq!(map, vec![(1, 0)]);
    let mut s = sim(&p);
    s.scan();
    assert!(!b(&s, "Motor"));
    s.write("Start", "TRUE").unwrap();
    s.scan();
    assert!(b(&s, "Motor"));
    s.write("Start", "FALSE").unwrap();
    s.scan();
    assert!(b(&s, "Motor"), "latched");
    assert!(b(&s, "LdPow_0_1_0"), "power map: the Motor contact conducts");
    s.write("Stop", "TRUE").unwrap();
    s.scan();
    assert!(!b(&s, "Motor"));
    assert!(power_map(&p)
        .iter()
        .any(|(r, row, c, v)| (*r, *row, *c) == (0, 1, 0) && v == "LdPow_0_1_0"));
}

#[test]
fn latch_through_run_project_json() {
    let options = RunOptions {
        set: vec![("Start".into(), "TRUE".into())],
        cycles: 2,
        ..RunOptions::default()
    };
    let report = run_project(&project(latch()), &options);
    assert_eq!(report.status, RunStatus::Ok, "{:?}", report.diagnostics);
    assert_eq!(report.vars["Motor"], serde_json::json!(true));
    assert!(!report.vars.keys().any(|k| k.starts_with("LdPow")));
}

#[test]
fn ton_delayed_lamp() {
    let mut r = rung(&["[Go] B (Lamp)"]);
    r.cells[0][1].element = block("TON", Some("T1"), &[("PT", "T#30ms")], &[("ET", "Elapsed")]);
    let p = pou("VAR Go : BOOL; Lamp : BOOL; T1 : TON; Elapsed : TIME; END_VAR", vec![r]);
    assert!(validate(&p).is_empty(), "{:?}", validate(&p));
    let mut s = sim(&p);
    s.write("Go", "TRUE").unwrap();
    s.scan(); // t = 0
    assert!(!b(&s, "Lamp"));
    s.scan(); // 10
    s.scan(); // 20
    assert!(!b(&s, "Lamp"));
    s.scan(); // 30
    assert!(b(&s, "Lamp"));
    s.write("Go", "FALSE").unwrap();
    s.scan();
    assert!(!b(&s, "Lamp"));
}

#[test]
fn ctu_counter_with_reset() {
    let mut r = rung(&["[P:Pulse] B (Done)"]);
    r.cells[0][1].element =
        block("CTU", Some("C1"), &[("R", "Reset"), ("PV", "3")], &[("CV", "Count")]);
    let p =
        pou("VAR Pulse : BOOL; Reset : BOOL; Done : BOOL; C1 : CTU; Count : INT; END_VAR", vec![r]);
    let mut s = sim(&p);
    for i in 1..=3 {
        s.write("Pulse", "TRUE").unwrap();
        s.scan();
        s.write("Pulse", "FALSE").unwrap();
        s.scan();
        assert_eq!(int(&s, "Count"), i);
    }
    assert!(b(&s, "Done"));
    s.write("Reset", "TRUE").unwrap();
    s.scan();
    assert_eq!(int(&s, "Count"), 0);
    assert!(!b(&s, "Done"));
}

#[test]
fn compare_and_move() {
    let mut r = rung(&["[Enable] B B (Big)"]);
    r.cells[0][1].element = block("GT", None, &[("IN1", "Level"), ("IN2", "50")], &[]);
    r.cells[0][2].element = block("MOVE", None, &[("IN", "Level")], &[("OUT", "Copy")]);
    let p = pou("VAR Enable : BOOL; Level : INT; Copy : INT; Big : BOOL; END_VAR", vec![r]);
    assert!(validate(&p).is_empty(), "{:?}", validate(&p));
    let mut s = sim(&p);
    s.write("Enable", "TRUE").unwrap();
    s.write("Level", "40").unwrap();
    s.scan();
    assert_eq!(int(&s, "Copy"), 0);
    assert!(!b(&s, "Big"));
    s.write("Level", "70").unwrap();
    s.scan();
    assert_eq!(int(&s, "Copy"), 70);
    assert!(b(&s, "Big"));
    let (view, _) = st_view(&p);
    assert!(view.contains("IF Enable AND (Level > 50) THEN Copy := Level; END_IF;"), "{view}");
}

#[test]
fn three_row_parallel_branch() {
    let p = pou(
        "VAR A : BOOL; B : BOOL; C : BOOL; D : BOOL; Out : BOOL; END_VAR",
        vec![rung(&["[A] +[D] (Out)", "[B] +. .", "[C] . ."])],
    );
    assert!(validate(&p).is_empty(), "{:?}", validate(&p));
    assert_eq!(st_view(&p).0.trim(), "Out := (A OR B OR C) AND D;");
    let mut s = sim(&p);
    s.write("D", "TRUE").unwrap();
    for (a, bb, c) in
        [(false, false, false), (false, false, true), (false, true, false), (true, false, false)]
    {
        s.write("A", if a { "TRUE" } else { "FALSE" }).unwrap();
        s.write("B", if bb { "TRUE" } else { "FALSE" }).unwrap();
        s.write("C", if c { "TRUE" } else { "FALSE" }).unwrap();
        s.scan();
        assert_eq!(b(&s, "Out"), a || bb || c);
    }
}

fn only(p: &LadderPou, code: Code) -> (usize, usize, usize) {
    let d = validate(p);
    let hits: Vec<_> = d.iter().filter(|d| d.code == code).collect();
    assert_eq!(hits.len(), 1, "{d:?}");
    (hits[0].rung, hits[0].row, hits[0].column)
}

const D: &str = "VAR A : BOOL; B : BOOL; C : BOOL; X : BOOL; Y : BOOL; T1 : TON; END_VAR";

#[test]
fn validation_rules_report_exact_locations() {
    let ok = rung(&["[A] (X)"]);
    // open circuit: a gap in the row
    let d = validate(&pou(D, vec![ok, rung(&["[A] . (Y)"])]));
    let open: Vec<_> = d
        .iter()
        .filter(|d| d.code == Code::LadderOpenCircuit)
        .map(|d| (d.rung, d.row, d.column))
        .collect();
    assert_eq!(open, vec![(1, 0, 0), (1, 0, 2)]);
    // leads nowhere
    assert_eq!(only(&pou(D, vec![rung(&["[A] [B] ."])]), Code::LadderOpenCircuit), (0, 0, 1));
    // short circuit
    assert_eq!(only(&pou(D, vec![rung(&["- - (X)"])]), Code::LadderShortCircuit), (0, 0, 2));
    assert_eq!(
        only(&pou(D, vec![rung(&["[A] +- (X)", "- . ."])]), Code::LadderShortCircuit),
        (0, 0, 2)
    );
    // ambiguous branch: rows 1 and 2 overlap (bridge)
    let bridge = rung(&["[A] +[B] [F] +(X)", ". [E] +[G] .", "[D] - . ."]);
    assert_eq!(only(&pou(D, vec![bridge]), Code::LadderAmbiguousBranch), (0, 0, 1));
    // missing operand
    assert_eq!(
        only(&pou(D, vec![rung(&["[A] (X)"]), rung(&["[] (X)"])]), Code::LadderMissingOperand),
        (1, 0, 0)
    );
    // bad operand
    assert_eq!(only(&pou(D, vec![rung(&["[A+B] (X)"])]), Code::LadderBadOperand), (0, 0, 0));
    // unknown block
    let mut r = rung(&["[A] B (X)"]);
    r.cells[0][1].element = block("NOPE", None, &[], &[]);
    let d = validate_with(&pou(D, vec![r]), &Catalog::standard());
    assert!(
        d.iter().any(|d| d.code == Code::LadderUnknownBlock && (d.row, d.column) == (0, 1)),
        "{d:?}"
    );
    // FB without instance
    let mut r = rung(&["[A] B (X)"]);
    r.cells[0][1].element = block("TON", None, &[("PT", "T#1s")], &[]);
    assert_eq!(only(&pou(D, vec![r]), Code::LadderMissingInstance), (0, 0, 1));
    // edge coil sharing a rung
    assert_eq!(
        only(&pou(D, vec![rung(&["[A] +(P:X)", "[B] (Y)"])]), Code::LadderEdgeCoilShared),
        (0, 0, 1)
    );
    // enable tied to the rail (warning)
    let mut r = rung(&["B (X)"]);
    r.cells[0][0].element = block("TON", Some("T1"), &[("PT", "T#1s")], &[]);
    assert_eq!(only(&pou(D, vec![r]), Code::LadderEnableFromRail), (0, 0, 0));
    // duplicate coil (warning)
    assert_eq!(
        only(&pou(D, vec![rung(&["[A] (X)"]), rung(&["[B] (X)"])]), Code::LadderDuplicateCoil),
        (1, 0, 1)
    );
    // after a coil
    assert_eq!(only(&pou(D, vec![rung(&["[A] (X) [B]"])]), Code::LadderAfterCoil), (0, 0, 2));
    // rows of different lengths; a block taller than the rung
    assert_eq!(only(&pou(D, vec![rung(&["[A] (X)", "[B]"])]), Code::LadderBadGrid), (0, 1, 0));
    let mut tall = Block::new("TON", Some("T1"));
    tall.height = 3;
    tall.inputs = vec![Pin::operand("PT", "T#1s")];
    let r = rung(&["[A] B (X)", ". # ."]);
    let mut r = r;
    r.cells[0][1].element = Element::Block(tall);
    assert_eq!(only(&pou(D, vec![r]), Code::LadderBadGrid), (0, 0, 1));
    // covered without block
    assert_eq!(only(&pou(D, vec![rung(&["[A] (X)", "# ."])]), Code::LadderStrayCovered), (0, 1, 0));
    // backward jump
    let mut r = rung(&["[A] (X)"]);
    r.label = Some("L1".into());
    let mut j = rung(&["[A] ."]);
    j.cells[0][1].element = Element::Jump { label: "L1".into() };
    assert_eq!(only(&pou(D, vec![r, j]), Code::LadderBadJump), (1, 0, 1));
}

#[test]
fn forward_jump_skips_rungs() {
    let mut j = rung(&["[A] ."]);
    j.cells[0][1].element = Element::Jump { label: "End".into() };
    let mut end = rung(&["[B] (Y)"]);
    end.label = Some("End".into());
    let p = pou(D, vec![j, rung(&["[B] (X)"]), end]);
    assert!(validate(&p).is_empty(), "{:?}", validate(&p));
    let mut s = sim(&p);
    s.write("A", "TRUE").unwrap();
    s.write("B", "TRUE").unwrap();
    s.scan();
    assert!(!b(&s, "X"));
    assert!(b(&s, "Y"));
    s.write("A", "FALSE").unwrap();
    s.scan();
    assert!(b(&s, "X"));
}

#[test]
fn st_type_errors_map_to_cells() {
    let p = pou("VAR A : BOOL; N : INT; END_VAR", vec![rung(&["[A] (N)"])]);
    let report = run_project(&project(p), &RunOptions::default());
    assert_eq!(report.status, RunStatus::Error);
    assert!(
        report.diagnostics.iter().any(|d| d.message.contains("rung 1, row 1, column 2")),
        "{:?}",
        report.diagnostics
    );
}

/// The five Done-when rungs, built as in the tests above.
fn done_when_pous() -> Vec<(LadderPou, Vec<&'static str>)> {
    let mut ton = rung(&["[Go] B (Lamp)"]);
    ton.cells[0][1].element = block("TON", Some("T1"), &[("PT", "T#30ms")], &[("ET", "Elapsed")]);
    let mut ctu = rung(&["[P:Pulse] B (Done)"]);
    ctu.cells[0][1].element =
        block("CTU", Some("C1"), &[("R", "Reset"), ("PV", "3")], &[("CV", "Count")]);
    let mut cmp = rung(&["[Enable] B B (Big)"]);
    cmp.cells[0][1].element = block("GT", None, &[("IN1", "Level"), ("IN2", "50")], &[]);
    cmp.cells[0][2].element = block("MOVE", None, &[("IN", "Level")], &[("OUT", "Copy")]);
    vec![
        (latch(), vec!["Start", "Stop"]),
        (pou("VAR_INPUT Go : BOOL; END_VAR VAR Lamp : BOOL; T1 : TON; Elapsed : TIME; END_VAR", vec![ton]), vec!["Go"]),
        (
            pou("VAR_INPUT Pulse : BOOL; Reset : BOOL; END_VAR VAR Done : BOOL; C1 : CTU; Count : INT; END_VAR", vec![ctu]),
            vec!["Pulse", "Reset"],
        ),
        (pou("VAR_INPUT Enable : BOOL; Big : BOOL; END_VAR VAR Level : INT := 70; Copy : INT; END_VAR", vec![cmp]), vec!["Enable"]),
        (
            pou(
                "VAR_INPUT A : BOOL; B : BOOL; C : BOOL; D : BOOL; END_VAR VAR Out : BOOL; END_VAR",
                vec![rung(&["[A] +[D] (Out)", "[B] +. .", "[C] . ."])],
            ),
            vec!["A", "B", "C", "D"],
        ),
    ]
}

#[test]
fn each_done_when_rung_runs_the_same_from_plcopen_xml() {
    for (p, inputs) in done_when_pous() {
        let direct = project(p.clone());
        let xml = plc_core::plcopen::export(&direct);
        let imported =
            plc_core::plcopen::import(&xml).unwrap_or_else(|e| panic!("{}: {e}", p.name)).project;
        let mut a = project_simulator(&direct, None).unwrap();
        let mut b = project_simulator(&imported, None).unwrap();
        // The same pseudo-random input sequence, scan by scan.
        let mut seed = 0x2545_f491_u32;
        for scan in 0..40 {
            for name in &inputs {
                seed ^= seed << 13;
                seed ^= seed >> 17;
                seed ^= seed << 5;
                let v = if seed.is_multiple_of(3) { "TRUE" } else { "FALSE" };
                a.write(name, v).unwrap();
                b.write(name, v).unwrap();
            }
            a.scan();
            b.scan();
            // The import re-lays the grid out (so hidden power variables differ); the
            // program's own variables must not.
            let visible = |s: &Simulator| {
                let mut m = s.vars_json();
                m.retain(|k, _| !is_hidden_name(k));
                m
            };
            assert_eq!(visible(&a), visible(&b), "{} differs on scan {scan}", p.name);
        }
    }
}

/// A coil that writes a variable a contact of its rung read: the view keeps the value the
/// contact saw for the coils after it, as the rung computes it.
#[test]
fn st_view_keeps_what_a_contact_read_before_a_coil_of_its_rung_overwrote_it() {
    let p = pou("VAR A : BOOL; X : BOOL; Y : BOOL; END_VAR", vec![rung(&["[A] +(/A)", ". (Y)"])]);
    let (view, _) = st_view(&p);
    assert_eq!(view, "LdTmp_0 := A;\nA := NOT A;\nY := LdTmp_0;\n");
    let mut ld = sim(&p);
    let mut st_project = Project::new("v");
    st_project.source = st_view_pou(&p);
    let mut st = project_simulator(&st_project, None).unwrap();
    for _ in 0..3 {
        ld.scan();
        st.scan();
        // A toggles; Y is what A was before this scan's toggle.
        assert_eq!(b(&ld, "Y"), !b(&ld, "A"));
        assert_eq!((b(&st, "A"), b(&st, "Y")), (b(&ld, "A"), b(&ld, "Y")));
    }
}
