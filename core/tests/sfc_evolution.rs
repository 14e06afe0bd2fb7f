//! How an SFC evolves, scan by scan (docs/sfc.md, "Evolution rules"): the first scan,
//! `S.X` and `S.T`, OR and AND divergence/convergence, priorities, self-loops, function
//! block instances, breakpoints on steps, and cold/warm restarts. Cycle 10 ms; expected
//! values come from the rules, by hand.

mod sfc_common;
use plc_core::sim::ScanOutcome;
use sfc_common::Run;

#[test]
fn the_first_scan_runs_the_initial_step_and_tests_no_transition() {
    let src = "PROGRAM Main
VAR Entered : INT; END_VAR
INITIAL_STEP A : Hello(P1); END_STEP
TRANSITION FROM A TO B := TRUE; END_TRANSITION
STEP B : END_STEP
ACTION Hello : Entered := Entered + 1; END_ACTION
END_PROGRAM";
    let mut run = Run::new(src, &[]);
    assert!(run.bool("A.X"), "the initial step is active before the first scan");
    run.scan(&[]);
    assert_eq!((run.active(&["A", "B"]), run.int("Entered")), (vec!["A".into()], 1));
    run.scan(&[]);
    assert_eq!((run.active(&["A", "B"]), run.int("Entered")), (vec!["B".into()], 1));
}

const PING_PONG: &str = "PROGRAM Main
VAR_INPUT Go : BOOL; Back : BOOL; END_VAR
VAR SawA : BOOL; END_VAR
INITIAL_STEP A : END_STEP
TRANSITION FROM A TO B := Go; END_TRANSITION
STEP B : Watch(N); END_STEP
TRANSITION FROM B TO A := Back AND B.T >= T#20ms; END_TRANSITION
ACTION Watch : SawA := A.X; END_ACTION
END_PROGRAM";

#[test]
fn step_time_counts_from_zero_and_is_kept_after_the_step_is_left() {
    let mut run = Run::new(PING_PONG, &["Go", "Back"]);
    let mut seen = Vec::new();
    for on in [&[][..], &[], &["Go"], &["Back"], &["Back"], &[], &[]] {
        run.scan(on);
        let a = (run.bool("A.X"), run.ms("A.T"));
        seen.push((a, run.bool("B.X"), run.ms("B.T"), run.bool("SawA")));
    }
    assert_eq!(
        seen,
        [
            ((true, 0), false, 0, false),   // scan 1: first scan
            ((true, 10), false, 0, false),  // scan 2
            ((false, 20), true, 0, false),  // scan 3: A.T grows to 20 ms, A is left (kept)
            ((false, 20), true, 10, false), // scan 4: Back, but B.T = 10 ms < 20 ms
            ((true, 0), false, 20, true),   // scan 5: back to A (A.T restarts); Watch's
            //                                 final scan reads the new A.X = TRUE
            ((true, 10), false, 20, true), // scan 6: B.T kept
            ((true, 20), false, 20, true),
        ]
    );
}

#[test]
fn or_divergence_fires_one_transition_by_priority_then_source_order() {
    let src = "PROGRAM Main
VAR_INPUT GoLeft : BOOL; GoRight : BOOL; GoMiddle : BOOL; Back : BOOL; END_VAR
INITIAL_STEP A : END_STEP
TRANSITION ToMiddle FROM A TO Middle := GoMiddle; END_TRANSITION
TRANSITION ToLeft (PRIORITY := 2) FROM A TO Left := GoLeft; END_TRANSITION
TRANSITION ToRight (PRIORITY := 1) FROM A TO Right := GoRight; END_TRANSITION
STEP Left : END_STEP
STEP Right : END_STEP
STEP Middle : END_STEP
TRANSITION FROM Left TO A := Back; END_TRANSITION
TRANSITION FROM Right TO A := Back; END_TRANSITION
TRANSITION FROM Middle TO A := Back; END_TRANSITION
END_PROGRAM";
    let steps = ["A", "Left", "Right", "Middle"];
    let mut run = Run::new(src, &["GoLeft", "GoRight", "GoMiddle", "Back"]);
    run.scan(&[]);
    run.scan(&["GoLeft", "GoRight", "GoMiddle"]);
    assert_eq!(run.active(&steps), ["Right"], "PRIORITY 1 beats 2 and an unwritten one");
    run.scan(&["Back"]);
    assert_eq!(run.active(&steps), ["A"], "OR convergence back into A");
    run.scan(&["GoLeft", "GoMiddle"]);
    assert_eq!(run.active(&steps), ["Left"], "a written priority beats none");
    run.scan(&["Back"]);
    run.scan(&["GoMiddle"]);
    assert_eq!(run.active(&steps), ["Middle"]);
}

#[test]
fn without_priorities_the_first_written_transition_wins() {
    let src = "PROGRAM Main
INITIAL_STEP A : END_STEP
TRANSITION FROM A TO Second := TRUE; END_TRANSITION
TRANSITION FROM A TO First := TRUE; END_TRANSITION
STEP First : END_STEP
STEP Second : END_STEP
END_PROGRAM";
    let mut run = Run::new(src, &[]);
    run.idle(2);
    assert_eq!(run.active(&["A", "First", "Second"]), ["Second"]);
}

const PARALLEL: &str = "PROGRAM Main
VAR_INPUT Go : BOOL; DoneA : BOOL; DoneB : BOOL; Back : BOOL; END_VAR
INITIAL_STEP Start : END_STEP
TRANSITION FROM Start TO (FillA, FillB) := Go; END_TRANSITION
STEP FillA : END_STEP
TRANSITION FROM FillA TO WaitA := DoneA; END_TRANSITION
STEP WaitA : END_STEP
STEP FillB : END_STEP
TRANSITION FROM FillB TO WaitB := DoneB; END_TRANSITION
STEP WaitB : END_STEP
TRANSITION FROM (WaitA, WaitB) TO Mix := TRUE; END_TRANSITION
STEP Mix : END_STEP
TRANSITION FROM Mix TO Start := Back; END_TRANSITION
END_PROGRAM";

const PARALLEL_STEPS: [&str; 6] = ["Start", "FillA", "WaitA", "FillB", "WaitB", "Mix"];

#[test]
fn and_divergence_starts_both_branches_and_the_convergence_waits_for_both() {
    let mut run = Run::new(PARALLEL, &["Go", "DoneA", "DoneB", "Back"]);
    run.scan(&[]);
    run.scan(&["Go"]);
    assert_eq!(run.active(&PARALLEL_STEPS), ["FillA", "FillB"]);
    run.scan(&["DoneA"]);
    assert_eq!(run.active(&PARALLEL_STEPS), ["WaitA", "FillB"]);
    run.scan(&[]);
    assert_eq!(run.active(&PARALLEL_STEPS), ["WaitA", "FillB"], "the join waits for B");
    run.scan(&["DoneB"]);
    assert_eq!(
        run.active(&PARALLEL_STEPS),
        ["WaitA", "WaitB"],
        "the join is tested on the steps active at the start of the scan"
    );
    run.scan(&[]);
    assert_eq!(run.active(&PARALLEL_STEPS), ["Mix"]);
    run.scan(&["Back"]);
    assert_eq!(run.active(&PARALLEL_STEPS), ["Start"]);
}

#[test]
fn transitions_in_parallel_branches_fire_in_the_same_scan() {
    let mut run = Run::new(PARALLEL, &["Go", "DoneA", "DoneB", "Back"]);
    run.scan(&[]);
    run.scan(&["Go"]);
    run.scan(&["DoneA", "DoneB"]);
    assert_eq!(run.active(&PARALLEL_STEPS), ["WaitA", "WaitB"]);
}

#[test]
fn a_step_claimed_by_a_firing_transition_is_not_left_twice() {
    // P is left by the join (priority 0) and by ToS (no priority); only the join fires.
    let src = "PROGRAM Main
INITIAL_STEP Init : END_STEP
TRANSITION FROM Init TO (P, Q) := TRUE; END_TRANSITION
STEP P : END_STEP
STEP Q : END_STEP
TRANSITION ToS FROM P TO S := TRUE; END_TRANSITION
TRANSITION Join (PRIORITY := 0) FROM (P, Q) TO R := TRUE; END_TRANSITION
STEP R : END_STEP
STEP S : END_STEP
END_PROGRAM";
    let mut run = Run::new(src, &[]);
    run.idle(3);
    assert_eq!(run.active(&["Init", "P", "Q", "R", "S"]), ["R"]);
}

#[test]
fn a_self_loop_restarts_the_step_time_but_keeps_its_actions_going() {
    let src = "PROGRAM Main
VAR Runs : INT; Finals : INT; END_VAR
INITIAL_STEP A : Act(N); END_STEP
TRANSITION FROM A TO A := A.T >= T#20ms; END_TRANSITION
ACTION Act : Runs := Runs + 1; IF NOT Act.Q THEN Finals := Finals + 1; END_IF; END_ACTION
END_PROGRAM";
    let mut run = Run::new(src, &[]);
    let mut times = Vec::new();
    for _ in 0..6 {
        run.scan(&[]);
        times.push(run.ms("A.T"));
    }
    assert_eq!(times, [0, 10, 0, 10, 0, 10], "A.T reaches 20 ms in scans 3 and 5: re-entered");
    assert_eq!((run.int("Runs"), run.int("Finals")), (6, 0), "A.X never fell");
}

#[test]
fn a_transition_body_assigns_the_transition_name() {
    let src = "PROGRAM Main
VAR Count : INT; END_VAR
INITIAL_STEP A : Tick(N); END_STEP
TRANSITION Enough FROM A TO B :
    Enough := Count >= 3;
END_TRANSITION
STEP B : END_STEP
ACTION Tick : Count := Count + 1; END_ACTION
END_PROGRAM";
    let mut run = Run::new(src, &[]);
    run.idle(3);
    assert!(run.bool("A.X"), "scan 3 tests Count = 2");
    run.scan(&[]);
    assert!(run.bool("B.X"), "scan 4 tests Count = 3");
    assert_eq!(run.int("Count"), 4, "scan 4 runs Tick's final scan");
}

const SEQUENCE_FB: &str = "FUNCTION_BLOCK Sequence
VAR_INPUT Go : BOOL; END_VAR
INITIAL_STEP A : END_STEP
TRANSITION FROM A TO B := Go; END_TRANSITION
STEP B : END_STEP
TRANSITION FROM B TO C := B.T >= T#50ms; END_TRANSITION
STEP C : END_STEP
END_FUNCTION_BLOCK
";

#[test]
fn each_function_block_instance_has_its_own_chart() {
    let src = format!(
        "{SEQUENCE_FB}PROGRAM Main
VAR_INPUT GoOne : BOOL; END_VAR
VAR One : Sequence; Two : Sequence; END_VAR
One(Go := GoOne);
Two(Go := FALSE);
END_PROGRAM"
    );
    let mut run = Run::new(&src, &["GoOne"]);
    run.scan(&[]);
    run.scan(&["GoOne"]);
    assert_eq!((run.bool("One.B.X"), run.bool("Two.A.X")), (true, true));
}

#[test]
fn a_breakpoint_can_wait_for_a_step() {
    let mut run = Run::new(PING_PONG, &["Go", "Back"]);
    run.sim.add_breakpoint("B.X AND B.T >= T#10ms").unwrap();
    run.sim.hold("Go", "TRUE").unwrap();
    let outcome = run.sim.run_scans(10);
    assert!(matches!(outcome, ScanOutcome::Breakpoint(_)), "{outcome:?}");
    assert_eq!(run.sim.scan_count(), 3, "B active from scan 2, B.T = 10 ms in scan 3");
}

#[test]
fn warm_and_cold_restarts_start_a_program_chart_again() {
    let mut run = Run::new(PING_PONG, &["Go", "Back"]);
    run.scan(&[]);
    run.scan(&["Go"]);
    assert!(run.bool("B.X"));
    run.sim.warm_restart();
    assert_eq!(run.active(&["A", "B"]), ["A"], "step flags are not RETAIN");
    run.scan(&[]);
    run.scan(&["Go"]);
    run.sim.cold_restart();
    assert_eq!((run.active(&["A", "B"]), run.ms("B.T")), (vec!["A".into()], 0));
}

#[test]
fn a_retained_function_block_instance_resumes_its_chart_after_a_warm_restart() {
    let src = format!(
        "{SEQUENCE_FB}PROGRAM Main
VAR_INPUT Go : BOOL; END_VAR
VAR RETAIN Kept : Sequence; END_VAR
VAR Lost : Sequence; END_VAR
Kept(Go := Go);
Lost(Go := Go);
END_PROGRAM"
    );
    let mut run = Run::new(&src, &["Go"]);
    run.scan(&[]);
    run.scan(&["Go"]); // B active, B.T = 0 ms (virtual time 10 ms)
    run.idle(2); // B.T = 20 ms
    assert_eq!((run.bool("Kept.B.X"), run.ms("Kept.B.T")), (true, 20));
    run.sim.warm_restart(); // the clock goes back to 0
    assert_eq!((run.bool("Kept.B.X"), run.bool("Lost.A.X")), (true, true));
    run.scan(&[]);
    assert_eq!(run.ms("Kept.B.T"), 20, "no time passes across the restart");
    run.idle(2);
    assert_eq!((run.ms("Kept.B.T"), run.bool("Kept.B.X")), (40, true));
    run.scan(&[]);
    assert!(run.bool("Kept.C.X"), "B.T reached 50 ms");
    run.sim.cold_restart();
    assert!(run.bool("Kept.A.X"), "a cold restart resets RETAIN too");
}
