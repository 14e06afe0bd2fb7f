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
fn run_json_gives_the_suggestion_of_a_misspelled_name_as_data() {
    let src = "PROGRAM P\nVAR_OUTPUT Motor : BOOL; END_VAR\nMotr := TRUE;\nx := 1;\nEND_PROGRAM\n";
    let path = source_file("misspelt.st", src);
    let out = plc(&["run", path.to_str().expect("utf-8 path"), "--json"]);
    assert!(!out.status.success());
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("one JSON object");
    let d = &v["diagnostics"];
    assert_eq!(d[0]["message"], "`Motr` is not declared; did you mean Motor?");
    assert_eq!(d[0]["suggestion"], "Motor");
    assert_eq!((d[0]["line"].as_u64(), d[0]["column"].as_u64()), (Some(3), Some(1)));
    // No guess: no `suggestion` key at all.
    assert_eq!(d[1]["message"], "`x` is not declared");
    assert!(d[1].get("suggestion").is_none(), "{d}");
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
    // Reported as every problem is: a diagnostic line, then the count.
    assert!(
        stdout(&out).contains("/nonexistent/x.st:0:0: error[E0304]: cannot read"),
        "{}",
        stdout(&out)
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains("1 error(s), 0 warning(s)"));
}

#[test]
fn explain_describes_a_code() {
    let out = plc(&["explain", "e0150"]);
    assert!(out.status.success());
    assert!(stdout(&out).starts_with("E0150: "));
}

#[test]
fn explain_speaks_polish_and_czech_and_keeps_the_program_text() {
    let en = stdout(&plc(&["explain", "E0150"]));
    for lang in ["pl", "cs"] {
        let out = plc(&["explain", "E0150", "--lang", lang]);
        assert!(out.status.success());
        let text = stdout(&out);
        assert!(text.starts_with("E0150: "));
        assert_ne!(text, en, "--lang {lang} prints a translation");
        let example = en.lines().find(|l| l.contains("PROGRAM")).unwrap_or_default();
        assert!(text.contains(example), "--lang {lang} keeps the ST example as it is");
    }
    let out = plc(&["explain", "E0150", "--lang", "de"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown language `de`"));
}

fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn run_accepts_a_project_with_ladder_pous() {
    let path = example("latch-ladder.plcproj.json");
    let out = plc(&["run", &path, "--cycles", "150", "--set", "Start=TRUE", "--json"]);
    assert!(out.status.success(), "{}", stdout(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("json");
    assert_eq!(v["vars"]["Motor"], true);
    assert_eq!(v["vars"]["Lamp"], false, "the TON needs 2 s; 150 scans are 1.5 s");
    assert!(
        v["vars"].as_object().expect("vars").keys().all(|k| !k.starts_with("Ld")),
        "hidden power variables are not reported"
    );
    let out = plc(&["run", &path, "--cycles", "201", "--set", "Start=TRUE", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("json");
    assert_eq!(v["vars"]["Lamp"], true);
    let out = plc(&["check", &path]);
    assert!(out.status.success(), "{}", stdout(&out));
}

#[test]
fn st_view_prints_the_readable_program() {
    let out = plc(&["st-view", &example("latch-ladder.plcproj.json"), "--pou", "latch"]);
    assert!(out.status.success());
    assert!(stdout(&out).contains("Motor := (Start OR Motor) AND NOT Stop;"), "{}", stdout(&out));
    let out = plc(&["st-view", &example("latch-ladder.plcproj.json"), "--pou", "Nope"]);
    assert!(!out.status.success());
}

#[test]
fn bench_quick_prints_every_figure() {
    let out = plc(&["bench", "--quick", "--json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("json");
    for key in ["B1", "B2", "B3", "B4", "B5", "B6", "B7"] {
        assert!(v.get(key).is_some(), "{key} missing");
    }
    assert!(v["B1"]["ratio"].as_f64().is_some_and(|r| r > 0.0));
}

#[test]
fn export_to_plcopen_and_run_the_xml() {
    let out = plc(&["export", "--plcopen", &example("latch-ladder.plcproj.json")]);
    assert!(out.status.success());
    let xml = stdout(&out);
    assert!(xml.contains("http://www.plcopen.org/xml/tc6_0201"));
    let path = source_file("latch.xml", &xml);
    let p = path.to_str().expect("utf-8 path");
    let out = plc(&["run", p, "--cycles", "201", "--set", "Start=TRUE", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("json");
    assert_eq!((v["vars"]["Motor"].clone(), v["vars"]["Lamp"].clone()), (true.into(), true.into()));
    let out = plc(&["import", p]);
    assert!(out.status.success());
    assert!(plc_core::project::Project::from_file(&stdout(&out)).is_ok());
    let bad = source_file("bad.xml", "<?xml version=\"1.0\"?><project><pous><pou");
    let out = plc(&["run", bad.to_str().expect("utf-8 path"), "--json"]);
    assert_eq!(out.status.code(), Some(2));
}

/// The five Done-when rungs of the ladder issue, each a PROGRAM of one example project and
/// of its PLCopen XML export, run through `plc run` with the values worked out by hand.
#[test]
fn the_five_ladder_rungs_run_from_the_project_file_and_from_plcopen_xml() {
    // (program, --set pairs, cycles, expected variables)
    type Case<'a> = (&'a str, &'a [&'a str], &'a str, &'a [(&'a str, serde_json::Value)]);
    let cases: &[Case] = &[
        ("Latch", &["Start=TRUE"], "2", &[("Motor", true.into())]),
        ("Latch", &["Start=TRUE", "Stop=TRUE"], "2", &[("Motor", false.into())]),
        // Scan k (from 1) runs at 10(k - 1) ms: ET reaches PT = 2 s on scan 201.
        (
            "DelayedLamp",
            &["Go=TRUE"],
            "200",
            &[("Lamp", false.into()), ("Elapsed", "T#1s990ms".into())],
        ),
        ("DelayedLamp", &["Go=TRUE"], "201", &[("Lamp", true.into()), ("Elapsed", "T#2s".into())]),
        // A held sensor is one rising edge; Reset on R holds the count at 0.
        ("PartCounter", &["Part=TRUE"], "3", &[("Count", 1.into()), ("BoxFull", false.into())]),
        ("PartCounter", &["Part=TRUE", "Reset=TRUE"], "3", &[("Count", 0.into())]),
        (
            "LevelCopy",
            &["Enable=TRUE", "Level=70"],
            "1",
            &[("High", true.into()), ("Shown", 70.into())],
        ),
        (
            "LevelCopy",
            &["Enable=TRUE", "Level=40"],
            "1",
            &[("High", false.into()), ("Shown", 0.into())],
        ),
        ("ThreeWay", &["C=TRUE", "Permit=TRUE"], "1", &[("Out", true.into())]),
        ("ThreeWay", &["B=TRUE"], "1", &[("Out", false.into())]),
    ];
    for file in ["ladder-five-rungs.plcproj.json", "ladder-five-rungs.xml"] {
        let path = example(file);
        for (program, sets, cycles, want) in cases {
            let mut args =
                vec!["run", path.as_str(), "--program", program, "--cycles", cycles, "--json"];
            for s in *sets {
                args.extend(["--set", s]);
            }
            let out = plc(&args);
            assert!(out.status.success(), "{file} {program}: {}", stdout(&out));
            let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("JSON");
            for (name, value) in *want {
                assert_eq!(&v["vars"][name], value, "{file} {program} {sets:?}: {name}");
            }
        }
    }
    // The ST view of the counter shows its wired reset input.
    let out = plc(&["st-view", &example("ladder-five-rungs.xml"), "--pou", "PartCounter"]);
    assert!(
        stdout(&out).contains("Parts(CU := LdEdge_0.Q, R := Reset, PV := 5);"),
        "{}",
        stdout(&out)
    );
}

#[test]
fn run_prints_warnings_as_check_does() {
    let path = source_file(
        "warn.st",
        "PROGRAM P\nVAR s : SINT; i : INT; END_VAR\nCASE s OF 300: i := 1; END_CASE;\nEND_PROGRAM\n",
    );
    let p = path.to_str().expect("utf-8 path");
    let checked = stdout(&plc(&["check", p]));
    let run = stdout(&plc(&["run", p]));
    let warning = checked.lines().find(|l| l.contains(": warning[W")).expect("a warning");
    assert!(run.lines().any(|l| l == warning), "run printed:\n{run}\ncheck printed:\n{checked}");
}

#[test]
fn a_cycle_time_out_of_range_is_refused() {
    // Issue 11: `--cycle-ms` overflowed the nanosecond clock or silently became 1 ns.
    let f = source_file("cycle.st", "PROGRAM Main VAR t : TIME; END_VAR t := TIME(); END_PROGRAM");
    for bad in ["0", "60001", "18446744073709551615"] {
        let out = plc(&["run", "--cycle-ms", bad, f.to_str().unwrap_or_default()]);
        assert!(!out.status.success(), "--cycle-ms {bad} was accepted");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("--cycle-ms") && err.contains("1..=60000"), "{err}");
    }
    let json = plc_core::run::run_source(
        "PROGRAM Main END_PROGRAM",
        &plc_core::run::RunOptions { cycle_ms: u64::MAX, ..Default::default() },
    );
    assert!(json.diagnostics.iter().any(|d| d.code == "E0303"), "{:?}", json.diagnostics);
}

/// `plc grade`: the shipped latch exercise on a folder of a right, a wrong, a broken and
/// an unreadable submission: one CSV row each, the batch never stopped.
#[test]
fn grade_writes_one_row_per_submission_and_never_stops_the_batch() {
    let root = format!("{}/..", env!("CARGO_MANIFEST_DIR"));
    let exercise = format!("{root}/exercises/latch/latch.toml");
    let reference =
        std::fs::read_to_string(format!("{root}/exercises/latch/reference.st")).unwrap();
    let dir = std::env::temp_dir().join(format!("plc-grade-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("a-right.st"), &reference).unwrap();
    std::fs::write(dir.join("b-wrong.st"), reference.replace("(Start OR Motor)", "Start")).unwrap();
    std::fs::write(dir.join("c-broken.st"), reference.replace("NOT Stop", "NOT Stopp")).unwrap();
    std::fs::write(dir.join("d-unreadable.plcproj.json"), "{ \"schema\": 1, \"name\": ").unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_plc"))
        .args(["grade", &exercise, &dir.to_string_lossy(), "--format", "csv", "--jobs", "2"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines[0],
        "submission,score,total,passed,failed,error,first_failure,program,name,handed_in"
    );
    assert_eq!(lines.len(), 5, "{text}");
    assert!(lines[1].ends_with("a-right.st,3,3,2,0,,,Main,,"), "{}", lines[1]);
    assert!(
        lines[2].ends_with(
            "b-wrong.st,1,3,1,1,,\"Start, release, stop: Motor was FALSE at 0.21 s (scan 21)\",Main,,"
        ),
        "{}",
        lines[2]
    );
    assert!(
        lines[3].contains("c-broken.st,0,3,0,0,\"the program does not build: line 10, column 35: `Stopp` is not declared; did you mean Stop? [E0100]\""),
        "{}",
        lines[3]
    );
    assert!(lines[4].contains("d-unreadable.plcproj.json,,,,,"), "{}", lines[4]);
    // The text names the PROGRAM graded.
    let plain = std::process::Command::new(env!("CARGO_BIN_EXE_plc"))
        .args(["grade", &exercise, &dir.join("b-wrong.st").to_string_lossy()])
        .output()
        .unwrap();
    let plain = String::from_utf8_lossy(&plain.stdout).into_owned();
    assert!(plain.contains("b-wrong.st: 1/3 — checked PROGRAM Main (ST)"), "{plain}");
    assert!(plain.contains("  FAIL Start, release, stop: expected Motor stays TRUE from 0.21 s to 0.49 s; Motor was FALSE at 0.21 s (scan 21)\n"), "{plain}");
    // `--lang pl`: the report's sentences in Polish, program text as it is.
    let polish = std::process::Command::new(env!("CARGO_BIN_EXE_plc"))
        .args(["grade", &exercise, &dir.join("b-wrong.st").to_string_lossy(), "--lang", "pl"])
        .output()
        .unwrap();
    let polish = String::from_utf8_lossy(&polish.stdout).into_owned();
    assert!(polish.contains("b-wrong.st: 1/3 — sprawdzono PROGRAM Main (ST)"), "{polish}");
    assert!(polish.contains("oczekiwano: Motor ma wartość TRUE bez przerwy od 0.21 s do 0.49 s; rzeczywiście: Motor miało wartość FALSE w chwili 0.21 s (cykl 21)"), "{polish}");
    let json = std::process::Command::new(env!("CARGO_BIN_EXE_plc"))
        .args(["grade", &exercise, &dir.join("b-wrong.st").to_string_lossy(), "--format", "json"])
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(v[0]["score"], 1);
    assert_eq!((&v[0]["program"], &v[0]["language"]), (&"Main".into(), &"ST".into()));
    assert_eq!(v[0]["scenarios"][0]["expected"], "Motor stays TRUE from 0.21 s to 0.49 s");
    assert_eq!(v[0]["scenarios"][0]["scan"], 21);
    assert_eq!(v[0]["scenarios"][0]["hint"], "Does the motor hold itself when Start is released?");
}

/// A hand-in (`.plcsub`): graded again with the student's name in every format; one of
/// another exercise gets its own row with the reason, and a damaged one too.
#[test]
fn grade_reads_hand_ins_with_the_students_name_and_refuses_another_exercises() {
    use plc_core::exercise::HandIn;
    let root = format!("{}/..", env!("CARGO_MANIFEST_DIR"));
    let exercise = format!("{root}/exercises/latch/latch.toml");
    let reference =
        std::fs::read_to_string(format!("{root}/exercises/latch/reference.st")).unwrap();
    let dir = std::env::temp_dir().join(format!("plc-handin-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let hand_in = |exercise: &str, name: &str, source: &str| {
        let mut project = plc_core::project::Project::new("Exercise: latch");
        project.source = source.to_string();
        let text =
            HandIn::file_text(&project.to_file(), exercise, name, "2025-03-04T10:11:12.000Z");
        std::fs::write(dir.join(HandIn::file_name(exercise, name)), text).unwrap();
    };
    hand_in("latch", "Ada Lovelace", &reference);
    hand_in("latch", "Zoë, \"B\"", &reference.replace("(Start OR Motor)", "Start"));
    hand_in("blinker", "Ben Okri", &reference);
    std::fs::write(dir.join("latch--Broken.plcsub"), "{ \"schema\": 1").unwrap();
    let run = |format: &str| {
        let out = plc(&["grade", &exercise, &dir.to_string_lossy(), "--format", format]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        stdout(&out)
    };
    // Rows by file name: blinker--Ben-Okri, latch--Ada-Lovelace, latch--Broken, latch--Zoë-B.
    let text = run("text");
    assert!(text.contains("latch--Ada-Lovelace.plcsub (Ada Lovelace): 3/3"), "{text}");
    assert!(text.contains("latch--Zoë-B.plcsub (Zoë, \"B\"): 1/3"), "{text}");
    assert!(
        text.contains("blinker--Ben-Okri.plcsub (Ben Okri): cannot be graded: this is a hand-in of exercise “blinker”, not of “latch”"),
        "{text}"
    );
    assert!(text.contains("latch--Broken.plcsub: cannot be graded: "), "{text}");
    let csv = run("csv");
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 5, "{csv}");
    assert!(lines[1].ends_with(",Ben Okri,2025-03-04T10:11:12.000Z"), "{}", lines[1]);
    assert!(lines[1].contains(",,,,,\"this is a hand-in of exercise “blinker”"), "{}", lines[1]);
    assert!(
        lines[2].ends_with(",3,3,2,0,,,Main,Ada Lovelace,2025-03-04T10:11:12.000Z"),
        "{}",
        lines[2]
    );
    assert!(lines[4].ends_with(",\"Zoë, \"\"B\"\"\",2025-03-04T10:11:12.000Z"), "{}", lines[4]);
    let json: serde_json::Value = serde_json::from_str(&run("json")).unwrap();
    assert_eq!(json[1]["name"], "Ada Lovelace");
    assert_eq!(json[1]["handed_in"], "2025-03-04T10:11:12.000Z");
    assert_eq!(json[1]["score"], 3);
    assert_eq!(json[0]["name"], "Ben Okri");
    assert!(json[0]["error"].as_str().unwrap().contains("not of “latch”"));
    assert_eq!(json[2]["name"], serde_json::Value::Null);
}

/// `plc grade --format html`: the class report of a class's right, wrong, broken and
/// unreadable submissions to the reversing exercise — a row each, every scenario's pass
/// rate, the histogram of scores, the most common first failures — as one page that needs
/// nothing else (no script, nothing fetched).
#[test]
fn grade_html_is_a_self_contained_class_report() {
    let root = format!("{}/..", env!("CARGO_MANIFEST_DIR"));
    let ex = format!("{root}/exercises/reversing");
    let read = |f: &str| std::fs::read_to_string(format!("{ex}/{f}")).unwrap();
    let dir = std::env::temp_dir().join(format!("plc-class-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let files = [
        ("anna.st", read("reference.st")),
        ("ben.st", read("reference.st")),
        ("carl.st", read("mutants/no-interlock.st")),
        ("dora.st", read("mutants/no-interlock.st")),
        ("emil.st", read("mutants/stop-ignored.st")),
        ("fay.st", read("reference.st").replace("NOT Stop", "NOT Stopp")),
        ("gil.plcproj.json", "{ \"schema\": 1, \"name\": ".to_string()),
    ];
    for (name, text) in &files {
        std::fs::write(dir.join(name), text).unwrap();
    }
    let out = plc(&[
        "grade",
        &format!("{ex}/reversing.toml"),
        &dir.to_string_lossy(),
        "--format",
        "html",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let html = stdout(&out);
    assert!(html.starts_with("<!DOCTYPE html>"), "{html}");
    assert!(html.contains("<title>Class report — Reversing motor with interlock</title>"));
    // Self-contained: no script, nothing loaded from anywhere.
    for outside in ["<script", "src=", "href=", "url(", "@import"] {
        assert!(!html.contains(outside), "{outside} in the report");
    }
    // A row per submission: name, score, first failure with its time.
    assert!(
        html.contains(
            "<tr><td>anna.st</td><td class=\"num\"><span class=\"full\">2 / 2</span></td>"
        ),
        "{html}"
    );
    assert!(html.contains("<td>“Random presses never run both directions”: MotorFwd AND MotorRev was TRUE at 2.65 s (scan 265)<br><small>random run with seed 7"), "{html}");
    assert!(html.contains("<td class=\"num\">2.65 s</td>"), "{html}");
    assert!(html.contains("the program does not build: line "), "{html}");
    assert!(html.contains("<tr><td>gil.plcproj.json</td><td class=\"num\"><span class=\"refused\">not graded</span></td><td>this is not a project file"), "{html}");
    // Pass rates over the six graded submissions.
    assert!(html.contains("<td>Forward, stop, reverse</td>"), "{html}");
    assert!(html.contains("4 / 6 (67 %)"), "{html}");
    assert!(html.contains("3 / 6 (50 %)"), "{html}");
    // The histogram: one bar per score 0, 1, 2.
    assert!(
        html.contains("<title id=\"hist-title\">Submissions per score: 0: 1, 1: 3, 2: 2</title>"),
        "{html}"
    );
    assert_eq!(html.matches("<rect ").count(), 3);
    // The common first failures, most students first.
    let common = html.split("Most common first failures").nth(1).unwrap();
    let first_row = common.split("<tr><td>").nth(1).unwrap();
    assert!(first_row.starts_with("“Random presses never run both directions”: expected MotorFwd AND MotorRev is never TRUE"), "{first_row}");
    assert!(first_row.contains("2 of 6"), "{first_row}");
    assert!(common.contains("the program does not build</td>"), "{common}");
}

/// Every shipped exercise validates: its reference passes, its starter fails, each mutant
/// is caught with a located report (issue 15's CI check).
#[test]
fn every_shipped_exercise_validates() {
    let root = format!("{}/../exercises", env!("CARGO_MANIFEST_DIR"));
    // Every validation at once (each is its own process), then each result.
    let running: Vec<(String, std::process::Child)> = std::fs::read_dir(&root)
        .unwrap()
        .flatten()
        .filter(|d| d.path().is_dir())
        .map(|dir| {
            let id = dir.file_name().to_string_lossy().into_owned();
            let file = dir.path().join(format!("{id}.toml"));
            let child = std::process::Command::new(env!("CARGO_BIN_EXE_plc"))
                .args(["exercise", "validate", &file.to_string_lossy()])
                .stdout(std::process::Stdio::piped())
                .spawn()
                .unwrap();
            (id, child)
        })
        .collect();
    let mut checked = 0;
    let mut level_one = Vec::new();
    for (id, child) in running {
        let out = child.wait_with_output().unwrap();
        let text = String::from_utf8_lossy(&out.stdout).into_owned();
        assert!(out.status.success(), "{id}:\n{text}");
        assert!(text.contains("reference: passes all"), "{id}:\n{text}");
        let file = std::fs::read_to_string(format!("{root}/{id}/{id}.toml")).unwrap();
        let exercise = plc_core::exercise::Exercise::from_toml(&file).unwrap();
        if exercise.level == 1 {
            // A first exercise is in ST and ladder, with a right answer in each.
            assert_eq!(exercise.languages, ["st", "ld"], "{id}");
            assert!(text.contains("reference_ld: passes all"), "{id}:\n{text}");
            assert!(text.contains("checked PROGRAM Main (ladder)"), "{id}:\n{text}");
            assert!(text.contains("starter (Ladder): fails, as it should"), "{id}:\n{text}");
            level_one.push(id.clone());
        }
        assert!(
            text.lines().filter(|l| l.starts_with("mutant ")).all(|l| l.contains(": caught: ")),
            "{id}:\n{text}"
        );
        assert!(
            text.lines().filter(|l| l.starts_with("mutant ")).count() >= 3,
            "{id}: at least three mutants:\n{text}"
        );
        checked += 1;
    }
    assert!(checked >= 20, "the shipped exercises ({checked})");
    assert!(level_one.len() >= 5, "five Level 1 exercises: {level_one:?}");
}

/// `plc exercise new` writes a skeleton that validates, and never overwrites.
#[test]
fn a_new_exercise_skeleton_validates() {
    let dir = std::env::temp_dir().join(format!("plc-new-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let plc = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_plc"))
            .args(args)
            .current_dir(&dir)
            .output()
            .unwrap()
    };
    assert!(plc(&["exercise", "new", "blink"]).status.success());
    let out = plc(&["exercise", "validate", "blink/blink.toml"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stdout));
    assert!(String::from_utf8_lossy(&out.stdout).contains("mutant inverted.st: caught: "));
    let again = plc(&["exercise", "new", "blink"]);
    assert_eq!(again.status.code(), Some(2), "an existing folder is left alone");
}

/// `plc exercise validate` reports a translation that renames an interface variable, names
/// a scenario the exercise does not have or changes program text, with the file and the
/// table; a complete, faithful translation passes.
#[test]
fn exercise_validate_reports_a_translation_with_other_names() {
    let dir = std::env::temp_dir().join(format!("plc-i18n-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let plc = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_plc"))
            .args(args)
            .current_dir(&dir)
            .output()
            .unwrap()
    };
    assert!(plc(&["exercise", "new", "lamp"]).status.success());
    let file = dir.join("lamp/lamp.toml");
    let english = std::fs::read_to_string(&file).unwrap();
    let e = plc_core::exercise::Exercise::from_toml(&english).unwrap();
    let scenario = e.scenarios[0].name.clone();
    let translated = |meaning_key: &str, scenario_key: &str| {
        let mut t = format!("{english}\n[lang.pl]\ntitle = \"Lampka\"\n\n[lang.pl.meaning]\n");
        for v in &e.interface {
            let key = if v.name == "Lamp" { meaning_key } else { v.name.as_str() };
            t.push_str(&format!("{key} = \"znaczenie {}\"\n", v.name));
        }
        t.push_str(&format!("\n[lang.pl.scenario.\"{scenario_key}\"]\nname = \"Scenariusz\"\n"));
        t
    };
    std::fs::write(&file, translated("Lamp", &scenario)).unwrap();
    let out = plc(&["exercise", "validate", "lamp/lamp.toml"]);
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(out.status.success(), "{text}");
    assert!(text.contains("lang.pl: shown in English: statement"), "{text}");
    std::fs::write(&file, translated("Lampka", "Scenariusz 1")).unwrap();
    let out = plc(&["exercise", "validate", "lamp/lamp.toml"]);
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(!out.status.success(), "{text}");
    assert!(
        text.contains(
            "lamp/lamp.toml: lang.pl.meaning: “Lampka” is not a variable of the interface"
        ),
        "{text}"
    );
    assert!(
        text.contains(
            "lamp/lamp.toml: lang.pl.scenario.“Scenariusz 1”: there is no scenario of that name"
        ),
        "{text}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `plc exercise link` packs the exercise file and its starter into a `#x=` fragment
/// that the page reads back; the reference never travels.
#[test]
fn an_exercise_link_carries_the_file_and_the_starter_only() {
    let root = format!("{}/../exercises/latch", env!("CARGO_MANIFEST_DIR"));
    let out = plc(&[
        "exercise",
        "link",
        &format!("{root}/latch.toml"),
        "--base",
        "https://t.example/plc/",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let url = stdout(&out);
    let fragment =
        url.trim().strip_prefix("https://t.example/plc/#").expect("base, then the fragment");
    let (link, exercise) = plc_core::exercise::ExerciseLink::decode(fragment).unwrap();
    assert_eq!(exercise.id, "latch");
    assert_eq!(link.exercise, std::fs::read_to_string(format!("{root}/latch.toml")).unwrap());
    let starter = link.starter.unwrap();
    assert_eq!(starter.text, std::fs::read_to_string(format!("{root}/starter.st")).unwrap());
    let reference = std::fs::read_to_string(format!("{root}/reference.st")).unwrap();
    assert!(!serde_json::to_string(&link.exercise).unwrap().contains(reference.trim()));
    let missing = plc(&["exercise", "link", "no-such.toml"]);
    assert_eq!(missing.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&missing.stderr).contains("no-such.toml"));
}

/// The files of a ZIP archive, read through its central directory as an unzipper does.
fn unzip(b: &[u8]) -> Vec<(String, Vec<u8>)> {
    let u16_at = |at: usize| usize::from(u16::from_le_bytes([b[at], b[at + 1]]));
    let u32_at = |at: usize| u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]]) as usize;
    let end = b.len() - 22;
    assert_eq!(u32_at(end), 0x0605_4b50, "the end of the central directory");
    let mut at = u32_at(end + 16);
    (0..u16_at(end + 10))
        .map(|_| {
            assert_eq!(u32_at(at), 0x0201_4b50);
            let (method, packed, name_len) = (u16_at(at + 10), u32_at(at + 20), u16_at(at + 28));
            let local = u32_at(at + 42);
            let name = String::from_utf8(b[at + 46..at + 46 + name_len].to_vec()).unwrap();
            let start = local + 30 + u16_at(local + 26) + u16_at(local + 28);
            let body = &b[start..start + packed];
            let data = if method == 8 {
                miniz_oxide::inflate::decompress_to_vec(body).unwrap()
            } else {
                body.to_vec()
            };
            at += 46 + name_len;
            (name, data)
        })
        .collect()
}

/// `plc exercise scorm`: a package an LMS imports — the site, the exercise and its starter,
/// and a manifest with every element SCORM 1.2 requires; never the reference nor a mutant.
#[test]
fn an_exercise_scorm_package_has_the_manifest_site_exercise_and_starter_only() {
    let root = format!("{}/../exercises/latch", env!("CARGO_MANIFEST_DIR"));
    let dir = std::env::temp_dir().join(format!("plc-scorm-{}", std::process::id()));
    let site = dir.join("site");
    std::fs::create_dir_all(site.join("examples")).unwrap();
    std::fs::write(site.join("index.html"), "<!DOCTYPE html><title>PLC trainer</title>").unwrap();
    std::fs::write(site.join("plc-web-0123.wasm"), [0u8, 97, 115, 109, 1, 0, 0, 0]).unwrap();
    std::fs::write(site.join("examples/weighing.st"), "PROGRAM W END_PROGRAM").unwrap();
    let zip = dir.join("latch.zip");
    let out = plc(&[
        "exercise",
        "scorm",
        &format!("{root}/latch.toml"),
        "--site",
        &site.to_string_lossy(),
        "--out",
        &zip.to_string_lossy(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout(&out).starts_with(&format!("wrote {}", zip.display())));
    let files = unzip(&std::fs::read(&zip).unwrap());
    let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        [
            "imsmanifest.xml",
            "examples/weighing.st",
            "index.html",
            "plc-web-0123.wasm",
            "exercise/latch.toml",
            "exercise/starter.st"
        ]
    );
    let file = |name: &str| {
        String::from_utf8(files.iter().find(|(n, _)| n == name).unwrap().1.clone()).unwrap()
    };
    assert_eq!(
        file("exercise/latch.toml"),
        std::fs::read_to_string(format!("{root}/latch.toml")).unwrap()
    );
    assert_eq!(
        file("exercise/starter.st"),
        std::fs::read_to_string(format!("{root}/starter.st")).unwrap()
    );
    // Neither the reference solution nor a mutant is in any file.
    let reference = std::fs::read_to_string(format!("{root}/reference.st")).unwrap();
    let seal_in = reference.lines().find(|l| l.contains("Motor :=")).unwrap().trim().to_string();
    assert!(files.iter().all(|(_, data)| !String::from_utf8_lossy(data).contains(&seal_in)));
    // SCORM 1.2 (IMS Content Packaging 1.1.2 and ADL CP): the manifest and its metadata, the
    // default organization with an item naming the resource, the SCO resource with its
    // launch address and its files.
    let manifest = file("imsmanifest.xml");
    let required = [
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>",
        "<manifest identifier=\"plc-trainer-latch\"",
        "xmlns=\"http://www.imsproject.org/xsd/imscp_rootv1p1p2\"",
        "xmlns:adlcp=\"http://www.adlnet.org/xsd/adlcp_rootv1p2\"",
        "<metadata>\n    <schema>ADL SCORM</schema>\n    <schemaversion>1.2</schemaversion>\n  </metadata>",
        "<organizations default=\"org-latch\">\n    <organization identifier=\"org-latch\">\n      <title>Start/stop motor latch</title>",
        "<item identifier=\"item-latch\" identifierref=\"res-latch\" isvisible=\"true\">\n        <title>Start/stop motor latch</title>",
        "<resources>\n    <resource identifier=\"res-latch\" type=\"webcontent\" adlcp:scormtype=\"sco\" href=\"index.html?exercise=exercise/latch.toml&amp;scorm=1\">",
        "<file href=\"index.html\"/>",
        "<file href=\"exercise/starter.st\"/>",
        "</resources>\n</manifest>",
    ];
    for part in required {
        assert!(manifest.contains(part), "{part} in\n{manifest}");
    }
    // SCORM 2004 4th edition on request; a missing site is named with how to build it.
    let out = plc(&[
        "exercise",
        "scorm",
        &format!("{root}/latch.toml"),
        "--site",
        &site.to_string_lossy(),
        "--out",
        &zip.to_string_lossy(),
        "--scorm",
        "2004",
    ]);
    assert!(out.status.success());
    let files = unzip(&std::fs::read(&zip).unwrap());
    let manifest = String::from_utf8(files[0].1.clone()).unwrap();
    assert!(manifest.contains("<schemaversion>2004 4th Edition</schemaversion>"), "{manifest}");
    let missing = plc(&[
        "exercise",
        "scorm",
        &format!("{root}/latch.toml"),
        "--site",
        &dir.join("no-site").to_string_lossy(),
    ]);
    assert_eq!(missing.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&missing.stderr)
        .contains("no built site there (build it with `bash scripts/build-web.sh`"));
}

/// `st-view` prints the ST a network POU (an FBD body kept as drawn) runs as.
#[test]
fn st_view_prints_a_network_pou() {
    let xml = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="x" productName="x" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="Fbd"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Main" pouType="program">
      <interface><localVars><variable name="A"><type><BOOL/></type></variable><variable name="N"><type><INT/></type></variable></localVars></interface>
      <body><FBD>
        <inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>A</expression></inVariable>
        <inVariable localId="2"><position x="0" y="40"/><connectionPointOut/><expression>7</expression></inVariable>
        <block localId="3" typeName="MOVE"><position x="60" y="0"/><inputVariables>
          <variable formalParameter="EN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
          <variable formalParameter="IN"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
        </inputVariables><inOutVariables/><outputVariables><variable formalParameter="ENO"><connectionPointOut/></variable><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
        <outVariable localId="4"><position x="140" y="0"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn><expression>N</expression></outVariable>
      </FBD></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>"#;
    let path = source_file("network.xml", xml);
    let out = plc(&["st-view", &path.to_string_lossy(), "--pou", "main"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(
        stdout(&out).contains("IF A THEN N := MOVE(EN := A, IN := 7); END_IF;"),
        "{}",
        stdout(&out)
    );
    let out = plc(&["st-view", &path.to_string_lossy(), "--pou", "Nope"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("they are: Main"));
}

fn tank_example() -> String {
    format!("{}/../examples/tank-plant.plcproj.json", env!("CARGO_MANIFEST_DIR"))
}

/// A project whose settings name a plant PROGRAM runs it after the controller on every
/// scan; `--json` reports its variables under its name (issue 17, "A plant is a program").
#[test]
fn run_runs_the_plant_named_in_the_settings() {
    let tank = tank_example();
    let out = plc(&["run", &tank, "--cycles", "3", "--set", "Auto=TRUE", "--json"]);
    assert!(out.status.success(), "{}", stdout(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("json");
    // The controller runs the pump; the plant's tank loses 20 l/s over the two scans that
    // had time (the first scan's clock has not moved).
    assert_eq!(v["vars"]["OutletPump"], true, "{v}");
    assert_eq!(v["vars"]["TankPlant"]["OutletPump"], true, "{v}");
    let volume = v["vars"]["TankPlant"]["Volume"].as_f64().expect("a number");
    assert!((volume - 299.6).abs() < 1e-3, "{v}");
    assert_eq!(v["vars"]["TankPlant"]["Fills"], 0, "{v}");
    // The plant run on its own has no plant.
    let out = plc(&["run", &tank, "--cycles", "3", "--program", "TankPlant", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("json");
    assert!(v["vars"]["Volume"].is_number(), "{v}");
    assert!(v["vars"].get("TankPlant").is_none(), "{v}");
    // Linked variables of two types: E0306, named.
    let text = std::fs::read_to_string(&tank).expect("the example");
    let bad = text.replacen("HighSwitch : BOOL;", "HighSwitch : INT;", 1).replace(
        "HighSwitch := Volume >= 850.0 AND NOT FaultHighStuck;",
        "HighSwitch := BOOL_TO_INT(Volume >= 850.0 AND NOT FaultHighStuck);",
    );
    assert_ne!(bad, text);
    let path = source_file("tank-bad.plcproj.json", &bad);
    let out = plc(&["run", &path.to_string_lossy(), "--json"]);
    assert!(!out.status.success());
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).expect("json");
    assert_eq!(v["status"], "error");
    let d =
        v["diagnostics"].as_array().unwrap().iter().find(|d| d["code"] == "E0306").expect("E0306");
    assert!(d["message"].as_str().unwrap().contains("HighSwitch of the plant TankPlant"), "{d}");
}

/// `plc run --csv` prints the recorded variables scan by scan, as the web app's timeline
/// exports them: the project's timeline variables, or those `--trace` names.
#[test]
fn run_csv_prints_the_trace_scan_by_scan() {
    let tank = tank_example();
    let out = plc(&["run", &tank, "--cycles", "3", "--set", "Auto=TRUE", "--csv"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = stdout(&out);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines[0], "time_ms,scan,TankPlant.Volume,InletValve,OutletPump,HighSwitch,LowSwitch",
        "{text}"
    );
    assert_eq!(lines.len(), 4, "{text}");
    assert!(lines[1].starts_with("10,1,300,0,1,0,0"), "{text}");
    let out = plc(&[
        "run",
        &tank,
        "--cycles",
        "2",
        "--trace",
        "TankPlant.Fills",
        "--trace",
        "Auto",
        "--csv",
    ]);
    assert_eq!(stdout(&out), "time_ms,scan,TankPlant.Fills,Auto\r\n10,1,0,0\r\n20,2,0,0\r\n");
    // A name the program does not have: E0300 on standard error, nothing recorded.
    let out = plc(&["run", &tank, "--trace", "Nope", "--csv"]);
    assert!(!out.status.success());
    assert_eq!(stdout(&out), "");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("error[E0300]: --trace: the program has no variable `Nope`"), "{err}");
}
