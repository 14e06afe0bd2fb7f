#![allow(clippy::unwrap_used)]

use super::*;
use crate::i18n::Lang;
use crate::project::Project;

const LATCH: &str = r#"
id = "latch"
title = "Start/stop motor latch"
level = 1
languages = ["st", "ld"]
statement = "Start starts the motor, Stop stops it; the motor keeps running when Start is released."

[[interface]]
name = "Start"
type = "BOOL"
direction = "input"
meaning = "start button (NO)"

[[interface]]
name = "Stop"
type = "BOOL"
direction = "input"
meaning = "stop button (NO here)"

[[interface]]
name = "Motor"
type = "BOOL"
direction = "output"
meaning = "motor contactor"

[[scenario]]
name = "Start, release, stop"
hint = "Does the motor hold itself when Start is released?"
weight = 2
step = [
  { at = "0s", set = { Start = false, Stop = false } },
  { at = "100ms", set = { Start = true } },
  { at = "200ms", set = { Start = false } },
  { at = "500ms", set = { Stop = true } },
]
expect = [
  { holds = "NOT Motor", from = "0s", to = "90ms" },
  { that = "Motor", at = "150ms" },
  { holds = "Motor", from = "210ms", to = "490ms" },
  { becomes = "NOT Motor", from = "500ms", to = "530ms" },
]

[[scenario]]
name = "Both buttons"
step = [ { at = "0s", set = { Start = true, Stop = true } } ]
expect = [ { never = "Motor" } ]
duration = "1s"
"#;

fn project(st: &str) -> Project {
    let mut p = Project::new("submission");
    p.source = st.into();
    p
}

const GOOD: &str = "PROGRAM Main
VAR_INPUT Start, Stop : BOOL; END_VAR
VAR_OUTPUT Motor : BOOL; END_VAR
Motor := (Start OR Motor) AND NOT Stop;
END_PROGRAM
";

#[test]
fn the_file_reads_with_its_scenarios_and_durations() {
    let e = Exercise::from_toml(LATCH).unwrap();
    assert_eq!((e.id.as_str(), e.level, e.interface.len(), e.scenarios.len()), ("latch", 1, 3, 2));
    let x = e.scenarios[0].expectations().unwrap();
    assert_eq!(x[1], Expectation::At { condition: "Motor".into(), at: 150_000_000 });
    assert_eq!(x[3].describe(), "NOT Motor becomes TRUE between 0.5 s and 0.53 s");
    assert_eq!(e.scenarios[0].duration_ns().unwrap(), 540_000_000);
    assert_eq!(parse_duration("1.5s"), Ok(1_500_000_000));
    assert_eq!(parse_duration("T#1s500ms"), Ok(1_500_000_000));
    assert_eq!(parse_duration("2min"), Ok(120_000_000_000));
    assert!(parse_duration("5").unwrap_err().contains("no unit"));
}

#[test]
fn bad_files_say_where() {
    let e = Exercise::from_toml("id = \"x\"\ntitle = 3\n").unwrap_err();
    assert!(e.message.starts_with("line 2, column 9: "), "{e}");
    let two = LATCH.replace("{ never = \"Motor\" }", "{ never = \"Motor\", always = \"Motor\" }");
    let e = Exercise::from_toml(&two).unwrap_err();
    assert!(
        e.message.starts_with("scenario “Both buttons”, expectation 1: give exactly one"),
        "{e}"
    );
    let e = Exercise::from_toml(&LATCH.replace("\"150ms\"", "\"150\"")).unwrap_err();
    assert!(e.message.contains("“150” has no unit"), "{e}");
}

#[test]
fn the_right_program_passes_every_scenario() {
    let e = Exercise::from_toml(LATCH).unwrap();
    let r = grade(&e, &project(GOOD)).unwrap();
    assert_eq!(r.error, None);
    assert!(r.scenarios.iter().all(ScenarioReport::passed), "{r:#?}");
    assert_eq!((r.score, r.total), (3, 3));
}

#[test]
fn a_program_without_the_seal_in_fails_at_the_first_wrong_scan() {
    let e = Exercise::from_toml(LATCH).unwrap();
    let wrong = GOOD.replace("(Start OR Motor)", "Start");
    let r = grade(&e, &project(&wrong)).unwrap();
    assert_eq!((r.score, r.total), (1, 3));
    let s = &r.scenarios[0];
    let f = s.failure.as_ref().unwrap();
    assert_eq!(f.expected, "Motor stays TRUE from 0.21 s to 0.49 s");
    // Start is released for the scan that ends at 0.21 s: the motor drops on that scan.
    assert_eq!(f.actual, "Motor was FALSE at 0.21 s (scan 21)");
    assert_eq!((f.scan, f.time_ns), (21, 210_000_000));
    assert_eq!(s.hint.as_deref(), Some("Does the motor hold itself when Start is released?"));
    let scans: Vec<u64> = f.window.iter().map(|w| w.scan).collect();
    assert_eq!(scans, (16..=26).collect::<Vec<_>>());
    let at_20 = &f.window[4];
    assert_eq!(
        at_20.values,
        [
            ("Start".into(), "TRUE".into()),
            ("Stop".into(), "FALSE".into()),
            ("Motor".into(), "TRUE".into())
        ]
    );
    assert!(r.scenarios[1].passed());
}

#[test]
fn broken_missing_and_faulting_programs_are_reported_with_their_place() {
    let e = Exercise::from_toml(LATCH).unwrap();
    let r = grade(&e, &project(&GOOD.replace("NOT Stop", "NOT Stopp"))).unwrap();
    let error = r.error.unwrap();
    assert!(error.starts_with("the program does not build: line 4, column 35: "), "{error}");
    assert_eq!((r.score, r.total), (0, 3));
    let r = grade(
        &e,
        &project(
            &GOOD
                .replace("Motor : BOOL", "Motr : BOOL")
                .replace("Motor :=", "Motr :=")
                .replace("OR Motor", "OR Motr"),
        ),
    )
    .unwrap();
    assert_eq!(
        r.error.as_deref(),
        Some("the program does not declare Motor (VAR_OUTPUT Motor : BOOL)")
    );
    // Declared, but as a local or with another type: the interface is a contract.
    let local = GOOD.replace("VAR_OUTPUT Motor : BOOL; END_VAR", "VAR Motor : BOOL; END_VAR");
    assert_eq!(
        grade(&e, &project(&local)).unwrap().error.as_deref(),
        Some("the program declares Motor in another section than the exercise asks (VAR_OUTPUT Motor : BOOL, or VAR Motor AT %Q… : BOOL)")
    );
    let int = GOOD
        .replace("VAR_INPUT Start, Stop : BOOL;", "VAR_INPUT Start : BOOL; Stop : INT;")
        .replace("NOT Stop", "Stop = 0");
    assert_eq!(
        grade(&e, &project(&int)).unwrap().error.as_deref(),
        Some("the program declares Stop as INT, but the exercise asks for VAR_INPUT Stop : BOOL")
    );
    let faulting = "PROGRAM Main
VAR_INPUT Start, Stop : BOOL; END_VAR
VAR_OUTPUT Motor : BOOL; END_VAR
VAR a : ARRAY[1..2] OF INT; i : INT; END_VAR
IF Start THEN i := 3; a[i] := 1; END_IF;
END_PROGRAM
";
    let r = grade(&e, &project(faulting)).unwrap();
    let f = r.scenarios[0].failure.as_ref().unwrap();
    assert!(
        f.actual.starts_with("the program stopped with a FAULT at line 5, column "),
        "{}",
        f.actual
    );
}

/// On a PLC a variable at `%I…` is an input and one at `%Q…` an output: a PROGRAM that
/// declares its I/O as located locals (as OpenPLC Editor and Beremiz write them) has the
/// exercise's interface; a local in memory (`%M…`) or unlocated has not, and an input
/// located at `%Q…` is not an input.
#[test]
fn located_locals_are_inputs_and_outputs_by_their_area() {
    let e = Exercise::from_toml(LATCH).unwrap();
    let located = "PROGRAM program0
VAR
    Start AT %IX0.0 : BOOL;
    Stop AT %IX0.1 : BOOL;
    Motor AT %QX0.0 : BOOL;
END_VAR
Motor := (Start OR Motor) AND NOT Stop;
END_PROGRAM
";
    let r = grade(&e, &project(located)).unwrap();
    assert_eq!((r.error.as_deref(), r.score, r.total), (None, 3, 3), "{r:#?}");
    // RETAIN outputs and a mix of sections are outputs and inputs too.
    let mixed = "PROGRAM Main
VAR_INPUT Start : BOOL; END_VAR
VAR Stop AT %IX0.1 : BOOL; END_VAR
VAR_OUTPUT RETAIN Motor : BOOL; END_VAR
Motor := (Start OR Motor) AND NOT Stop;
END_PROGRAM
";
    let r = grade(&e, &project(mixed)).unwrap();
    assert_eq!((r.error.as_deref(), r.score), (None, 3), "{r:#?}");
    let error = |text: &str| grade(&e, &project(text)).unwrap().error.unwrap_or_default();
    assert_eq!(
        error(&located.replace("%QX0.0", "%MX0.0")),
        "the program declares Motor in another section than the exercise asks (VAR_OUTPUT Motor : BOOL, or VAR Motor AT %Q… : BOOL)"
    );
    assert_eq!(
        error(&located.replace("%IX0.0", "%QX0.1")),
        "the program declares Start in another section than the exercise asks (VAR_INPUT Start : BOOL, or VAR Start AT %I… : BOOL)"
    );
    assert!(error(&located.replace("Stop AT %IX0.1", "Stop"))
        .contains("declares Stop in another section"));
}

#[test]
fn grading_is_deterministic() {
    let e = Exercise::from_toml(LATCH).unwrap();
    let wrong = GOOD.replace("(Start OR Motor)", "Start");
    assert_eq!(grade(&e, &project(&wrong)).unwrap(), grade(&e, &project(&wrong)).unwrap());
}

const REVERSING: &str = include_str!("../../../exercises/reversing/reversing.toml");

#[test]
fn a_random_scenario_finds_both_directions_on_and_gives_a_seed_that_replays_it() {
    let e = Exercise::from_toml(REVERSING).unwrap();
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../exercises/reversing");
    let read = |f: &str| std::fs::read_to_string(format!("{root}/{f}")).unwrap();
    // The fixed scenario lets the classic bug pass; the random one catches it.
    let r = grade(&e, &project(&read("mutants/no-interlock.st"))).unwrap();
    assert!(r.scenarios[0].passed(), "{r:#?}");
    let f = r.scenarios[1].failure.as_ref().unwrap();
    assert_eq!(f.expected, "MotorFwd AND MotorRev is never TRUE");
    assert!(f.actual.starts_with("MotorFwd AND MotorRev was TRUE at "), "{}", f.actual);
    let seed: u64 = f
        .actual
        .split("random run with seed ")
        .nth(1)
        .unwrap()
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let events = f.actual.split("shortest failing events: ").nth(1).unwrap();
    assert!(events.contains("Fwd := TRUE") && events.contains("Rev := TRUE"), "{events}");
    // Replayed alone with its seed, the run fails the same way.
    let mut replay = e.clone();
    replay.scenarios[1].random = Some(Random { runs: 1, seed });
    let again = grade(&replay, &project(&read("mutants/no-interlock.st"))).unwrap();
    assert_eq!(again.scenarios[1].failure.as_ref().unwrap().actual, f.actual);
    // The interlocked reference survives every run.
    assert!(grade(&e, &project(&read("reference.st")))
        .unwrap()
        .scenarios
        .iter()
        .all(ScenarioReport::passed));
}

#[test]
fn random_scenarios_check_safety_rules_only_and_say_how_long_they_run() {
    let no_duration = REVERSING.replace("duration = \"3s\"\n", "");
    let e = Exercise::from_toml(&no_duration).unwrap_err();
    assert!(e.message.contains("says how long it runs"), "{e}");
    let at = REVERSING.replace(
        "expect = [ { never = \"MotorFwd AND MotorRev\" } ]",
        "expect = [ { that = \"MotorFwd\", at = \"1s\" } ]",
    );
    let e = Exercise::from_toml(&at).unwrap_err();
    assert!(e.message.contains("only `never` and `always`"), "{e}");
}

#[test]
fn a_failure_window_draws_the_condition_against_what_it_should_be() {
    let e = Exercise::from_toml(LATCH).unwrap();
    let no_seal = "PROGRAM Main
VAR_INPUT Start, Stop : BOOL; END_VAR
VAR_OUTPUT Motor : BOOL; END_VAR
Motor := Start AND NOT Stop;
END_PROGRAM
";
    let report = grade_with(&e, &project(no_seal), GradeOptions { window: 30 }).unwrap();
    let f = report.scenarios[0].failure.as_ref().unwrap();
    assert_eq!(f.condition.as_deref(), Some("Motor"));
    // Every scan before the wrong one (scan 21 at 0.21 s: only 20, fewer than 30), the
    // wrong one and 30 after.
    let scans: Vec<u64> = f.window.iter().map(|s| s.scan).collect();
    assert_eq!(scans, (1..=51).collect::<Vec<u64>>());
    let wrong = f.window.iter().find(|s| s.scan == f.scan).unwrap();
    assert_eq!((wrong.actual, wrong.expected), (Some(false), Some(true)));
    // Before the `holds` window any value is right; Motor was TRUE while Start was held.
    let held = f.window.iter().find(|s| s.scan == 15).unwrap();
    assert_eq!((held.actual, held.expected), (Some(true), None));
}

#[test]
fn a_warm_restart_step_keeps_retain_variables_and_the_scenario_clock_goes_on() {
    let toml = r#"
id = "retain"
title = "Retained counter"
level = 2

[[interface]]
name = "Pulse"
type = "BOOL"
direction = "input"

[[interface]]
name = "Count"
type = "INT"
direction = "output"

[[scenario]]
name = "Count survives a power cycle"
step = [
  { at = "0s", set = { Pulse = false } },
  { at = "100ms", set = { Pulse = true } },
  { at = "200ms", set = { Pulse = false } },
  { at = "300ms", restart = "warm" },
]
expect = [
  { that = "Count = 1", at = "250ms" },
  { holds = "Count = 1", from = "300ms", to = "500ms" },
]
"#;
    let e = Exercise::from_toml(toml).unwrap();
    let body = "VAR_INPUT Pulse : BOOL; END_VAR
VAR_OUTPUT Count : INT; END_VAR
VAR Edge : R_TRIG; END_VAR
Edge(CLK := Pulse);
IF Edge.Q THEN Count := Count + 1; END_IF;
END_PROGRAM
";
    let retained = format!("PROGRAM Main\n{body}")
        .replace("VAR_OUTPUT Count : INT;", "VAR_OUTPUT RETAIN Count : INT;");
    let report = grade(&e, &project(&retained)).unwrap();
    assert_eq!(report.score, 1, "{report:?}");
    let plain = format!("PROGRAM Main\n{body}");
    let report = grade(&e, &project(&plain)).unwrap();
    let f = report.scenarios[0].failure.as_ref().unwrap();
    // The scenario's clock runs on across the restart: the counter is 0 from 0.3 s.
    assert_eq!(f.actual, "Count = 1 was FALSE at 0.31 s (scan 31)");
    let bad = toml.replace(r#"{ at = "300ms", restart = "warm" }"#, r#"{ at = "300ms" }"#);
    let err = Exercise::from_toml(&bad).unwrap_err().message;
    assert!(err.contains("neither sets inputs"), "{err}");
}

fn with_languages(languages: &str) -> Exercise {
    let text = LATCH.replace(
        "languages = [\"st\", \"ld\"]",
        &format!("languages = [{languages}]\nprogram = \"Latch\""),
    );
    Exercise::from_toml(&text).unwrap()
}

/// Every generated starter declares the interface, builds, names its PROGRAM in the
/// settings, is graded as that PROGRAM in its language, and fails.
#[test]
fn a_starter_is_made_in_every_language_with_the_interface_declared() {
    let e = with_languages(r#""ld", "st", "petri", "sfc""#);
    let starters = e.starters(|f| Err(format!("no file {f}"))).unwrap();
    let languages: Vec<Language> = starters.iter().map(|(l, _)| *l).collect();
    assert_eq!(languages, [Language::Ld, Language::St, Language::Petri, Language::Sfc]);
    let labels = ["ladder", "ST", "Petri net", "SFC"];
    for ((language, p), label) in starters.iter().zip(labels) {
        assert_eq!(p.settings.program.as_deref(), Some("Latch"), "{language:?}");
        let build = crate::build::build_project(p);
        assert!(!build.has_errors(), "{language:?}: {:?}", build.diagnostics);
        assert_eq!(build.program_names(), ["Latch"], "{language:?}");
        let r = grade(&e, p).unwrap();
        assert_eq!(r.error, None, "{language:?}");
        assert!(r.score < r.total, "{language:?}");
        assert_eq!(r.checked_line().unwrap(), format!("Checked PROGRAM Latch ({label})"));
    }
    let ld = &starters[0].1.ladder[0];
    assert_eq!(ld.rungs.len(), 1);
    assert!(ld.declarations.starts_with(
        "VAR_INPUT\n    Start : BOOL; (* start button (NO) *)\n    Stop : BOOL; (* stop button (NO here) *)\nEND_VAR\nVAR_OUTPUT\n    Motor : BOOL; (* motor contactor *)\nEND_VAR\n"
    ), "{}", ld.declarations);
    let net = &starters[2].1.petri[0];
    // The net holds its initial place only (an empty net does not build).
    assert_eq!((net.net.places.len(), net.net.places[0].tokens), (1, 1));
    assert!(net.net.transitions.is_empty() && net.net.arcs.is_empty());
    assert!(net.declarations.contains("Motor : BOOL; (* motor contactor *)"));
    let sfc = &starters[3].1.source;
    assert!(sfc.contains("INITIAL_STEP Idle :\nEND_STEP"), "{sfc}");
    assert!(starters[1].1.source.starts_with("PROGRAM Latch\nVAR_INPUT\n"));
}

/// A starter the exercise gives is used for its language and names the PROGRAM the
/// generated ones get; a starter that does not open is refused with its name.
#[test]
fn given_starters_name_the_program_of_the_generated_ones() {
    let mut e = with_languages(r#""st", "ld""#);
    e.program = None;
    e.starter = Some("starter.st".into());
    let starters = e
        .starters(|f| {
            assert_eq!(f, "starter.st");
            Ok(project("PROGRAM Motor1\nVAR_INPUT Start, Stop : BOOL; END_VAR\nVAR_OUTPUT Motor : BOOL; END_VAR\nEND_PROGRAM\n"))
        })
        .unwrap();
    assert_eq!(starters[0].1.settings.program.as_deref(), Some("Motor1"));
    assert_eq!(starters[1].1.ladder[0].name, "Motor1");
    e.starter_ld = Some("ld.plcproj.json".into());
    let err =
        e.starters(|f| if f == "starter.st" { Ok(project(GOOD)) } else { Err("broken".into()) });
    assert_eq!(err.unwrap_err().message, "the starter ld.plcproj.json cannot be opened: broken");
    assert_eq!(e.starter_files(), ["starter.st", "ld.plcproj.json"]);
    let bad = LATCH.replace("languages = [\"st\", \"ld\"]", "languages = [\"st\", \"fbd\"]");
    assert_eq!(
        Exercise::from_toml(&bad).unwrap_err().message,
        "languages: “fbd” is not one of st, ld, petri, sfc"
    );
}

/// The grader grades the PROGRAM the project's settings choose (the student's), else the
/// one the exercise names, else the first; the report names it and its language.
#[test]
fn the_grader_grades_the_program_the_student_chose() {
    let e = with_languages(r#""st", "ld""#);
    let two = format!(
        "{}\n{}",
        GOOD.replace("PROGRAM Main", "PROGRAM Other").replace("(Start OR Motor)", "Start"),
        GOOD.replace("PROGRAM Main", "PROGRAM Latch")
    );
    // Nothing chosen: the exercise's `program = "Latch"`, though it comes second.
    let mut p = project(&two);
    let r = grade(&e, &p).unwrap();
    assert_eq!((r.score, r.checked_line().unwrap().as_str()), (3, "Checked PROGRAM Latch (ST)"));
    // The student chose Other.
    p.settings.program = Some("Other".into());
    let r = grade(&e, &p).unwrap();
    assert_eq!((r.score, r.program.as_deref()), (1, Some("Other")));
    // A ladder latch drawn in a POU of its own and chosen.
    let mut p = e.starters(|_| Err(String::new())).unwrap()[1].1.clone();
    p.add_ladder_pou("Drawn", crate::ladder::LadderPouKind::Program).unwrap();
    p.ladder[1].declarations = p.ladder[0].declarations.clone();
    p.ladder[1].rungs = serde_json::from_str(LATCH_RUNG).unwrap();
    p.settings.program = Some("Drawn".into());
    let r = grade(&e, &p).unwrap();
    assert_eq!((r.score, r.total), (3, 3), "{r:?}");
    assert_eq!(r.checked_line().unwrap(), "Checked PROGRAM Drawn (ladder)");
    // A choice that names no PROGRAM falls back to the exercise's.
    p.settings.program = Some("Gone".into());
    assert_eq!(grade(&e, &p).unwrap().program.as_deref(), Some("Latch"));
}

/// `Start OR Motor` in parallel, then NC `Stop`, then the `Motor` coil.
const LATCH_RUNG: &str = r#"[{ "comment": "", "cells": [
  [ { "element": { "type": "Contact", "kind": "NormallyOpen", "operand": "Start" } },
    { "element": { "type": "Contact", "kind": "NormallyClosed", "operand": "Stop" }, "link_down": true },
    { "element": { "type": "Coil", "kind": "Normal", "operand": "Motor" } } ],
  [ { "element": { "type": "Contact", "kind": "NormallyOpen", "operand": "Motor" } },
    { "element": { "type": "Empty" } }, { "element": { "type": "Empty" } } ] ] }]"#;

#[test]
fn the_score_line_explains_the_weights_when_they_matter() {
    let e = Exercise::from_toml(LATCH).unwrap();
    let r = grade(&e, &project(&GOOD.replace("(Start OR Motor)", "Start"))).unwrap();
    assert_eq!(r.score_line(), "Score 1 of 3 (scenario weights: 2 + 1)");
    assert_eq!(grade(&e, &project(GOOD)).unwrap().score_line(), "Score 3 of 3");
    let mut even = e.clone();
    even.scenarios[0].weight = 1;
    even.scenarios.push(even.scenarios[1].clone());
    let r = grade(&even, &project(&GOOD.replace("(Start OR Motor)", "Start"))).unwrap();
    assert_eq!(r.score_line(), "Score 2 of 3 (3 scenarios, 1 point each)");
    let mut one = e.clone();
    one.scenarios.truncate(1);
    let r = grade(&one, &project(&GOOD.replace("(Start OR Motor)", "Start"))).unwrap();
    assert_eq!(r.score_line(), "Score 0 of 2");
    let broken = grade(&e, &project(&GOOD.replace("NOT Stop", "NOT Stopp"))).unwrap();
    assert_eq!(broken.checked_line().unwrap(), "Checked PROGRAM Main (ST)");
    assert_eq!(broken.score_line(), "Score 0 of 3");
}

/// The built form (what the web app ships) reads as the TOML file does, with the statement
/// already rendered, and is checked as a file is.
#[test]
fn the_built_form_reads_as_the_toml_file() {
    let render = |m: &str| statement_html(m, None);
    let built = built_form(LATCH, render).unwrap();
    assert!(is_built(&built) && !is_built(LATCH), "{built}");
    let (read, html) = Exercise::from_built(&built).unwrap();
    let toml = Exercise::from_toml(LATCH).unwrap();
    assert_eq!(read, Exercise { statement: String::new(), ..toml.clone() });
    assert_eq!(ExerciseView::with_statement(&read, html), ExerciseView::of(&toml, None));
    assert_eq!(Exercise::from_text(&built).unwrap(), read);
    assert_eq!(Exercise::from_text(LATCH).unwrap(), toml);
    // A link carries either form.
    let link = ExerciseLink { exercise: built.clone(), starter: None, starters: Vec::new() };
    let (back, exercise) = ExerciseLink::decode(&link.encode().unwrap()).unwrap();
    assert_eq!((back, exercise), (link, read));

    let bad = built_form(&LATCH.replace("level = 1", "level = 9"), render).unwrap();
    assert_eq!(
        Exercise::from_built(&bad).unwrap_err().message,
        "level is 1 (beginner) to 5 (advanced)"
    );
    let damaged = format!("{BUILT_PREFIX}\"statement_html\":3}}");
    assert!(Exercise::from_built(&damaged).unwrap_err().message.starts_with("the built exercise"));
    assert!(built_form("id = 1979-05-27", render).unwrap_err().contains("date"));
    assert!(built_form("id = ", render).is_err());
}

/// The latch with a Polish translation that leaves the meaning of `Stop` out and a Czech one
/// that has only a title.
fn translated_latch() -> String {
    format!(
        r#"{LATCH}
[lang.pl]
title = "Podtrzymanie silnika start/stop"
statement = "Start uruchamia silnik, Stop go zatrzymuje: `Motor := (Start OR Motor) AND NOT Stop;`"

[lang.pl.meaning]
Start = "przycisk start (zwierny)"
Motor = "stycznik silnika"

[lang.pl.scenario."Start, release, stop"]
name = "Start się podtrzymuje"
hint = "Czy Motor podtrzymuje się sam?"

[lang.cs]
title = "Samodržný obvod start/stop"
"#
    )
}

/// A localised exercise is the Polish where the file translates it and the English where
/// it does not; grading is the same.
#[test]
fn the_localised_exercise_falls_back_to_english() {
    let text = translated_latch().replace(
        "Start starts the motor, Stop stops it; the motor keeps running when Start is released.",
        "Start starts the motor: `Motor := (Start OR Motor) AND NOT Stop;`",
    );
    let e = Exercise::from_toml(&text).unwrap();
    let pl = e.localised(Lang::Pl);
    assert_eq!(pl.title, "Podtrzymanie silnika start/stop");
    assert!(pl.statement.starts_with("Start uruchamia"), "{}", pl.statement);
    assert_eq!(pl.interface[0].meaning, "przycisk start (zwierny)");
    assert_eq!(pl.interface[1].meaning, "stop button (NO here)", "English where untranslated");
    assert_eq!(pl.interface[1].name, "Stop", "names stay");
    assert_eq!(pl.scenarios[0].name, "Start się podtrzymuje");
    assert_eq!(pl.scenarios[0].hint.as_deref(), Some("Czy Motor podtrzymuje się sam?"));
    assert_eq!(pl.scenarios[1], e.scenarios[1], "an untranslated scenario stays English");
    let cs = e.localised(Lang::Cs);
    assert_eq!(cs.title, "Samodržný obvod start/stop");
    assert_eq!((cs.statement.as_str(), &cs.scenarios), (e.statement.as_str(), &e.scenarios));
    assert_eq!(e.localised(Lang::En), e);
    assert!(e.translation_problems().is_empty(), "{:?}", e.translation_problems());
    assert!(e.untranslated(Lang::Pl).contains(&"meaning.Stop".to_string()));
    assert!(e.untranslated(Lang::Cs).contains(&"statement".to_string()));
    // The same grade in every language, names translated.
    let p = project(GOOD);
    let (en, pl) = (grade(&e, &p).unwrap(), grade(&pl, &p).unwrap());
    assert_eq!((en.score, en.total), (pl.score, pl.total));
    assert_eq!(pl.scenarios[0].name, "Start się podtrzymuje");
}

/// A translation that renames an interface variable or a scenario, or changes program
/// text, is reported, located; an unknown language is refused.
#[test]
fn a_translation_with_other_names_is_reported() {
    let bad = translated_latch()
        .replace("Motor = \"stycznik", "Silnik = \"stycznik")
        .replace("scenario.\"Start, release, stop\"", "scenario.\"Start zatrzaskuje\"")
        .replace("`Motor := (Start OR Motor) AND NOT Stop;`", "`Silnik := Start;`");
    let e = Exercise::from_toml(&bad).unwrap();
    let problems = e.translation_problems();
    assert_eq!(problems.len(), 3, "{problems:#?}");
    assert!(
        problems[0].starts_with(
            "lang.pl.meaning: “Silnik” is not a variable of the interface (Start, Stop, Motor)"
        ),
        "{problems:#?}"
    );
    assert!(
        problems[1]
            .starts_with("lang.pl.scenario.“Start zatrzaskuje”: there is no scenario of that name"),
        "{problems:#?}"
    );
    assert!(
        problems[2].starts_with("lang.pl.statement: the program text between backticks differs from English: the translation has `Silnik := Start;`"),
        "{problems:#?}"
    );
    let de = format!("{LATCH}\n[lang.de]\ntitle = \"Selbsthaltung\"\n");
    assert!(Exercise::from_toml(&de)
        .unwrap_err()
        .message
        .starts_with("lang.de: the translations are"));
    let unknown = format!("{LATCH}\n[lang.pl]\ntitel = \"x\"\n");
    assert!(Exercise::from_toml(&unknown).unwrap_err().message.contains("unknown field `titel`"));
    let html = format!("{LATCH}\n[lang.pl]\nstatement_html = \"<b>x</b>\"\n");
    assert!(Exercise::from_toml(&html).unwrap_err().message.contains("statement_html"));
}

/// The built form and the page's view carry the translations, statements rendered; the
/// view and its reports localise with the English fallback.
#[test]
fn the_built_form_and_the_view_carry_the_translations() {
    let text = translated_latch();
    let built = built_form(&text, |m| statement_html(m, None)).unwrap();
    let (read, html) = Exercise::from_built(&built).unwrap();
    let toml = Exercise::from_toml(&text).unwrap();
    let pl = &read.lang["pl"];
    assert_eq!(pl.statement, None);
    assert!(pl
        .statement_html
        .as_deref()
        .unwrap()
        .contains("<code>Motor := (Start OR Motor) AND NOT Stop;</code>"));
    let view = ExerciseView::with_statement(&read, html);
    assert_eq!(view, ExerciseView::of(&toml, None));
    let json = serde_json::to_string(&view).unwrap();
    assert_eq!(serde_json::from_str::<ExerciseView>(&json).unwrap(), view);
    let v = view.localised(Lang::Pl);
    assert_eq!(v.title, "Podtrzymanie silnika start/stop");
    assert!(v.statement_html.starts_with("<p>Start uruchamia"), "{}", v.statement_html);
    assert_eq!(v.interface[2].meaning, "stycznik silnika");
    assert_eq!(v.scenarios[0].name, "Start się podtrzymuje");
    let cs = view.localised(Lang::Cs);
    assert_eq!(cs.title, "Samodržný obvod start/stop");
    assert_eq!(
        (cs.statement_html.as_str(), &cs.interface),
        (view.statement_html.as_str(), &view.interface)
    );
    assert_eq!(view.localised(Lang::En), view);
    // A failed report: the Polish name and hint.
    let report = grade(&toml, &project(&GOOD.replace("(Start OR Motor)", "Start"))).unwrap();
    let failed = report.scenarios.iter().position(|s| s.name == "Start, release, stop").unwrap();
    assert!(report.scenarios[failed].hint.is_some());
    let r = view.localised_report(Lang::Pl, report.clone());
    assert_eq!(r.scenarios[failed].name, "Start się podtrzymuje");
    assert_eq!(r.scenarios[failed].hint.as_deref(), Some("Czy Motor podtrzymuje się sam?"));
    assert_eq!(view.localised_report(Lang::Cs, report.clone()), report);
}

/// The report's sentences are data beside their English (issue 33): English as the text,
/// Polish and Czech from the message catalogue, the same after the trip to the page as JSON.
#[test]
fn a_reports_sentences_in_english_polish_and_czech_survive_json() {
    let e = Exercise::from_toml(LATCH).unwrap();
    let r = grade(&e, &project(&GOOD.replace("(Start OR Motor)", "Start"))).unwrap();
    let json = serde_json::to_string(&r).unwrap();
    let back: Report = serde_json::from_str(&json).unwrap();
    assert_eq!(back, r);
    let f = back.scenarios[0].failure.as_ref().unwrap();
    let (expected, actual) = (f.expected_msg.as_ref().unwrap(), f.actual_msg.as_ref().unwrap());
    assert_eq!(expected.render(Lang::En), f.expected);
    assert_eq!(actual.render(Lang::En), f.actual);
    assert_eq!(actual.render(Lang::Pl), "Motor miało wartość FALSE w chwili 0.21 s (cykl 21)");
    assert_eq!(
        expected.render(Lang::Cs),
        "Motor má hodnotu TRUE bez přerušení od 0.21 s do 0.49 s"
    );
    assert_eq!(r.score_said().message.render(Lang::Pl), "Wynik 1 z 3 (wagi scenariuszy: 2 + 1)");
    assert_eq!(r.checked().unwrap().message.render(Lang::Cs), "Zkontrolován PROGRAM Main (ST)");

    // A FAULT: its place and the fault's own message are parts, translated too.
    let faulting = "PROGRAM Main
VAR_INPUT Start, Stop : BOOL; END_VAR
VAR_OUTPUT Motor : BOOL; END_VAR
VAR a : ARRAY[1..2] OF INT; i : INT; END_VAR
IF Start THEN i := 3; a[i] := 1; END_IF;
END_PROGRAM
";
    let r = grade(&e, &project(faulting)).unwrap();
    let back: Report = serde_json::from_str(&serde_json::to_string(&r).unwrap()).unwrap();
    let f = back.scenarios[0].failure.as_ref().unwrap();
    let actual = f.actual_msg.as_ref().unwrap();
    assert_eq!(actual.render(Lang::En), f.actual);
    let polish = actual.render(Lang::Pl);
    assert!(
        polish.starts_with("program zatrzymał się z AWARIĄ (FAULT): wiersz 5, kolumna "),
        "{polish}"
    );
    assert!(polish.ends_with(": indeks tablicy 3 jest poza zakresem 1..2"), "{polish}");
    assert_eq!(f.expected_msg.as_ref().unwrap().render(Lang::Cs), "žádná PORUCHA (FAULT)");

    // Nothing ran: the error, with the build error's own message translated.
    let broken = grade(&e, &project(&GOOD.replace("NOT Stop", "NOT Stopp"))).unwrap();
    let error = broken.error_msg.as_ref().unwrap();
    assert_eq!(error.render(Lang::En), broken.error.clone().unwrap());
    let polish = error.render(Lang::Pl);
    assert!(polish.starts_with("programu nie da się zbudować: wiersz 4, kolumna 35: "), "{polish}");
    // The build error's message with its `did you mean` is translated too, the name kept.
    assert!(polish.contains("; czy chodziło o Stop?"), "{polish}");
    assert!(!polish.contains("did you mean"), "{polish}");
    let local = GOOD.replace("VAR_OUTPUT Motor : BOOL; END_VAR", "VAR Motor : BOOL; END_VAR");
    let r = grade(&e, &project(&local)).unwrap();
    assert_eq!(
        r.error_msg.unwrap().render(Lang::Cs),
        "program deklaruje Motor v jiné sekci, než cvičení požaduje (VAR_OUTPUT Motor : BOOL, nebo VAR Motor AT %Q… : BOOL)"
    );
}

#[test]
fn a_step_sets_booleans_numbers_and_literals_and_refuses_anything_else() {
    let file = LATCH.replace(
        "{ at = \"0s\", set = { Start = false, Stop = false } }",
        "{ at = \"0s\", set = { Start = false, Stop = true, N = 7, X = 1.0, Y = -2.5e3, T = \"T#2s\" } }",
    );
    let e = Exercise::from_toml(&file).unwrap();
    let at_zero: Vec<(String, String)> = random::step_events(&e.scenarios[0])
        .into_iter()
        .filter(|(at, _, _)| *at == 0)
        .map(|(_, name, value)| (name, value))
        .collect();
    let pair = |n: &str, v: &str| (n.to_string(), v.to_string());
    assert_eq!(
        at_zero,
        [
            pair("N", "7"),
            pair("Start", "FALSE"),
            pair("Stop", "TRUE"),
            pair("T", "T#2s"),
            pair("X", "1.0"),
            pair("Y", "-2500.0")
        ]
    );
    // The built form (JSON) reads the same values.
    let built = built_form(&file, |md| md.to_string()).unwrap();
    let (from_json, _) = Exercise::from_built(&built).unwrap();
    assert_eq!(from_json.scenarios[0].steps, e.scenarios[0].steps);
    // An array, a table or a date is not a value an input takes: refused where it stands.
    for bad in ["[1, 2]", "{ a = 1 }", "1979-05-27T07:32:00Z"] {
        let file = LATCH.replace("set = { Start = true }", &format!("set = {{ Start = {bad} }}"));
        let err = Exercise::from_toml(&file).unwrap_err();
        assert!(err.message.starts_with("line 32, column 35: "), "{bad}: {err}");
        assert!(
            err.message.contains("a boolean, a number or an IEC literal in quotes"),
            "{bad}: {err}"
        );
    }
}
