#![allow(clippy::unwrap_used)]

use super::*;
use crate::vm::Value;

fn sim(source: &str) -> Simulator {
    let analysis = semantic::analyze(source);
    let errors: Vec<_> = analysis.diagnostics.iter().filter(|d| d.is_error()).collect();
    assert!(errors.is_empty(), "{errors:?}");
    let program = analysis.program.unwrap();
    let main = program.programs().find(|&p| !program.pou(p).library).unwrap();
    Simulator::new(program, main).unwrap()
}

fn int(s: &Simulator, path: &str) -> i128 {
    match s.read(path).unwrap() {
        Value::Int(v, _) => v,
        other => panic!("{path} is {other:?}"),
    }
}

fn boolean(s: &Simulator, path: &str) -> bool {
    match s.read(path).unwrap() {
        Value::Bool(b) => b,
        other => panic!("{path} is {other:?}"),
    }
}

const LATCH: &str = "
PROGRAM Latch
VAR_INPUT Start : BOOL; Stop : BOOL; END_VAR
VAR_OUTPUT Motor : BOOL; END_VAR
VAR RETAIN Count : INT; END_VAR
VAR n : INT; END_VAR
Motor := (Start OR Motor) AND NOT Stop;
Count := Count + 1;
n := n + 1;
END_PROGRAM";

#[test]
fn held_inputs_drive_a_latch_scan_by_scan() {
    let mut s = sim(LATCH);
    assert_eq!(s.scan(), ScanOutcome::Completed);
    assert!(!boolean(&s, "Motor"));
    s.hold("Start", "TRUE").unwrap();
    s.scan();
    assert!(boolean(&s, "motor"), "names are case-insensitive");
    s.hold("Start", "FALSE").unwrap();
    s.scan();
    assert!(boolean(&s, "Motor"), "the latch holds");
    s.hold("Stop", "TRUE").unwrap();
    s.scan();
    assert!(!boolean(&s, "Motor"));
}

#[test]
fn warm_restart_keeps_retain_and_cold_restart_does_not() {
    let mut s = sim(LATCH);
    s.run_scans(5);
    assert_eq!((int(&s, "Count"), int(&s, "n")), (5, 5));
    s.warm_restart();
    assert_eq!((int(&s, "Count"), int(&s, "n")), (5, 0));
    assert_eq!((s.scan_count(), s.time_ns()), (0, 0));
    s.cold_restart();
    assert_eq!(int(&s, "Count"), 0);
}

#[test]
fn forcing_wins_over_the_program() {
    let mut s = sim(LATCH);
    s.force("Motor", "TRUE").unwrap();
    s.hold("Stop", "TRUE").unwrap();
    s.scan();
    assert!(boolean(&s, "Motor"));
    s.unforce("Motor");
    s.scan();
    assert!(!boolean(&s, "Motor"));
}

#[test]
fn a_breakpoint_pauses_on_the_scan_its_condition_becomes_true() {
    let mut s = sim(LATCH);
    let bp = s.add_breakpoint("n >= 3 AND NOT Motor").unwrap();
    assert_eq!(s.run_scans(10), ScanOutcome::Breakpoint(bp));
    assert_eq!(s.scan_count(), 3);
    assert_eq!(s.state(), &SimState::Paused(bp));
    // Still true: no new pause (it pauses when the condition becomes true).
    assert_eq!(s.run_scans(4), ScanOutcome::Completed);
    assert!(matches!(s.add_breakpoint("n +"), Err(SimError::BadCondition(_))));
    assert!(matches!(s.add_breakpoint("n := 1"), Err(SimError::BadCondition(_))));
}

#[test]
fn a_fault_stops_the_plc_until_a_restart() {
    let src = "PROGRAM P VAR d : INT; x : INT := 10; k : INT; END_VAR
k := k + 1;
IF k = 3 THEN d := x / (k - 3); END_IF;
END_PROGRAM";
    let mut s = sim(src);
    let ScanOutcome::Fault(info) = s.run_scans(10) else { panic!("no fault") };
    assert_eq!(info.fault, Fault::DivisionByZero);
    assert_eq!(info.scan, 3);
    assert_eq!(&src[info.span.start as usize..info.span.start as usize + 6], "d := x");
    assert_eq!(s.scan_count(), 2);
    assert!(matches!(s.scan(), ScanOutcome::Fault(_)));
    assert_eq!(int(&s, "k"), 3, "writes before the fault stay");
    s.cold_restart();
    assert_eq!(s.scan(), ScanOutcome::Completed);
}

#[test]
fn the_watchdog_stops_an_endless_loop() {
    let mut s =
        sim("PROGRAM P VAR i : INT; END_VAR WHILE TRUE DO i := i + 1; END_WHILE; END_PROGRAM");
    s.set_watchdog(100_000);
    let ScanOutcome::Fault(info) = s.scan() else { panic!("no fault") };
    assert_eq!(info.fault, Fault::Watchdog { budget: 100_000 });
}

#[test]
fn timers_run_on_the_virtual_clock_in_single_scans() {
    let mut s = sim("PROGRAM P VAR t : TON; END_VAR t(IN := TRUE, PT := T#50ms); END_PROGRAM");
    s.set_cycle_ns(10_000_000);
    s.scan();
    assert_eq!(s.read("t.ET").unwrap(), Value::Time(0));
    s.run_scans(4);
    assert!(!boolean(&s, "t.Q"));
    assert_eq!(s.read("t.ET").unwrap(), Value::Time(40_000_000));
    s.scan();
    assert!(boolean(&s, "t.Q"));
    assert_eq!(s.run_until(1_000_000_000), ScanOutcome::Completed);
    assert_eq!(s.time_ns(), 1_000_000_000);
    assert_eq!(s.read("t.ET").unwrap(), Value::Time(50_000_000));
}

#[test]
fn first_scan_and_square_waves() {
    let src =
        "PROGRAM P VAR RETAIN first : INT; END_VAR VAR sec : INT; on : BOOL; off : BOOL; END_VAR
IF FST_SCN THEN first := first + 1; END_IF;
IF T_100MS THEN sec := sec + 1; END_IF;
on := ALW_ON; off := ALW_OFF;
END_PROGRAM";
    let mut s = sim(src);
    s.run_scans(100);
    assert_eq!(int(&s, "first"), 1);
    // 100 scans of 10 ms = 1 s = ten periods of 100 ms, TRUE half of each.
    assert_eq!(int(&s, "sec"), 50);
    assert!(boolean(&s, "on") && !boolean(&s, "off"));
    s.warm_restart();
    s.scan();
    assert_eq!(int(&s, "first"), 2);
}

#[test]
fn the_trace_keeps_the_last_samples() {
    let mut s = sim(LATCH);
    s.set_trace(&["n", "Motor"], 3).unwrap();
    s.run_scans(5);
    let scans: Vec<u64> = s.trace().samples().map(|t| t.scan).collect();
    assert_eq!(scans, vec![3, 4, 5]);
    assert!(s.set_trace(&["nope"], 3).is_err());
}

#[test]
fn bad_values_are_errors_not_panics() {
    let mut s = sim(LATCH);
    assert!(matches!(s.write("Count", "'text'"), Err(SimError::BadValue { .. })));
    assert!(matches!(s.write("Count", "70000"), Err(SimError::BadValue { .. })));
    assert!(matches!(s.write("Nope", "1"), Err(SimError::UnknownVariable(_))));
    s.write("Count", "-5").unwrap();
    assert_eq!(int(&s, "Count"), -5);
}

#[test]
fn the_active_case_branch_is_reported() {
    let src = "PROGRAM P VAR p : INT := 1; x : INT; END_VAR
CASE p OF
    1: x := 10;
       p := 2;
    2: x := 20;
END_CASE;
END_PROGRAM";
    let mut s = sim(src);
    assert!(s.active_case_branches().is_empty());
    s.scan();
    let first: Vec<&str> = s
        .active_case_branches()
        .iter()
        .map(|sp| &src[sp.start as usize..sp.end as usize])
        .collect();
    assert_eq!(first, ["x := 10;"]);
    s.scan();
    let second: Vec<&str> = s
        .active_case_branches()
        .iter()
        .map(|sp| &src[sp.start as usize..sp.end as usize])
        .collect();
    assert_eq!(second, ["x := 20;"]);
    s.write("p", "7").unwrap();
    s.scan();
    assert!(s.active_case_branches().is_empty(), "no label matched");
}

/// How many loop iterations ran before the watchdog stopped the scan, with `budget`.
fn iterations_before_watchdog(source: &str, budget: u64) -> i128 {
    let mut s = sim(source);
    s.set_watchdog(budget);
    let outcome = s.scan();
    assert!(
        matches!(&outcome, ScanOutcome::Fault(f) if matches!(f.fault, crate::vm::Fault::Watchdog { .. })),
        "{outcome:?}"
    );
    int(&s, "n")
}

#[test]
fn the_watchdog_charges_array_copies_by_their_size() {
    // Issue 11: a loop of whole-array copies ran for hours, each copy counted as one
    // instruction. Now a copy of 4,096 cells costs 512 units: about 194 copies fit a budget
    // of 100,000 (counted by instructions, 33,000 did).
    let src = "PROGRAM Main VAR a, b : ARRAY[1..4096] OF LINT; n : DINT; END_VAR
               WHILE TRUE DO a := b; n := n + 1; END_WHILE; END_PROGRAM";
    let n = iterations_before_watchdog(src, 100_000);
    assert!((150..=200).contains(&n), "{n} copies");
}

#[test]
fn the_watchdog_charges_string_functions_by_their_length() {
    // Issue 11: FIND on long strings was one instruction however long the strings.
    let src = "PROGRAM Main VAR s, t : STRING[4000]; k, n : DINT; END_VAR
               WHILE LEN(s) < 3990 DO s := CONCAT(s, 'aaaaaaaaaa'); END_WHILE;
               t := LEFT(s, 1990); t := CONCAT(t, 'b'); s := CONCAT(s, 'b');
               n := 0;
               WHILE TRUE DO k := FIND(s, t); n := n + 1; END_WHILE; END_PROGRAM";
    let n = iterations_before_watchdog(src, 1_000_000);
    // FIND reads about 6,000 bytes: 750 units, after the CONCAT loop has used about a
    // fifth of the budget (counted by instructions, about 250,000 searches fit).
    assert!((600..=1_100).contains(&n), "{n} searches");
}

#[test]
fn the_trace_stays_within_its_memory_budget() {
    // Issue 11: tracing a whole 4M-element array kept 20,000 copies of it.
    let mut s = sim("PROGRAM Main VAR big : ARRAY[1..4000000] OF LINT; s : STRING[60000]; \
         n : INT; END_VAR n := n + 1; big[1] := n; END_PROGRAM");
    let e = s.set_trace(&["big"], 20_000).unwrap_err();
    assert!(matches!(e, SimError::NotTraceable(_)), "{e}");
    assert!(e.to_string().contains("big[1]"), "{e}");
    // Elements are fine; a long string gets fewer samples than asked, within the budget.
    s.set_trace(&["big[1]", "n"], 20_000).unwrap();
    assert_eq!(s.trace().capacity(), 20_000);
    s.set_trace(&["s", "n"], 20_000).unwrap();
    let per_sample = s.trace_cost("s").unwrap() + s.trace_cost("n").unwrap();
    assert!(s.trace().capacity() * per_sample <= crate::limits::TRACE_BUDGET_BYTES);
    assert!(s.trace().capacity() >= 100, "still a useful window");
    s.run_scans(3);
    assert_eq!(s.trace().len(), 3);
}

#[test]
fn a_watch_is_evaluated_after_each_run_of_scans() {
    let src = "
FUNCTION Bump : INT
VAR_INPUT x : INT; END_VAR
VAR_EXTERNAL g : INT; END_VAR
g := g + 1;
Bump := x;
END_FUNCTION
PROGRAM P
VAR_GLOBAL g : INT; END_VAR
VAR n : INT; d : INT; s : STRING; END_VAR
n := n + 2;
END_PROGRAM";
    let mut s = sim(src);
    s.add_watch("ADD(n, 5)").unwrap();
    s.add_watch("DIV(10, d)").unwrap();
    assert_eq!(s.watch("ADD(n, 5)"), Some(&Value::Int(5, semantic::Elem::Int)));
    s.run_scans(3);
    assert_eq!(s.watch("ADD(n, 5)"), Some(&Value::Int(11, semantic::Elem::Int)));
    // A division by zero has no value and does not fault the PLC.
    assert_eq!(s.watch("DIV(10, d)"), None);
    assert_eq!(s.state(), &SimState::Ready);
    s.cold_restart();
    assert_eq!(s.watch("ADD(n, 5)"), Some(&Value::Int(5, semantic::Elem::Int)));
    // Evaluating twice must not change the program: no FUNCTION of the program, and
    // only single elementary values.
    assert!(matches!(s.add_watch("Bump(n)"), Err(SimError::BadCondition(_))));
    assert!(matches!(s.add_watch("s"), Err(SimError::BadCondition(_))));
    assert!(matches!(s.add_watch("n := 1"), Err(SimError::BadCondition(_))));
    assert_eq!(s.watch("Bump(n)"), None);
}

#[test]
fn instances_of_a_function_block_are_found_nested_too() {
    let src = "
FUNCTION_BLOCK Mixer
VAR t : TON; END_VAR
END_FUNCTION_BLOCK
FUNCTION_BLOCK Line
VAR m : Mixer; END_VAR
END_FUNCTION_BLOCK
PROGRAM P
VAR a : Mixer; l : Line; b : Mixer; END_VAR
END_PROGRAM";
    let s = sim(src);
    assert_eq!(s.instances_of("mixer"), ["a", "l.m", "b"]);
    assert_eq!(s.instances_of("TON"), ["a.t", "l.m.t", "b.t"]);
    assert!(s.instances_of("Nope").is_empty());
}

/// A controller and a tank plant: the controller fills while the level is low; the plant
/// integrates the level from the valve over the scan's time and reports it back.
const TANK: &str = "
PROGRAM Control
VAR_INPUT Level : INT; END_VAR
VAR_OUTPUT Fill : BOOL; END_VAR
IF Level < 40 THEN Fill := TRUE; ELSIF Level > 60 THEN Fill := FALSE; END_IF;
END_PROGRAM
PROGRAM Tank
VAR_INPUT Fill : BOOL; END_VAR
VAR_OUTPUT Level : INT; END_VAR
VAR Scans : INT; END_VAR
IF Fill THEN Level := Level + 5; ELSIF Level > 0 THEN Level := Level - 1; END_IF;
Scans := Scans + 1;
END_PROGRAM";

fn tank_sim() -> Simulator {
    let analysis = semantic::analyze(TANK);
    assert!(!crate::diagnostics::has_errors(&analysis.diagnostics), "{:?}", analysis.diagnostics);
    let program = analysis.program.unwrap();
    let find = |n: &str| program.programs().find(|&p| program.pou(p).name == n).unwrap();
    let (main, plant) = (find("Control"), find("Tank"));
    Simulator::with_plant(program, main, plant).unwrap()
}

#[test]
fn a_plant_runs_after_the_controller_on_every_scan() {
    let mut s = tank_sim();
    assert_eq!(s.plant_name(), Some("Tank"));
    // The plant writes the controller's Level (a sensor), not its Fill.
    assert!(s.plant_drives("level"));
    assert!(!s.plant_drives("Fill"));
    // Scan 1: the controller sees Level 0 and fills; the plant then rises to 5, which
    // the controller reads on scan 2.
    s.scan();
    assert!(boolean(&s, "Fill"));
    assert_eq!(int(&s, "Tank.Level"), 5);
    assert_eq!(int(&s, "Level"), 5);
    // Filling stops above 60 (at 65) and the level falls back to 39 before it starts again.
    let mut levels = Vec::new();
    for _ in 0..60 {
        s.scan();
        levels.push(int(&s, "Level"));
    }
    assert_eq!(levels.iter().copied().max(), Some(65));
    let peak = levels.iter().position(|&l| l == 65).unwrap();
    assert_eq!(levels[peak..].iter().copied().min(), Some(39));
    assert_eq!(levels[peak + 1], 64, "the controller stops filling once it reads 65");
    assert_eq!(int(&s, "Tank.Scans"), 61);
    // The plant's variables are in the JSON report under its name.
    let vars = s.vars_json();
    assert_eq!(vars["Tank"]["Scans"], 61);
    // A cold restart starts both over.
    s.cold_restart();
    assert_eq!(int(&s, "Tank.Level"), 0);
}

#[test]
fn a_plant_whose_links_do_not_match_is_refused() {
    let src = TANK.replace(
        "VAR_OUTPUT Level : INT; END_VAR\nVAR Scans",
        "VAR_OUTPUT Level : REAL; END_VAR\nVAR Scans",
    );
    let analysis = semantic::analyze(&src.replace(
        "Level := Level + 5; ELSIF Level > 0 THEN Level := Level - 1;",
        "Level := Level + 5.0;",
    ));
    let program = analysis.program.unwrap();
    let find = |n: &str| program.programs().find(|&p| program.pou(p).name == n).unwrap();
    let (main, plant) = (find("Control"), find("Tank"));
    let err = Simulator::with_plant(program.clone(), main, plant).unwrap_err();
    assert!(err.to_string().contains("Level of the plant Tank"), "{err}");
    assert!(Simulator::with_plant(program, main, main).is_err());
}

const TWO_TASKS: &str = "
PROGRAM Count
VAR_INPUT Step : INT := 1; END_VAR
VAR_OUTPUT n : INT; END_VAR
VAR_EXTERNAL Total : INT; END_VAR
n := n + Step; Total := Total + 1;
END_PROGRAM
CONFIGURATION Cell
  VAR_GLOBAL Total : INT; Two : INT := 2; Go : BOOL; END_VAR
  TASK Fast (INTERVAL := T#10ms, PRIORITY := 1);
  TASK Slow (INTERVAL := T#40ms, PRIORITY := 0);
  TASK OnGo (SINGLE := Go);
  PROGRAM A WITH Fast : Count;
  PROGRAM B WITH Slow : Count (Step := Two);
  PROGRAM E WITH OnGo : Count;
END_CONFIGURATION
";

fn config_sim(source: &str) -> Simulator {
    let analysis = semantic::analyze(source);
    let errors: Vec<_> = analysis.diagnostics.iter().filter(|d| d.is_error()).collect();
    assert!(errors.is_empty(), "{errors:?}");
    let program = analysis.program.unwrap();
    let main = crate::build::find_program(&program, None).unwrap();
    Simulator::new(program, main).unwrap()
}

#[test]
fn a_configuration_runs_each_instance_under_its_task_and_restarts_its_clock() {
    let mut s = config_sim(TWO_TASKS);
    assert_eq!(s.configuration().map(|c| c.name.as_str()), Some("Cell"));
    s.run_scans(9);
    assert_eq!(
        (s.task_runs("fast"), s.task_runs("SLOW"), s.task_runs("OnGo")),
        (Some(9), Some(3), Some(0))
    );
    assert_eq!((int(&s, "A.n"), int(&s, "B.n")), (9, 6));
    s.write("Go", "TRUE").unwrap();
    s.run_scans(3);
    assert_eq!((int(&s, "E.n"), s.task_runs("OnGo")), (1, Some(1)), "one run per rising edge");
    // Inside an instance, a VAR_EXTERNAL is the global.
    assert_eq!(int(&s, "A.Total"), int(&s, "Total"));
    // 12 scans: Fast on each, Slow at 0, 40 and 80 ms, OnGo once.
    assert_eq!(int(&s, "Total"), 12 + 3 + 1);
    s.cold_restart();
    s.scan();
    assert_eq!((s.task_runs("Fast"), s.task_runs("Slow")), (Some(1), Some(1)));
    assert_eq!(int(&s, "B.n"), 2);
    assert_eq!(s.task_runs("Nope"), None);
}

#[test]
fn the_panels_list_each_instances_own_variables_by_path() {
    let s = config_sim(TWO_TASKS);
    let names: Vec<String> = s.listed_vars().into_iter().map(|(n, _)| n).collect();
    // B.Step is driven by the global Two, and Total is listed once, as the global.
    assert_eq!(names, ["A.Step", "A.n", "B.n", "E.Step", "E.n", "Total", "Two", "Go"]);
    let json = s.vars_json();
    assert!(json["A"].is_object() && json["B"].is_object() && json["E"].is_object());
    assert!(json["A"].get("Total").is_none(), "{json:?}");
    // Without a configuration the panels list the main program's variables as they are.
    let plain = sim(LATCH);
    assert!(plain.configuration().is_none());
    assert_eq!(plain.listed_vars().len(), plain.executable().main_vars().len());
}

#[test]
fn a_value_written_from_outside_stays_inside_its_subrange() {
    let mut s = sim("PROGRAM P VAR_INPUT Level : INT(0..100); END_VAR VAR a : ARRAY[1..2] OF INT(1..5); n : INT; END_VAR n := Level; END_PROGRAM");
    let err = s.write("Level", "150").unwrap_err();
    assert!(err.to_string().contains("150 is outside its subrange 0..100"), "{err}");
    assert!(s.hold("level", "-1").is_err());
    s.write("Level", "100").unwrap();
    assert!(s.write("a[2]", "6").is_err(), "an array's element subrange");
    s.write("a[2]", "5").unwrap();
    s.write("n", "-7").unwrap();
}

#[test]
fn a_var_external_of_the_main_program_reads_and_writes_its_global() {
    let mut s = sim("VAR_GLOBAL Total : INT; END_VAR PROGRAM P VAR_EXTERNAL Total : INT; END_VAR Total := Total + 1; END_PROGRAM");
    s.run_scans(3);
    assert_eq!(int(&s, "Total"), 3);
    assert_eq!(s.vars_json()["Total"], serde_json::json!(3));
    s.write("Total", "10").unwrap();
    s.scan();
    assert_eq!(int(&s, "Total"), 11);
}

/// The program's own memory now (without the scratch cells of conditions).
fn state(s: &Simulator) -> Vec<u64> {
    s.machine.memory().cells[..s.state_cells].to_vec()
}

#[test]
fn a_recorded_scan_is_rebuilt_cell_for_cell() {
    let mut s = sim(LATCH);
    s.set_recording(true).unwrap();
    let mut live = vec![state(&s)];
    for k in 1..=100u64 {
        if k % 7 == 0 {
            s.hold("Start", if k % 2 == 0 { "TRUE" } else { "FALSE" }).unwrap();
        }
        if k % 11 == 0 {
            s.write("n", "5").unwrap();
        }
        if k == 50 {
            s.force("Stop", "TRUE").unwrap();
        }
        if k == 60 {
            s.unforce("Stop");
            s.set_cycle_ns(3_000_000);
        }
        s.scan();
        live.push(state(&s));
    }
    assert_eq!(s.recorded_range(), Some((0, 100)));
    for (k, cells) in live.iter().enumerate() {
        let v = s.view_at(k as u64).unwrap();
        assert_eq!(&v.memory().cells[..s.state_cells], &cells[..], "scan {k}");
        assert_eq!(v.scan(), k as u64);
    }
    let v = s.view_at(61).unwrap();
    assert_eq!(v.time_ns() - s.view_at(60).unwrap().time_ns(), 3_000_000);
    assert!(matches!(
        s.view_at(101),
        Err(RecordError::OutOfRange { scan: 101, first: 0, last: 100 })
    ));
}

#[test]
fn rewinding_starts_a_new_future_from_a_recorded_scan() {
    let mut s = sim(LATCH);
    s.set_recording(true).unwrap();
    s.set_trace(&["Motor", "n"], 1000).unwrap();
    s.run_scans(10);
    s.hold("Start", "TRUE").unwrap();
    s.run_scans(10);
    s.hold("Start", "FALSE").unwrap();
    s.run_scans(10);
    let at_15 = s.view_at(15).unwrap();
    s.rewind_to(15).unwrap();
    assert_eq!(s.scan_count(), 15);
    assert_eq!(state(&s), at_15.memory().cells[..s.state_cells].to_vec());
    assert_eq!(s.recorded_range(), Some((0, 15)));
    assert_eq!(s.trace().len(), 15);
    assert!(boolean(&s, "Start"), "the input as it was held at scan 15");
    // A new future: Stop pressed instead.
    s.hold("Stop", "TRUE").unwrap();
    s.run_scans(5);
    assert!(!boolean(&s, "Motor"));
    assert_eq!(s.recorded_range(), Some((0, 20)));
    assert_eq!(s.view_at(15).unwrap().read("Motor").unwrap(), Value::Bool(true));
    assert_eq!(s.view_at(17).unwrap().read("Motor").unwrap(), Value::Bool(false));
}

#[test]
fn a_large_image_keeps_a_shorter_history_within_the_budget() {
    // 200,000 cells: a snapshot is 1.6 MB, so the budget affords fewer than the hour.
    let mut s = sim("PROGRAM Big
VAR a : ARRAY[1..200000] OF LINT; i : DINT; END_VAR
i := i MOD 200000 + 1;
a[i] := a[i] + 1;
END_PROGRAM");
    s.set_recording(true).unwrap();
    let r = s.recording().unwrap();
    assert_eq!(r.interval, limits::RECORD_MAX_INTERVAL);
    assert!(r.capacity < limits::RECORD_SCANS && r.capacity >= 10 * r.interval, "{r:?}");
    s.run_scans(r.capacity + 3 * r.interval);
    let r = s.recording().unwrap();
    assert!(r.bytes <= limits::RECORD_BUDGET_BYTES + 2 * 1024 * 1024, "{r:?}");
    assert!(r.first > 0, "the oldest history was dropped: {r:?}");
    assert!(r.last - r.first >= r.capacity, "at least the capacity is kept: {r:?}");
    // The oldest scan kept is still rebuilt exactly.
    let first = s.view_at(r.first).unwrap();
    assert_eq!(
        first.read("i").unwrap(),
        Value::Int(i128::from(r.first as i64 % 200_000), crate::semantic::Elem::DInt)
    );
    assert!(matches!(s.view_at(r.first - 1), Err(RecordError::OutOfRange { .. })));
}

#[test]
fn a_small_image_keeps_the_hour() {
    let mut s = sim(LATCH);
    s.set_recording(true).unwrap();
    let r = s.recording().unwrap();
    assert_eq!((r.interval, r.capacity), (limits::RECORD_MIN_INTERVAL, limits::RECORD_SCANS));
}

#[test]
fn recording_off_drops_the_history() {
    let mut s = sim(LATCH);
    s.set_recording(true).unwrap();
    s.run_scans(20);
    s.set_recording(false).unwrap();
    assert_eq!(s.recorded_range(), None);
    assert!(matches!(s.view_at(3), Err(RecordError::NotRecording)));
    s.set_recording(true).unwrap();
    assert_eq!(s.recorded_range(), Some((20, 20)), "a new history starts at the present");
    s.cold_restart();
    assert_eq!(s.recorded_range(), Some((0, 0)), "a restart starts a new history");
}

#[test]
fn a_change_from_outside_is_recorded_in_24_bytes() {
    assert_eq!(std::mem::size_of::<(u64, record::Control)>(), 24);
}

#[test]
fn reference_initial_values_come_back_on_a_restart_as_other_initial_values() {
    // Scan 1 adds 1 and 10 to `a` through r and k, then points both at `b`.
    let src = "PROGRAM P
VAR r : REF_TO INT := REF(a); a, b : INT; END_VAR
VAR RETAIN k : REF_TO INT := REF(a); END_VAR
r^ := r^ + 1;
k^ := k^ + 10;
r := REF(b);
k := REF(b);
END_PROGRAM";
    let mut s = sim(src);
    s.run_scans(2);
    assert_eq!((int(&s, "a"), int(&s, "b")), (11, 11));
    // Warm: r is REF(a) again, the RETAIN k keeps pointing at b.
    s.warm_restart();
    s.scan();
    assert_eq!((int(&s, "a"), int(&s, "b")), (1, 10));
    // Cold: both are REF(a) again.
    s.cold_restart();
    s.scan();
    assert_eq!((int(&s, "a"), int(&s, "b")), (11, 0));
}

#[test]
fn var_config_initial_values_come_back_on_a_restart_as_other_initial_values() {
    let src = "FUNCTION_BLOCK Valve
VAR_INPUT Setpoint : INT := 10; END_VAR
VAR RETAIN Kept : INT := 1; END_VAR
Setpoint := Setpoint + 1;
Kept := Kept + 1;
END_FUNCTION_BLOCK
PROGRAM Cell VAR V1 : Valve; END_VAR V1(); END_PROGRAM
CONFIGURATION Plant
  PROGRAM Line : Cell;
  VAR_CONFIG
    Line.V1.Setpoint : INT := 50;
    Line.V1.Kept : INT := 7;
  END_VAR
END_CONFIGURATION";
    let mut s = config_sim(src);
    assert_eq!((int(&s, "Line.V1.Setpoint"), int(&s, "Line.V1.Kept")), (50, 7));
    s.run_scans(3);
    assert_eq!((int(&s, "Line.V1.Setpoint"), int(&s, "Line.V1.Kept")), (53, 10));
    s.warm_restart();
    assert_eq!((int(&s, "Line.V1.Setpoint"), int(&s, "Line.V1.Kept")), (50, 10));
    s.cold_restart();
    assert_eq!((int(&s, "Line.V1.Setpoint"), int(&s, "Line.V1.Kept")), (50, 7));
}

/// The locator's plain-name path (no dots, no brackets) finds what the full path parser
/// finds: any case, spaces around, the program's own variable before a global of the same
/// name; a number, an empty path or a name not declared is no variable.
#[test]
fn a_plain_name_is_located_as_the_path_parser_locates_it() {
    let mut s = sim("
VAR_GLOBAL Level : INT := 5; Shared : INT := 7; END_VAR
PROGRAM Main
VAR Level : INT := 1; Word_1 : WORD := 16#8000; END_VAR
Level := Level + 1;
END_PROGRAM");
    s.scan();
    assert_eq!(int(&s, "level"), 2, "the program's Level, not the global");
    assert_eq!(int(&s, "  LEVEL "), 2);
    assert_eq!(int(&s, "shared"), 7);
    assert!(boolean(&s, "word_1.15"), "a bit of a plain name still goes through the parser");
    for missing in ["", "   ", "15", "Nope", "Level2", "Lev el"] {
        assert!(
            matches!(s.read(missing), Err(SimError::UnknownVariable(_))),
            "{missing:?} is no variable"
        );
    }
    s.hold_value("LEVEL", Value::Int(40, semantic::Elem::Int)).unwrap();
    s.scan();
    assert_eq!(int(&s, "Level"), 41);
}
