#![allow(clippy::unwrap_used)]

use super::*;
use crate::semantic;
use crate::semantic::types::Elem;
use crate::sim::Simulator;
use crate::vm::Value;

fn sim(source: &str) -> Simulator {
    let analysis = semantic::analyze(source);
    let errors: Vec<_> = analysis.diagnostics.iter().filter(|d| d.is_error()).collect();
    assert!(errors.is_empty(), "{errors:?}");
    let program = analysis.program.unwrap();
    let main = program.programs().find(|&p| !program.pou(p).library).unwrap();
    Simulator::new(program, main).unwrap()
}

const SRC: &str = "
TYPE Point : STRUCT x : INT; y : REAL; END_STRUCT; END_TYPE
PROGRAM Main
VAR_INPUT Start AT %IX0.0 : BOOL; (* start, button *) END_VAR
VAR_OUTPUT Motor : BOOL; Level : INT; END_VAR
VAR
  p : Point;
  arr : ARRAY[1..3] OF INT;
  m : ARRAY[0..1, 2..3] OF BOOL;
  t : TON;
  s : STRING := 'a$'b';
  r : LREAL;
END_VAR
Motor := Start;
Level := Level - 3;
r := r + 0.5;
arr[2] := Level;
t(IN := Start, PT := T#20ms);
END_PROGRAM";

#[test]
fn literals() {
    assert_eq!(value_text(&Value::Bool(true)), "TRUE");
    assert_eq!(value_text(&Value::Int(-5, Elem::Int)), "-5");
    assert_eq!(value_text(&Value::Real(0.1f32 as f64, Elem::Real)), "0.1");
    assert_eq!(value_text(&Value::Time(1_500_000_000)), "T#1s500ms");
    assert_eq!(value_text(&Value::Str(b"it's $5\n".to_vec())), "'it$'s $$5$N'");
    assert_eq!(
        value_text(&Value::Struct(vec![
            ("a".into(), Value::Int(1, Elem::Int)),
            ("b".into(), Value::Array(vec![Value::Bool(false)]))
        ])),
        "(a := 1, b := [FALSE])"
    );
    assert_eq!(value_number(&Value::Bool(true)), Some(1.0));
    assert_eq!(value_number(&Value::Time(2_000_000)), Some(2.0));
    assert_eq!(value_number(&Value::Str(vec![])), None);
    assert_eq!(ms_text(10_000_000), "10");
    assert_eq!(ms_text(2_500_000), "2.5");
    assert_eq!(ms_text(1_000), "0.001");
}

#[test]
fn children_of_aggregates() {
    let s = sim(SRC);
    let exe = s.executable();
    let ty = |name: &str| exe.main_vars().iter().find(|v| v.var.name == name).unwrap().var.ty;
    let p: Vec<String> = children(exe, "p", ty("p")).into_iter().map(|c| c.path).collect();
    assert_eq!(p, ["p.x", "p.y"]);
    let a: Vec<String> = children(exe, "arr", ty("arr")).into_iter().map(|c| c.label).collect();
    assert_eq!(a, ["[1]", "[2]", "[3]"]);
    let m: Vec<String> = children(exe, "m", ty("m")).into_iter().map(|c| c.path).collect();
    assert_eq!(m, ["m[0,2]", "m[0,3]", "m[1,2]", "m[1,3]"]);
    let t: Vec<String> = children(exe, "t", ty("t")).into_iter().map(|c| c.label).collect();
    assert!(t.iter().any(|l| l == "Q") && t.iter().any(|l| l == "ET"), "{t:?}");
    for c in children(exe, "t", ty("t")) {
        assert!(s.read(&c.path).is_ok(), "{}", c.path);
    }
    assert!(children(exe, "Motor", ty("Motor")).is_empty());
    assert!(is_expandable(ty("t")) && !is_expandable(ty("Motor")));
}

#[test]
fn variables_snapshot_csv() {
    let mut s = sim(SRC);
    s.run_scans(1);
    let rows = snapshot(&s);
    let start = rows.iter().find(|r| r.path == "Start").unwrap();
    assert_eq!(start.address, "%IX0.0");
    assert_eq!(start.ty, "BOOL");
    assert!(rows.iter().any(|r| r.path == "arr[2]" && r.value == "-3"));
    assert!(rows.iter().any(|r| r.path == "m[1,3]" && r.value == "FALSE"));
    let csv = variables_csv(&rows);
    assert!(csv.starts_with("name,address,type,value\r\n"));
    assert!(csv.contains("Start,%IX0.0,BOOL,FALSE\r\n"));
    assert!(csv.contains("\"m[1,3]\",,BOOL,FALSE\r\n"), "{csv}");
    assert!(csv.contains("s,,STRING[80],'a$'b'\r\n") || csv.contains("s,,"), "{csv}");
    assert_eq!(csv_field("a\"b"), "\"a\"\"b\"");
}

fn traced() -> Simulator {
    let mut s = sim(SRC);
    s.set_cycle_ns(10_000_000);
    s.set_trace(&["Motor", "Level", "r", "t.ET", "s"], 100).unwrap();
    s.run_scans(2);
    s.hold("Start", "TRUE").unwrap();
    s.run_scans(3);
    s
}

#[test]
fn trace_as_csv() {
    let s = traced();
    let csv = trace_csv(s.trace());
    let lines: Vec<&str> = csv.split("\r\n").collect();
    assert_eq!(lines[0], "time_ms,scan,Motor,Level,r,t.ET,s");
    assert_eq!(lines[1], "10,1,0,-3,0.5,T#0s,'a$'b'");
    assert_eq!(lines[3], "30,3,1,-9,1.5,T#0s,'a$'b'");
    assert_eq!(lines.len(), 7);
}

#[test]
fn trace_as_vcd() {
    let s = traced();
    let vcd = trace_vcd(s.trace());
    assert!(vcd.contains("$timescale 1 ms $end"), "{vcd}");
    assert!(vcd.contains("$var wire 1 ! Motor $end"), "{vcd}");
    assert!(vcd.contains("$var integer 16 \" Level $end"), "{vcd}");
    assert!(vcd.contains("$var real 64 # r $end"), "{vcd}");
    assert!(vcd.contains("$var integer 64 $ t.ET $end"), "{vcd}");
    assert!(!vcd.contains(" s $end"), "strings are left out");
    assert!(vcd.contains("$enddefinitions $end\n#10\n$dumpvars\n0!\nb1111111111111101 \"\nr0.5 #\nb0 $\n$end\n#20\n"), "{vcd}");
    // Motor turns on at 30 ms and is not repeated afterwards.
    assert!(vcd.contains("#30\n1!\n"), "{vcd}");
    assert_eq!(vcd.matches("1!").count(), 1);
    assert!(vcd.contains("#50\n"), "{vcd}");
}

#[test]
fn vcd_timescale_and_ids() {
    assert_eq!(vcd::tests_ident(0), "!");
    assert_eq!(vcd::tests_ident(93), "~");
    assert_eq!(vcd::tests_ident(94), "!!");
    let mut s = sim(SRC);
    s.set_cycle_ns(500_000);
    s.set_trace(&["Motor"], 10).unwrap();
    s.run_scans(3);
    let vcd = trace_vcd(s.trace());
    assert!(vcd.contains("$timescale 1 us $end"), "{vcd}");
    assert!(vcd.contains("#500\n$dumpvars\n0!\n$end\n#1500\n"), "{vcd}");
    // An empty trace is still a valid header.
    let empty = sim(SRC);
    assert!(trace_vcd(empty.trace()).contains("$enddefinitions $end"));
}
