//! The `plc` binary as a user runs it.

use std::io::Write;
use std::process::{Command, Output};

fn plc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_plc")).args(args).output().expect("plc runs")
}

fn source_file(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("plc-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    let mut f = std::fs::File::create(&path).expect("create");
    f.write_all(text.as_bytes()).expect("write");
    path
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn check_prints_located_diagnostics_and_fails() {
    let path = source_file("bad.st", "PROGRAM P\nVAR i : INT; END_VAR\ni := j;\nEND_PROGRAM\n");
    let out = plc(&["check", path.to_str().expect("utf-8 path")]);
    assert!(!out.status.success());
    let text = stdout(&out);
    let want = format!("{}:3:6: error[E0100]: `j` is not declared", path.display());
    assert!(text.lines().any(|l| l == want), "{text}");
}

#[test]
fn check_passes_a_good_program() {
    let path = source_file("good.st", "PROGRAM P VAR i : INT; END_VAR i := i + 1; END_PROGRAM");
    let out = plc(&["check", path.to_str().expect("utf-8 path")]);
    assert!(out.status.success(), "{}", stdout(&out));
}

#[test]
fn run_json_reports_vars_and_exits_zero() {
    let src = "PROGRAM P
VAR_INPUT Start : BOOL; END_VAR
VAR_OUTPUT Motor : BOOL; END_VAR
VAR n : INT; t : TON; s : STRING := 'hi'; tm : TIME; END_VAR
Motor := Start; n := n + 1;
t(IN := Start, PT := T#1s500ms);
tm := t.ET;
END_PROGRAM";
    let path = source_file("run.st", src);
    let out = plc(&[
        "run",
        path.to_str().expect("utf-8 path"),
        "--cycles",
        "3",
        "--cycle-ms",
        "100",
        "--set",
        "Start=TRUE",
        "--json",
    ]);
    assert!(out.status.success(), "{}", stdout(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("one JSON object");
    assert_eq!(v["status"], "ok");
    assert_eq!(v["cycles"], 3);
    assert_eq!(v["vars"]["Motor"], true);
    assert_eq!(v["vars"]["n"], 3);
    assert_eq!(v["vars"]["s"], "hi");
    assert_eq!(v["vars"]["tm"], "T#200ms");
    assert_eq!(v["vars"]["t"]["PT"], "T#1s500ms");
    assert_eq!(v["fault"], serde_json::Value::Null);
}

#[test]
fn run_reports_a_fault_with_its_line_and_exits_non_zero() {
    let path = source_file(
        "fault.st",
        "PROGRAM P\nVAR a : INT := 1; b : INT; END_VAR\na := a / b;\nEND_PROGRAM\n",
    );
    let out = plc(&["run", path.to_str().expect("utf-8 path"), "--json"]);
    assert!(!out.status.success());
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("one JSON object");
    assert_eq!(v["status"], "fault");
    assert_eq!(v["cycles"], 0);
    assert_eq!(v["fault"]["line"], 3);
    assert_eq!(v["fault"]["column"], 1);
}

#[test]
fn run_rejects_unknown_set_variables_and_programs() {
    let path = source_file("p.st", "PROGRAM P VAR i : INT; END_VAR END_PROGRAM");
    let p = path.to_str().expect("utf-8 path");
    let out = plc(&["run", p, "--set", "nope=1", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("json");
    assert_eq!(v["status"], "error");
    assert_eq!(v["diagnostics"][0]["code"], "E0300");
    let out = plc(&["run", p, "--program", "Other", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("json");
    assert_eq!(v["diagnostics"][0]["code"], "E0106");
    assert!(!out.status.success());
}

#[test]
fn a_missing_file_is_a_clear_error() {
    let out = plc(&["check", "/nonexistent/x.st"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot read"));
}

#[test]
fn explain_describes_a_code() {
    let out = plc(&["explain", "e0150"]);
    assert!(out.status.success());
    assert!(stdout(&out).starts_with("E0150: "));
}
