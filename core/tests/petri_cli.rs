//! `plc petri …`, and `plc run` / `plc check` on nets, as a user runs them.
#![allow(clippy::unwrap_used)]

use std::process::{Command, Output};

fn plc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_plc")).args(args).output().unwrap()
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn temp(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("plc-petri-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_string_lossy().into_owned()
}

#[test]
fn analyze_json_prints_the_issue_object() {
    let out = plc(&["petri", "analyze", &example("weighing-sequential.plcproj.json"), "--json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(v["states"], 5);
    assert_eq!(v["edges"], 9);
    assert_eq!(v["complete"], true);
    assert_eq!((v["bounded"].clone(), v["safe"].clone()), (true.into(), true.into()));
    assert_eq!(v["bounds"]["P31"], 1);
    assert_eq!(v["deadlocks"], serde_json::json!([]));
    assert_eq!(v["dead_transitions"], serde_json::json!([]));
    assert_eq!((v["live"].clone(), v["reversible"].clone()), (true.into(), true.into()));
    assert_eq!(
        v["p_invariants"],
        serde_json::json!([{"P1": 1, "P20": 1, "P31": 1, "P32": 1, "P33": 1}])
    );
    assert_eq!(v["t_invariants"].as_array().unwrap().len(), 5);
}

#[test]
fn analyze_text_and_budget() {
    let out =
        plc(&["petri", "analyze", &example("weighing-concurrent.plcproj.json"), "--budget", "4"]);
    assert!(out.status.success());
    let text = stdout(&out);
    assert!(text.starts_with("Guards are ignored"), "{text}");
    assert!(text.contains("4 markings") && text.contains("INCOMPLETE"), "{text}");
}

#[test]
fn codegen_prints_the_program_and_the_place_map() {
    let out = plc(&["petri", "codegen", &example("weighing-concurrent.plcproj.json")]);
    assert!(out.status.success());
    let st = stdout(&out);
    assert!(st.contains("PROGRAM WeighingConcurrent") && st.contains("CASE PnScan_pA OF"), "{st}");
    let out = plc(&["petri", "codegen", &example("traffic-light.plcproj.json"), "--place-map"]);
    let map: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(
        map["places"][0],
        serde_json::json!({"id": "Free", "step_variable": "pCross", "value": 0})
    );
}

#[test]
fn run_and_check_accept_projects_with_nets() {
    let path = example("weighing-sequential.plcproj.json");
    let out = plc(&["run", &path, "--cycles", "3", "--set", "Start=TRUE", "--json"]);
    assert!(out.status.success(), "{}", stdout(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(v["vars"]["p"], 31);
    assert_eq!(v["vars"]["FeedValve"], true);
    let out = plc(&["check", &path]);
    assert!(out.status.success(), "{}", stdout(&out));
}

#[test]
fn run_accepts_a_pnml_file() {
    let out = plc(&["petri", "export", &example("traffic-light.plcproj.json")]);
    assert!(out.status.success());
    let pnml = temp("traffic.pnml", &stdout(&out));
    // EW takes the crossing at scan 12 (see the examples test): after 20 scans of 100 ms
    // east-west is green.
    let out = plc(&["run", &pnml, "--cycles", "20", "--cycle-ms", "100", "--json"]);
    assert!(out.status.success(), "{}", stdout(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert_eq!(
        (v["vars"]["EwGreen"].clone(), v["vars"]["NsRed"].clone()),
        (true.into(), true.into())
    );
    let out = plc(&["petri", "import", &pnml]);
    assert!(stdout(&out).contains("\"petri\""));
}

#[test]
fn check_reports_net_problems_at_the_element() {
    let project = std::fs::read_to_string(example("weighing-sequential.plcproj.json")).unwrap();
    let broken = project.replace("\"Weight >= Setpoint\"", "\"Weight >= \"");
    let path = temp("broken.plcproj.json", &broken);
    let out = plc(&["check", &path]);
    assert!(!out.status.success());
    let text = stdout(&out);
    // "Weight >= " ends after 10 characters: the missing operand is at column 11.
    assert!(
        text.contains("error[E0503]: POU Weighing, transition T5 (guard line 1, column 11)"),
        "{text}"
    );
    let out = plc(&["petri", "codegen", &path]);
    assert!(!out.status.success());
    assert!(stdout(&out).contains("E0503"));
}

#[test]
fn a_bad_pnml_file_is_a_located_error() {
    let path = temp("bad.pnml", "<pnml>\n<net id=\"n\"><page id=\"p\">\n<place id=\"a\"><initialMarking><text>x</text></initialMarking></place>\n</page></net></pnml>");
    let out = plc(&["petri", "analyze", &path]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("line 3, column 1: the initial marking `x` is not a whole number"),
        "{err}"
    );
}
