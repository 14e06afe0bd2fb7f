//! IL lowering: bodies run as the rules of `docs/il.md` say, and wrong bodies give located
//! errors (never a panic).

use crate::run::{run_source, RunOptions, RunReport, RunStatus};

fn run(src: &str, cycles: u64) -> RunReport {
    run_source(src, &RunOptions { cycles, ..RunOptions::default() })
}

fn var(r: &RunReport, name: &str) -> serde_json::Value {
    assert_eq!(r.status, RunStatus::Ok, "{:?}", r.diagnostics);
    r.vars.get(name).cloned().unwrap_or_else(|| panic!("no {name} in {:?}", r.vars))
}

fn errors(src: &str) -> Vec<(String, u32, String)> {
    let r = run(src, 1);
    r.diagnostics
        .iter()
        .filter(|d| d.severity == crate::diagnostics::Severity::Error)
        .map(|d| (d.code.clone(), d.line, d.message.clone()))
        .collect()
}

#[test]
fn the_lecture_rung_in_il() {
    let src = "PROGRAM Main\nVAR A : BOOL := TRUE; B : BOOL; C : BOOL; END_VAR\nLD A\nANDN B\nST C\nEND_PROGRAM\n";
    assert_eq!(var(&run(src, 1), "C"), serde_json::json!(true));
}

#[test]
fn a_stored_result_survives_the_store_and_a_reset() {
    // CR = A AND B = TRUE; R A clears A, but the CR keeps TRUE for ST D.
    let src = "PROGRAM Main\nVAR A : BOOL := TRUE; B : BOOL := TRUE; C, D : BOOL; END_VAR\n\
               LD A\nAND B\nST C\nR A\nST D\nEND_PROGRAM\n";
    let r = run(src, 1);
    assert_eq!(var(&r, "A"), serde_json::json!(false));
    assert_eq!(var(&r, "D"), serde_json::json!(true));
}

#[test]
fn deferred_operations_and_arithmetic() {
    let src = "PROGRAM Main\nVAR x : INT := 7; y : INT; b : BOOL; END_VAR\n\
               LD x\nMUL( 2\nADD 1\n)\nSUB 3\nST y\nGT 10\nST b\nEND_PROGRAM\n";
    let r = run(src, 1);
    assert_eq!(var(&r, "y"), serde_json::json!(18));
    assert_eq!(var(&r, "b"), serde_json::json!(true));
}

#[test]
fn jumps_loop_within_a_scan() {
    // Sum 1..5 with a backward jump.
    let src = "PROGRAM Main\nVAR i : INT; s : INT; END_VAR\n\
               LD 0\nST s\nST i\nLoop: LD i\nADD 1\nST i\nADD s\nST s\nLD i\nLT 5\nJMPC Loop\nEND_PROGRAM\n";
    let r = run(src, 1);
    assert_eq!(var(&r, "s"), serde_json::json!(15));
    assert_eq!(var(&r, "i"), serde_json::json!(5));
}

#[test]
fn calls_and_input_operators() {
    let src = "PROGRAM Main\nVAR go : BOOL := TRUE; T1 : TON; C1 : CTU; q : BOOL; n : INT; END_VAR\n\
               CAL T1(IN := go, PT := T#20ms)\nLD T1.Q\nST q\nLD 3\nPV C1\nLD go\nCU C1\nLD C1.CV\nST n\nEND_PROGRAM\n";
    let r = run(src, 3);
    assert_eq!(var(&r, "q"), serde_json::json!(true));
    assert_eq!(var(&r, "n"), serde_json::json!(1));
}

#[test]
fn functions_take_the_result_as_first_argument() {
    let src = "PROGRAM Main\nVAR x : INT := -12; y : INT; z : INT; END_VAR\n\
               LD x\nABS\nST y\nLD 0\nLIMIT x, 10\nST z\nEND_PROGRAM\n";
    let r = run(src, 1);
    assert_eq!(var(&r, "y"), serde_json::json!(12));
    assert_eq!(var(&r, "z"), serde_json::json!(0));
}

#[test]
fn located_errors() {
    let unknown = errors("PROGRAM Main\nVAR a : BOOL; END_VAR\nLD a\nLDX a\nEND_PROGRAM\n");
    assert!(unknown.iter().any(|(c, l, _)| c == "E0580" && *l == 4), "{unknown:?}");
    let label = errors("PROGRAM Main\nVAR a : BOOL; END_VAR\nLD a\nJMPC Nowhere\nEND_PROGRAM\n");
    assert!(label.iter().any(|(c, l, _)| c == "E0582" && *l == 4), "{label:?}");
    let ty =
        errors("PROGRAM Main\nVAR a : BOOL; i : INT; END_VAR\nLD i\nAND a\nST a\nEND_PROGRAM\n");
    assert!(ty.iter().any(|(_, l, _)| *l == 4), "{ty:?}");
    let none = errors("PROGRAM Main\nVAR a : BOOL; END_VAR\nST a\nEND_PROGRAM\n");
    assert!(none.iter().any(|(c, l, _)| c == "E0583" && *l == 3), "{none:?}");
}

#[test]
fn st_bodies_are_not_taken_for_il() {
    let src =
        "PROGRAM Main\nVAR LD : INT; S : BOOL; END_VAR\nLD := 3;\nS := LD > 2;\nEND_PROGRAM\n";
    assert_eq!(var(&run(src, 1), "S"), serde_json::json!(true));
}

#[test]
fn hostile_bodies_give_errors_not_panics() {
    let deep = format!(
        "PROGRAM Main\nVAR a : BOOL; END_VAR\nLD a\n{}ST a\nEND_PROGRAM\n",
        "AND( a\n".repeat(500)
    );
    assert!(!errors(&deep).is_empty());
    let long = format!(
        "PROGRAM Main\nVAR a : BOOL; END_VAR\nLD a\n{}ST a\nEND_PROGRAM\n",
        "AND a\n".repeat(5000)
    );
    assert_eq!(var(&run(&long, 1), "a"), serde_json::json!(false));
    let constant = format!(
        "PROGRAM Main\nVAR n : DINT; END_VAR\nLD 0\n{}ST n\nEND_PROGRAM\n",
        "ADD 1\n".repeat(5000)
    );
    assert_eq!(var(&run(&constant, 1), "n"), serde_json::json!(5000));
    for junk in
        ["LD", "LD (a", ")", "JMP", "CAL", "AND(", "L1:\nL1:\nRET", "LD 1,2", "&N", "LD a b"]
    {
        let src = format!("PROGRAM Main\nVAR a : BOOL; END_VAR\nL0: {junk}\nEND_PROGRAM\n");
        let _ = run(&src, 1);
    }
}

#[test]
fn the_lecture_example_agrees_in_ld_il_and_st_scan_by_scan() {
    use crate::project::Project;
    let text = include_str!("../../../examples/lecture-ld-il-st.plcproj.json");
    let project = Project::from_file(text).expect("the example opens");
    let mut sims: Vec<_> = ["LectureLD", "LectureIL", "LectureST"]
        .iter()
        .map(|p| crate::run::project_simulator(&project, Some(p)).expect("it builds"))
        .collect();
    // Every input combination, in an order that walks the latch through set, hold, reset
    // and the stop-wins case: 16 combinations, each held for one scan, twice over.
    let mut scans = 0;
    for round in 0..2u32 {
        for code in 0..16u32 {
            let bits = code ^ (code >> 1) ^ round;
            let inputs =
                [("A", bits & 1), ("B", bits & 2), ("Start", bits & 4), ("Stop", bits & 8)];
            let mut seen = Vec::new();
            for sim in &mut sims {
                for (name, on) in inputs {
                    sim.write(name, if on != 0 { "TRUE" } else { "FALSE" }).expect("input");
                }
                sim.scan();
                let c = sim.read("C").expect("C");
                let motor = sim.read("Motor").expect("Motor");
                seen.push(format!("{c:?} {motor:?}"));
            }
            assert!(
                seen.iter().all(|s| *s == seen[0]),
                "scan {scans}, inputs {inputs:?}: {seen:?}"
            );
            scans += 1;
        }
    }
    // The latch was both on and off at some point (the walk is not vacuous).
    assert_eq!(scans, 32);
}

#[test]
fn plcopen_xml_keeps_il_bodies_as_il() {
    use crate::project::Project;
    let text = include_str!("../../../examples/lecture-ld-il-st.plcproj.json");
    let project = Project::from_file(text).expect("the example opens");
    let xml = crate::plcopen::export(&project);
    let il_pou = xml.find("name=\"LectureIL\"").expect("LectureIL exported");
    let st_pou = xml.find("name=\"LectureST\"").expect("LectureST exported");
    assert!(xml[il_pou..st_pou].contains("<IL>"), "{}", &xml[il_pou..st_pou]);
    assert!(xml[st_pou..].contains("<ST>"));
    let back = crate::plcopen::import(&xml).expect("imports").project;
    for (name, a, b, c) in
        [("LectureIL", "TRUE", "FALSE", true), ("LectureIL", "TRUE", "TRUE", false)]
    {
        let mut sim = crate::run::project_simulator(&back, Some(name)).expect("builds");
        sim.write("A", a).expect("A");
        sim.write("B", b).expect("B");
        sim.scan();
        assert_eq!(
            format!("{:?}", sim.read("C").expect("C")),
            format!("{:?}", crate::vm::Value::Bool(c))
        );
    }
}

#[test]
fn a_beremiz_il_body_imports_and_runs() {
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="x" productName="x" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="il"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Main" pouType="program">
      <interface>
        <localVars>
          <variable name="A"><type><BOOL/></type><initialValue><simpleValue value="TRUE"/></initialValue></variable>
          <variable name="B"><type><BOOL/></type></variable>
          <variable name="C"><type><BOOL/></type></variable>
        </localVars>
      </interface>
      <body>
        <IL>
          <xhtml:p><![CDATA[LD A
ANDN B
ST C
]]></xhtml:p>
        </IL>
      </body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>"#;
    let import = crate::plcopen::import(xml).expect("imports");
    assert!(import.skipped.is_empty(), "{:?}", import.skipped);
    let report = crate::run::run_project(&import.project, &RunOptions::default());
    assert_eq!(var(&report, "C"), serde_json::json!(true));
}

#[test]
fn a_result_kept_inside_parentheses_does_not_overwrite_the_deferred_one() {
    // CR = A AND B = TRUE is kept (ST C, ST D); inside OR( the function Inv keeps its own
    // BOOL result: the deferred TRUE must survive it. E := TRUE OR Inv(TRUE) = TRUE (were it
    // overwritten: FALSE OR FALSE).
    let src = "FUNCTION Inv : BOOL\nVAR_INPUT x : BOOL; END_VAR\nLD x\nSTN Inv\nEND_FUNCTION\n\
               PROGRAM Main\nVAR A, B, F : BOOL := TRUE; C, D, E : BOOL; END_VAR\n\
               LD A\nAND B\nST C\nST D\nOR( F\nInv\n)\nST E\nEND_PROGRAM\n";
    let r = run(src, 1);
    assert_eq!(var(&r, "E"), serde_json::json!(true));
}

#[test]
fn random_instruction_lists_never_panic() {
    // A deterministic walk over operators, operands and labels, right and wrong alike.
    let ops = [
        "LD", "LDN", "ST", "STN", "S", "R", "AND", "ANDN", "&", "&N", "OR", "ORN", "XOR", "XORN",
        "NOT", "ADD", "SUB", "MUL", "DIV", "MOD", "GT", "GE", "EQ", "NE", "LT", "LE", "AND(",
        "OR(", "ADD(", ")", "JMP", "JMPC", "JMPCN", "CAL", "CALC", "CALCN", "RET", "RETC", "RETCN",
        "S1", "R1", "CLK", "CU", "PV", "IN", "PT", "ABS", "LIMIT", "FOO", "L1:", "L2:",
    ];
    let operands = [
        "a", "b", "i", "r", "t", "T1", "C1", "T1.Q", "5", "-3", "2.5", "T#1s", "L1", "L2", "",
        "a, 1", "(a",
    ];
    let mut seed = 0x9e37_79b9_u32;
    let mut next = |n: usize| {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        seed as usize % n
    };
    for _ in 0..200 {
        let mut body = String::new();
        for _ in 0..next(12) + 1 {
            body.push_str(&format!(
                "{} {}\n",
                ops[next(ops.len())],
                operands[next(operands.len())]
            ));
        }
        let src = format!(
            "PROGRAM Main\nVAR a, b : BOOL; i : INT; r : REAL; t : TIME; T1 : TON; C1 : CTU; END_VAR\nLD a\n{body}END_PROGRAM\n"
        );
        let _ = run(&src, 2);
    }
}

#[test]
fn did_you_mean_survives_the_lowering() {
    let src =
        "PROGRAM Main\nVAR_INPUT Start, Stop : BOOL; END_VAR\nVAR_OUTPUT Motor : BOOL; END_VAR\n\
               LD Start\nOR Motr\nANDN Stop\nST Motor\nEND_PROGRAM\n";
    let errs = errors(src);
    assert_eq!(
        errs,
        vec![("E0100".to_string(), 5, "`Motr` is not declared; did you mean Motor?".to_string())]
    );
    let analysis = crate::semantic::analyze(src);
    let d = analysis.diagnostics.iter().find(|d| d.is_error()).expect("an error");
    assert_eq!(d.suggestion.as_deref(), Some("Motor"));
    assert_eq!(&src[d.span.start as usize..d.span.end as usize], "Motr", "the operand's span");
    // A misspelled operator.
    let errs = errors("PROGRAM Main\nVAR a, b : BOOL; END_VAR\nLD a\nANDD b\nST a\nEND_PROGRAM\n");
    assert!(
        errs.iter().any(|(c, l, m)| c == "E0580" && *l == 4 && m.ends_with("; did you mean AND?")),
        "{errs:?}"
    );
}
