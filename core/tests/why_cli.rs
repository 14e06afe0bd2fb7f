//! `plc why` and `plc run --set-at` as a user runs them (issue 36): the latch pressed and
//! released, a TON's output, a Petri net place, and the errors.

use std::io::Write;
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

use serde_json::{json, Value};

fn plc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_plc")).args(args).output().expect("plc runs")
}

/// Writes `text` to a file of its own: the tests run in parallel, and a file they shared
/// could be truncated by one test while `plc` reads it for another.
fn source_file(name: &str, text: &str) -> String {
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("plc-why-{}-{n}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    let mut f = std::fs::File::create(&path).expect("create");
    f.write_all(text.as_bytes()).expect("write");
    path.to_str().expect("utf-8 path").to_string()
}

fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn json_of(out: &Output) -> Value {
    let text = String::from_utf8_lossy(&out.stdout);
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("not JSON ({e}): {text}"))
}

/// The operand `name` of an explanation: `(value, since_scan)`.
fn operand(v: &Value, name: &str) -> (Value, u64) {
    let ops = v["operands"].as_array().expect("operands");
    let o = ops.iter().find(|o| o["name"] == name).unwrap_or_else(|| panic!("no {name} in {v}"));
    (o["value"].clone(), o["since_scan"].as_u64().expect("since_scan"))
}

const LATCH: &str = "PROGRAM Main
VAR_INPUT Start : BOOL; Stop : BOOL; END_VAR
VAR_OUTPUT Motor : BOOL; Lamp : BOOL; END_VAR
VAR Delay : TON; END_VAR
Motor := (Start OR Motor) AND NOT Stop;
Delay(IN := Motor, PT := T#100ms);
Lamp := Delay.Q;
END_PROGRAM
";

/// Start pressed on scans 3 and 4, released from 5; Stop pressed from 30.
const PRESSES: [&str; 6] =
    ["--set-at", "3:Start=TRUE", "--set-at", "5:Start=FALSE", "--set-at", "30:Stop=TRUE"];

fn why_latch(var: &str, at: u64) -> Value {
    let path = source_file("latch.st", LATCH);
    let at = at.to_string();
    let mut args = vec!["why", &path, var, "--at", &at, "--cycles", "40", "--json"];
    args.extend(PRESSES);
    let out = plc(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    json_of(&out)
}

#[test]
fn why_motor_on_the_scan_it_turned_on_names_the_line_with_start_true() {
    let v = why_latch("Motor", 3);
    assert_eq!(
        (v["var"].clone(), v["value"].clone(), v["scan"].clone()),
        (json!("Motor"), json!(true), json!(3))
    );
    assert_eq!(v["written_by"]["kind"], "statement");
    assert_eq!(v["written_by"]["pou"], "Main");
    assert_eq!(v["written_by"]["line"], 5);
    assert_eq!(v["written_by"]["text"], "Motor := (Start OR Motor) AND NOT Stop");
    assert_eq!(operand(&v, "Start"), (json!(true), 3));
    assert_eq!(operand(&v, "Motor"), (json!(false), 0), "the value read: the scan before's");
    assert_eq!(operand(&v, "Stop"), (json!(false), 0));
    assert_eq!(v["previous_change"], Value::Null);
    assert_eq!(v["next_change"], 30, "Stop turns it off");
}

#[test]
fn why_motor_later_names_the_seal_in_operand() {
    let v = why_latch("Motor", 12);
    assert_eq!(v["value"], true);
    assert_eq!(v["written_by"]["line"], 5);
    assert_eq!(operand(&v, "Start"), (json!(false), 5), "released since scan 5");
    assert_eq!(operand(&v, "Motor"), (json!(true), 3), "the seal-in: on since scan 3");
    assert_eq!(v["previous_change"], 3);
}

#[test]
fn why_a_ton_output_gives_its_in_and_et_at_that_scan() {
    // PT 100 ms at 10 ms per scan: Q rises 10 scans after IN (scan 3), on scan 13.
    let v = why_latch("Delay.Q", 13);
    assert_eq!(v["value"], true);
    assert_eq!(v["written_by"]["line"], 6);
    assert_eq!(
        (v["block"]["instance"].clone(), v["block"]["type"].clone()),
        (json!("Delay"), json!("TON"))
    );
    assert_eq!(
        v["block"]["history"],
        json!([{"scan": 3, "name": "Delay.IN", "value": true}, {"scan": 13, "name": "Delay.Q", "value": true}])
    );
    assert_eq!(operand(&v, "Delay.IN"), (json!(true), 3));
    assert_eq!(operand(&v, "Delay.ET"), (json!("T#100ms"), 13));
    assert_eq!(operand(&v, "Delay.PT"), (json!("T#100ms"), 1));
    let v = why_latch("Delay.Q", 8);
    assert_eq!(v["value"], false);
    assert_eq!(operand(&v, "Delay.ET"), (json!("T#50ms"), 8), "timing: ET grows every scan");
    let v = why_latch("Lamp", 20);
    assert_eq!(operand(&v, "Delay.Q"), (json!(true), 13));
}

#[test]
fn why_in_words_reads_like_the_issue() {
    let path = source_file("latch.st", LATCH);
    let mut args = vec!["why", &path, "Motor", "--at", "12"];
    args.extend(PRESSES);
    let out = plc(&args);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.starts_with(
            "Motor is TRUE at scan 12: written by Main line 5: Motor := (Start OR Motor) AND NOT Stop — \
             Start FALSE (since scan 5), Motor TRUE (since scan 3), Stop FALSE (since scan 0)"
        ),
        "{text}"
    );
}

#[test]
fn why_on_the_ladder_latch_names_the_rung_and_its_power_path() {
    let file = example("latch-ladder.plcproj.json");
    let run = |at: &str| {
        let args = [
            "why",
            &file,
            "Motor",
            "--at",
            at,
            "--set-at",
            "3:Start=TRUE",
            "--set-at",
            "4:Start=FALSE",
            "--json",
        ];
        json_of(&plc(&args))
    };
    let v = run("3");
    assert_eq!(v["written_by"]["kind"], "rung");
    assert_eq!(
        (v["written_by"]["pou"].clone(), v["written_by"]["rung"].clone()),
        (json!("Latch"), json!(1))
    );
    assert_eq!(v["written_by"]["element"], "coil Motor");
    assert_eq!(operand(&v, "Start"), (json!(true), 3));
    let powered = |v: &Value, element: &str| {
        v["path"]
            .as_array()
            .expect("path")
            .iter()
            .find(|s| s["element"] == element)
            .map(|s| s["powered"].clone())
    };
    assert_eq!(powered(&v, "NO contact Start"), Some(json!(true)));
    assert_eq!(powered(&v, "NO contact Motor"), Some(json!(false)));
    let v = run("9");
    assert_eq!(operand(&v, "Motor"), (json!(true), 3));
    assert_eq!(powered(&v, "NO contact Start"), Some(json!(false)));
    assert_eq!(powered(&v, "NO contact Motor"), Some(json!(true)), "power took the seal-in branch");
}

#[test]
fn why_a_petri_place_holds_a_token_names_the_transition_and_its_guard() {
    let file = example("weighing-sequential.plcproj.json");
    let out = plc(&["why", &file, "P31", "--at", "10", "--set-at", "4:Start=TRUE", "--json"]);
    let v = json_of(&out);
    assert_eq!(v["var"], "P31");
    assert_eq!(v["value"], true);
    assert_eq!(v["place"]["holds_token"], true);
    assert_eq!(v["written_by"]["kind"], "none", "nothing moved the token on scan 10");
    assert_eq!(v["written_by"]["since_scan"], 4);
    assert_eq!(v["written_by"]["then"]["kind"], "transition");
    assert_eq!(v["written_by"]["then"]["element"], "T2");
    assert_eq!(operand(&v, "Start"), (json!(true), 4));
    assert_eq!(operand(&v, "Fault"), (json!(false), 0));
}

#[test]
fn run_set_at_presses_and_releases_a_button() {
    let path = source_file("latch.st", LATCH);
    let out = plc(&[
        "run",
        &path,
        "--cycles",
        "6",
        "--set-at",
        "3:Start=TRUE",
        "--set-at",
        "4:Start=FALSE",
        "--trace",
        "Start",
        "--trace",
        "Motor",
        "--csv",
    ]);
    assert!(out.status.success());
    let csv = String::from_utf8_lossy(&out.stdout);
    let starts: Vec<&str> =
        csv.lines().skip(1).map(|l| l.split(',').nth(2).unwrap_or("")).collect();
    assert_eq!(starts, ["0", "0", "1", "0", "0", "0"], "{csv}");
    let motors: Vec<&str> =
        csv.lines().skip(1).map(|l| l.split(',').nth(3).unwrap_or("")).collect();
    assert_eq!(motors, ["0", "0", "1", "1", "1", "1"], "{csv}");
}

#[test]
fn why_errors_are_located_and_exit_non_zero() {
    let path = source_file("latch.st", LATCH);
    let out = plc(&["why", &path, "Nothing", "--at", "2", "--json"]);
    assert!(!out.status.success());
    let v = json_of(&out);
    assert!(v["error"].as_str().expect("error").contains("`Nothing`"), "{v}");
    let out = plc(&["run", &path, "--set-at", "0:Start=TRUE"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("numbered from 1"));
    let out = plc(&["run", &path, "--set-at", "3:Start=maybe", "--json"]);
    let v = json_of(&out);
    assert_eq!(v["status"], "error");
    assert_eq!(v["diagnostics"][0]["code"], "E0301");
    let faulty = source_file(
        "fault.st",
        "PROGRAM P\nVAR a : INT := 1; b : INT; END_VAR\na := a / b;\nEND_PROGRAM\n",
    );
    let out = plc(&["why", &faulty, "a", "--at", "3", "--json"]);
    assert!(!out.status.success());
    assert!(json_of(&out)["error"].as_str().expect("error").contains("faulted"));
}
