#![allow(clippy::unwrap_used)]

use super::*;
use crate::build::build_project;

const LATCH: &str = "PROGRAM Main
VAR_INPUT Start : BOOL; Stop : BOOL; END_VAR
VAR_OUTPUT Motor : BOOL; Lamp : BOOL; END_VAR
VAR T1 : TON; n : INT; END_VAR
Motor := (Start OR Motor) AND NOT Stop;
T1(IN := Motor, PT := T#50ms);
Lamp := T1.Q;
END_PROGRAM
";

fn st_project(source: &str) -> Project {
    let mut p = Project::new("test");
    p.source = source.to_string();
    p.ladder.clear();
    p
}

fn file_project(name: &str) -> Project {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).unwrap();
    crate::open::open_text(name, &text).unwrap().project
}

/// A recording simulator of `project`, run with `script`: `(scan, var, value)` held from
/// that scan on, up to `scans`.
fn recorded(
    project: &Project,
    build: &ProjectBuild,
    script: &[(u64, &str, &str)],
    scans: u64,
) -> Simulator {
    let program = build.chosen_program(&project.settings);
    let mut sim = build.simulator_with_plant(program, project.settings.plant.as_deref()).unwrap();
    sim.set_recording(true).unwrap();
    for (at, var, value) in script {
        sim.run_scans(at - 1 - sim.scan_count());
        sim.hold(var, value).unwrap();
    }
    sim.run_scans(scans - sim.scan_count());
    sim
}

fn operand<'e>(e: &'e Explanation, name: &str) -> &'e Operand {
    e.operands
        .iter()
        .find(|o| o.name == name)
        .unwrap_or_else(|| panic!("no {name}: {}", e.to_text()))
}

fn step<'e>(e: &'e Explanation, element: &str) -> &'e PowerStep {
    e.path
        .iter()
        .find(|s| s.element == element)
        .unwrap_or_else(|| panic!("no {element}: {}", e.to_text()))
}

#[test]
fn the_ladder_latch_is_explained_by_its_rung_and_the_power_path() {
    let p = file_project("latch-ladder.plcproj.json");
    let b = build_project(&p);
    let sim = recorded(&p, &b, &[(3, "Start", "TRUE"), (4, "Start", "FALSE")], 20);
    let ctx = Context::new(&p, &b);
    let on = explain(&ctx, &sim, "Motor", 3).unwrap();
    assert_eq!(on.value, Json::Bool(true));
    assert_eq!(on.written_by.kind, Kind::Rung);
    assert_eq!(
        (on.written_by.rung, on.written_by.element.as_deref()),
        (Some(1), Some("coil Motor"))
    );
    assert_eq!(on.written_by.text.as_deref(), Some("Motor := (Start OR Motor) AND NOT Stop"));
    assert_eq!(
        on.written_by.site,
        Some(Site::Ladder { pou: "Latch".into(), cell: Some((0, 0, 2)) })
    );
    assert_eq!(
        (operand(&on, "Start").value.clone(), operand(&on, "Start").since_scan),
        (Json::Bool(true), 3)
    );
    assert!(step(&on, "NO contact Start").powered && !step(&on, "NO contact Motor").powered);
    let held = explain(&ctx, &sim, "Motor", 12).unwrap();
    assert_eq!(operand(&held, "Motor").since_scan, 3, "the seal-in contact's variable");
    assert!(!step(&held, "NO contact Start").powered && step(&held, "NO contact Motor").powered);
    assert_eq!((held.previous_change, held.next_change), (Some(3), None));
}

#[test]
fn a_value_nothing_wrote_names_the_scan_it_changed_and_what_wrote_it_then() {
    let p = file_project("weighing-sequential.plcproj.json");
    let b = build_project(&p);
    let sim = recorded(&p, &b, &[(4, "Start", "TRUE")], 30);
    let ctx = Context::new(&p, &b);
    let e = explain_place(&ctx, &sim, "P31", 20).unwrap();
    assert_eq!(e.var, "P31");
    assert_eq!(e.place.as_ref().map(|p| (p.holds_token, p.step_value)), Some((true, 31)));
    assert_eq!((e.written_by.kind, e.written_by.since_scan), (Kind::None, Some(4)));
    let then = e.written_by.then.as_deref().unwrap();
    assert_eq!((then.kind, then.element.as_deref()), (Kind::Transition, Some("T2")));
    assert_eq!(then.text.as_deref(), Some("Start AND NOT Fault"), "the guard");
    assert!(
        matches!(&then.site, Some(Site::Petri { element: Some(NetElement::Transition(t)), .. }) if t == "T2")
    );
    assert_eq!(operand(&e, "p").value, serde_json::json!(1), "the marking that enabled T2: P1");
    assert!(explain_place(&ctx, &sim, "P99", 20).is_err());
    let not = explain_place(&ctx, &sim, "P1", 20).unwrap();
    assert_eq!(not.value, Json::Bool(false));
    assert!(not.to_text().starts_with("P1 holds no token at scan 20"), "{}", not.to_text());
}

#[test]
fn a_petri_output_cleared_by_the_prologue_names_the_marking() {
    let p = file_project("weighing-sequential.plcproj.json");
    let b = build_project(&p);
    let sim = recorded(&p, &b, &[(4, "Start", "TRUE")], 10);
    let ctx = Context::new(&p, &b);
    let e = explain(&ctx, &sim, "DischargeValve", 8).unwrap();
    assert_eq!(e.value, Json::Bool(false));
    assert_eq!(
        (e.written_by.kind, e.written_by.element.as_deref()),
        (Kind::Statement, Some("prologue"))
    );
    assert_eq!(operand(&e, "p").value, serde_json::json!(31));
    let e = explain(&ctx, &sim, "FeedValve", 8).unwrap();
    assert_eq!(
        (e.written_by.kind, e.written_by.element.as_deref()),
        (Kind::StepAction, Some("place P31"))
    );
}

/// Follows the operands of `first` backwards, each at the scan since which it has had its
/// value (the student's clicks), and returns every name reached.
fn follow(ctx: &Context<'_>, sim: &Simulator, first: Explanation, clicks: usize) -> Vec<String> {
    let mut seen: Vec<(String, u64)> = Vec::new();
    let mut queue = vec![first];
    while let Some(e) = queue.pop() {
        for o in &e.operands {
            let click = (o.name.clone(), o.since_scan);
            if seen.contains(&click) || seen.len() >= clicks {
                continue;
            }
            seen.push(click);
            if let Ok(next) = explain(ctx, sim, &o.name, o.since_scan.max(1)) {
                queue.insert(0, next);
            }
        }
    }
    seen.into_iter().map(|(n, _)| n).collect()
}

#[test]
fn the_discharge_valve_of_the_weighing_plant_is_followed_back_to_the_set_point() {
    let p = file_project("weighing-plant.plcproj.json");
    let b = build_project(&p);
    let sim = recorded(&p, &b, &[(2, "Start", "TRUE")], 400);
    let ctx = Context::new(&p, &b);
    let open = (1..=400)
        .find(|&k| sim.view_at(k).unwrap().read("DischargeValve").unwrap() == Value::Bool(true))
        .unwrap();
    let e = explain(&ctx, &sim, "DischargeValve", open + 3).unwrap();
    assert_eq!(e.written_by.element.as_deref(), Some("place P33"));
    let reached = follow(&ctx, &sim, e, 40);
    assert!(reached.iter().any(|n| n == "Setpoint"), "{reached:?}");
    assert!(reached.iter().any(|n| n == "Weight"), "{reached:?}");
    // The load cell is the plant's output: its writer is the plant's statement.
    let w = explain(&ctx, &sim, "Weight", 100).unwrap();
    assert_eq!(w.written_by.pou.as_deref(), Some("WeighingPlant"));
    assert!(w.operands.iter().any(|o| o.name == "WeighingPlant.Content"), "{}", w.to_text());
}

#[test]
fn inputs_forced_values_writes_and_initial_values_are_named() {
    let p = st_project(LATCH);
    let b = build_project(&p);
    let mut sim = recorded(&p, &b, &[(3, "Start", "TRUE")], 5);
    sim.force("Lamp", "TRUE").unwrap();
    sim.write("n", "7").unwrap();
    sim.run_scans(3);
    let ctx = Context::new(&p, &b);
    let start = explain(&ctx, &sim, "start", 4).unwrap();
    assert_eq!(
        (start.var.as_str(), start.written_by.kind),
        ("Start", Kind::Input),
        "declared spelling"
    );
    let lamp = explain(&ctx, &sim, "Lamp", 7).unwrap();
    assert_eq!(lamp.written_by.kind, Kind::Forced);
    let n = explain(&ctx, &sim, "n", 6).unwrap();
    assert_eq!(n.written_by.kind, Kind::Input);
    assert_eq!(n.written_by.text.as_deref(), Some("written from outside before the scan"));
    let n = explain(&ctx, &sim, "n", 8).unwrap();
    assert_eq!((n.written_by.kind, n.written_by.since_scan), (Kind::None, Some(6)));
    let stop = explain(&ctx, &sim, "Stop", 8).unwrap();
    assert_eq!((stop.written_by.kind, stop.written_by.since_scan), (Kind::Initial, Some(0)));
    let zero = explain(&ctx, &sim, "Motor", 0).unwrap();
    assert_eq!(zero.written_by.kind, Kind::Initial);
}

#[test]
fn a_timer_output_names_the_call_with_in_pt_and_et() {
    let p = st_project(LATCH);
    let b = build_project(&p);
    let sim = recorded(&p, &b, &[(3, "Start", "TRUE")], 12);
    let ctx = Context::new(&p, &b);
    let q = explain(&ctx, &sim, "T1.Q", 8).unwrap();
    assert_eq!((q.written_by.kind, q.written_by.line), (Kind::Statement, Some(6)));
    let block = q.block.as_ref().unwrap();
    assert_eq!((block.instance.as_str(), block.fb.as_str()), ("T1", "TON"));
    let history: Vec<(u64, &str, Json)> =
        block.history.iter().map(|c| (c.scan, c.name.as_str(), c.value.clone())).collect();
    assert_eq!(history, [(3, "T1.IN", Json::Bool(true)), (8, "T1.Q", Json::Bool(true))]);
    assert_eq!(operand(&q, "T1.IN").since_scan, 3);
    assert_eq!(operand(&q, "T1.ET").text, "T#50ms");
    let lamp = explain(&ctx, &sim, "Lamp", 10).unwrap();
    assert_eq!(operand(&lamp, "T1.Q").since_scan, 8);
    assert_eq!(
        lamp.to_text().lines().next().unwrap(),
        "Lamp is TRUE at scan 10: written by Main line 7: Lamp := T1.Q — T1.Q TRUE (since scan 8)"
    );
}

#[test]
fn when_changed_finds_the_changes_around_a_scan() {
    let p = st_project(LATCH);
    let b = build_project(&p);
    let sim = recorded(
        &p,
        &b,
        &[
            (3, "Start", "TRUE"),
            (5, "Start", "FALSE"),
            (9, "Start", "TRUE"),
            (10, "Start", "FALSE"),
        ],
        12,
    );
    assert_eq!(when_changed(&sim, "Start", 7).unwrap(), (Some(5), Some(9)));
    assert_eq!(when_changed(&sim, "Start", 5).unwrap(), (Some(3), Some(9)));
    assert_eq!(when_changed(&sim, "Start", 10).unwrap(), (Some(9), None));
    assert_eq!(when_changed(&sim, "Stop", 10).unwrap(), (None, None));
    assert!(matches!(
        when_changed(&sim, "Start", 13),
        Err(WhyError::Record(RecordError::OutOfRange { .. }))
    ));
    assert!(matches!(when_changed(&sim, "Nope", 3), Err(WhyError::Unknown(_))));
}

#[test]
fn the_instances_of_a_configuration_are_named_by_their_paths() {
    let path = format!("{}/../examples/bottling-two-tasks.st", env!("CARGO_MANIFEST_DIR"));
    let p = st_project(&std::fs::read_to_string(path).unwrap());
    let b = build_project(&p);
    let sim = recorded(&p, &b, &[(3, "Barrier", "TRUE"), (4, "Barrier", "FALSE")], 6);
    let ctx = Context::new(&p, &b);
    let e = explain(&ctx, &sim, "Line.Count", 3).unwrap();
    assert_eq!(e.value, serde_json::json!(1));
    assert_eq!(e.written_by.pou.as_deref(), Some("Counting"));
    assert_eq!(operand(&e, "Line.Count").value, serde_json::json!(0));
    assert_eq!(operand(&e, "Line.Edge.Q").value, Json::Bool(true));
    let bottles = explain(&ctx, &sim, "Bottles", 5).unwrap();
    assert_eq!((bottles.written_by.kind, bottles.written_by.since_scan), (Kind::None, Some(3)));
}

#[test]
fn no_recording_and_scans_outside_it_are_errors() {
    let p = st_project(LATCH);
    let b = build_project(&p);
    let mut sim = b.simulator(None).unwrap();
    sim.run_scans(3);
    let ctx = Context::new(&p, &b);
    assert!(matches!(
        explain(&ctx, &sim, "Motor", 2),
        Err(WhyError::Record(RecordError::NotRecording))
    ));
    sim.set_recording(true).unwrap();
    sim.run_scans(3);
    assert!(
        matches!(
            explain(&ctx, &sim, "Motor", 3),
            Err(WhyError::Record(RecordError::OutOfRange { .. }))
        ),
        "scan 3 is the first state kept: its scan was not"
    );
    assert!(explain(&ctx, &sim, "Motor", 4).is_ok());
    assert!(matches!(
        explain(&ctx, &sim, "Motor", 7),
        Err(WhyError::Record(RecordError::OutOfRange { scan: 7, first: 3, last: 6 }))
    ));
}

#[test]
fn labels_are_the_accessible_names_the_issue_gives() {
    assert_eq!(why_label("Motor", &Value::Bool(true)), "Why is Motor TRUE?");
    assert_eq!(why_label("Stop", &Value::Bool(false)), "Why is Stop FALSE?");
    assert_eq!(why_place_label("P3"), "Why does P3 hold a token?");
    assert_eq!(when_label("Motor"), "When did Motor change?");
}

#[test]
fn a_counter_output_keeps_the_history_of_its_count() {
    let p = st_project(
        "PROGRAM Main
VAR_INPUT Pulse : BOOL; END_VAR
VAR_OUTPUT Full : BOOL; END_VAR
VAR C1 : CTU; END_VAR
C1(CU := Pulse, PV := 3);
Full := C1.Q;
END_PROGRAM",
    );
    let b = build_project(&p);
    // Rising edges on scans 2, 4, 6 and 8: the count reaches 3 on scan 6.
    let script: Vec<(u64, &str, &str)> =
        (2..=9).map(|k| (k, "Pulse", if k % 2 == 0 { "TRUE" } else { "FALSE" })).collect();
    let sim = recorded(&p, &b, &script, 10);
    let ctx = Context::new(&p, &b);
    let q = explain(&ctx, &sim, "C1.Q", 6).unwrap();
    assert_eq!(q.value, Json::Bool(true));
    assert_eq!(operand(&q, "C1.CV").value, serde_json::json!(3));
    assert_eq!(operand(&q, "C1.CU").since_scan, 6);
    let history = &q.block.as_ref().unwrap().history;
    let counts: Vec<(u64, Json)> =
        history.iter().filter(|c| c.name == "C1.CV").map(|c| (c.scan, c.value.clone())).collect();
    assert_eq!(
        counts,
        [(2, serde_json::json!(1)), (4, serde_json::json!(2)), (6, serde_json::json!(3))]
    );
    let edges = history.iter().filter(|c| c.name == "C1.CU").count();
    assert_eq!(edges, HISTORY, "the last four changes of CU up to scan 6: 3, 4, 5, 6");
}
