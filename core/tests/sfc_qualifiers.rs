//! Every action qualifier, scan by scan, with timing (docs/sfc.md, "Action qualifiers").
//!
//! The chart: `Idle` (initial) → `Work` on `Go` → `After` on `Leave` → `Clear` on `Back` →
//! `Idle` at once. The association under test sits in `Work` (and `After`/`Clear` when the
//! test needs them). Cycle 10 ms: scan k runs at SYS_CLOCK = (k - 1) × 10 ms. `Go` in scan 2
//! activates `Work` in scan 2 (transitions are tested at the start of the scan, actions run
//! after), so `Work.T` = 0 ms in scan 2, 10 ms in scan 3, …, 50 ms in scan 7.
//!
//! A script line per scan: upper-case letters are the inputs held TRUE in that scan
//! (G = Go, L = Leave, B = Back), lower-case letters what must hold after it
//! (q = `Act.Q`, a = `Act.A`; absent = FALSE). Expected values are derived from the rules
//! by hand, as the comments explain.

mod sfc_common;
use sfc_common::Run;

fn chart(work: &str, after: &str, clear: &str) -> String {
    format!(
        "PROGRAM Main
VAR_INPUT Go : BOOL; Leave : BOOL; Back : BOOL; END_VAR
VAR Runs : INT; FinalRuns : INT; Delay : TIME := T#30ms; Lamp : BOOL; END_VAR
INITIAL_STEP Idle : END_STEP
TRANSITION FROM Idle TO Work := Go; END_TRANSITION
STEP Work : {work} END_STEP
TRANSITION FROM Work TO After := Leave; END_TRANSITION
STEP After : {after} END_STEP
TRANSITION FROM After TO Clear := Back; END_TRANSITION
STEP Clear : {clear} END_STEP
TRANSITION FROM Clear TO Idle := TRUE; END_TRANSITION
ACTION Act :
    Runs := Runs + 1;
    IF NOT Act.Q THEN FinalRuns := FinalRuns + 1; END_IF;
END_ACTION
END_PROGRAM"
    )
}

/// Runs `script` (see the module comment) and returns (Runs, FinalRuns).
fn play(work: &str, after: &str, clear: &str, script: &[&str]) -> (i128, i128) {
    let mut run = Run::new(&chart(work, after, clear), &["Go", "Leave", "Back"]);
    for (i, line) in script.iter().enumerate() {
        let mut on = Vec::new();
        for c in line.chars() {
            match c {
                'G' => on.push("Go"),
                'L' => on.push("Leave"),
                'B' => on.push("Back"),
                _ => {}
            }
        }
        run.scan(&on);
        let scan = i + 1;
        let (q, a) = (line.contains('q'), line.contains('a'));
        assert_eq!(run.bool("Act.Q"), q, "Act.Q after scan {scan} (`{line}`) of {work}");
        assert_eq!(run.bool("Act.A"), a, "Act.A after scan {scan} (`{line}`) of {work}");
    }
    (run.int("Runs"), run.int("FinalRuns"))
}

#[test]
fn n_runs_while_the_step_is_active_then_once_more_with_q_false() {
    let runs = play("Act(N);", "", "", &["-", "G qa", "qa", "L a", "-", "-"]);
    assert_eq!(runs, (3, 1), "scans 2, 3 with Q, scan 4 the final scan");
}

#[test]
fn no_qualifier_means_n() {
    let runs = play("Act();", "", "", &["-", "G qa", "L a", "-"]);
    assert_eq!(runs, (2, 1));
}

#[test]
fn d_becomes_active_when_the_step_has_been_active_for_the_delay() {
    // Work.T reaches 50 ms in scan 7: the delay timer's ET does too.
    let script = ["-", "G", "", "", "", "", "qa", "qa", "L a", "-"];
    assert_eq!(play("Act(D, T#50ms);", "", "", &script), (3, 1));
    let mut run = Run::new(&chart("Act(D, T#50ms);", "", ""), &["Go", "Leave", "Back"]);
    run.scan(&[]);
    run.scan(&["Go"]);
    run.idle(4);
    assert_eq!((run.ms("Work.T"), run.bool("Act.Q")), (40, false), "scan 6");
    run.idle(1);
    assert_eq!((run.ms("Work.T"), run.bool("Act.Q")), (50, true), "scan 7");
}

#[test]
fn d_never_runs_when_the_step_is_left_before_the_delay() {
    let script = ["-", "G", "", "", "L", "", "", "", "", ""];
    assert_eq!(play("Act(D, T#50ms);", "", "", &script), (0, 0));
}

#[test]
fn d_reads_its_delay_from_a_time_variable() {
    // Delay = 30 ms: active from scan 5 (Work.T = 30 ms).
    let script = ["-", "G", "", "", "qa", "L a", "-"];
    assert_eq!(play("Act(D, Delay);", "", "", &script), (2, 1));
}

#[test]
fn l_stops_after_its_duration_though_the_step_stays_active() {
    // Active while ET < 50 ms: scans 2..6; in scan 7 ET = 50 ms, Q falls (final scan).
    let script = ["-", "G qa", "qa", "qa", "qa", "qa", "a", "-", "-"];
    assert_eq!(play("Act(L, T#50ms);", "", "", &script), (6, 1));
}

#[test]
fn l_stops_with_the_step_when_it_is_left_early() {
    let script = ["-", "G qa", "qa", "L a", "-"];
    assert_eq!(play("Act(L, T#50ms);", "", "", &script), (3, 1));
}

#[test]
fn s_stays_stored_after_the_step_is_left_until_r() {
    // Stored in scan 2; Work left in scan 4; Clear (R) active in scan 6 resets it.
    let script = ["-", "G qa", "qa", "L qa", "qa", "B a", "-", "-"];
    assert_eq!(play("Act(S);", "", "Act(R);", &script), (5, 1));
}

#[test]
fn r_wins_over_every_other_association_of_the_action() {
    let script = ["-", "G", "", "L", "-"];
    assert_eq!(play("Act(N); Act(R);", "", "", &script), (0, 0));
    let script = ["-", "G", "L", "-"];
    assert_eq!(play("Act(S); Act(R);", "", "", &script), (0, 0), "nothing is stored under R");
}

#[test]
fn sd_stays_stored_after_the_step_is_left_and_starts_after_the_delay() {
    // Stored in scan 2, the delay runs on after Work is left in scan 4: ET = 50 ms in scan 7.
    let script = ["-", "G", "", "L", "", "", "qa", "qa", "B a", "-"];
    assert_eq!(play("Act(SD, T#50ms);", "", "Act(R);", &script), (3, 1));
}

#[test]
fn sd_reset_before_its_delay_never_runs() {
    let script = ["-", "G", "L", "B", "-", "", "", "", "", ""];
    assert_eq!(play("Act(SD, T#50ms);", "", "Act(R);", &script), (0, 0));
}

#[test]
fn ds_stores_only_once_the_delay_has_passed_in_the_step() {
    // ET = 50 ms in scan 7: stored; it stays after Work is left in scan 8, until R (scan 10).
    let script = ["-", "G", "", "", "", "", "qa", "L qa", "qa", "B a", "-"];
    assert_eq!(play("Act(DS, T#50ms);", "", "Act(R);", &script), (4, 1));
}

#[test]
fn ds_does_not_store_when_the_step_is_left_before_the_delay() {
    let script = ["-", "G", "", "", "L", "", "", "", "", "", ""];
    assert_eq!(play("Act(DS, T#50ms);", "", "Act(R);", &script), (0, 0));
}

#[test]
fn sl_stops_after_its_time_even_though_stored_and_r_rearms_it() {
    // Stored in scan 2, Work left in scan 3, still active (stored) until ET = 50 ms in
    // scan 7; Clear's R in scan 9 clears the store, so Go in scan 11 starts it again.
    let script = ["-", "G qa", "L qa", "qa", "qa", "qa", "a", "-", "B", "-", "G qa", "qa"];
    assert_eq!(play("Act(SL, T#50ms);", "", "Act(R);", &script), (8, 1));
}

#[test]
fn p_is_a_one_scan_pulse_followed_by_the_final_scan() {
    let script = ["-", "G qa", "a", "-", "-"];
    assert_eq!(play("Act(P);", "", "", &script), (2, 1));
}

#[test]
fn p1_runs_once_on_activation_without_a_final_scan() {
    let script = ["-", "G qa", "-", "-", "L", "-"];
    assert_eq!(play("Act(P1);", "", "", &script), (1, 0));
}

#[test]
fn p0_runs_once_on_deactivation() {
    let script = ["-", "G", "", "L qa", "-", "-"];
    assert_eq!(play("Act(P0);", "", "", &script), (1, 0));
}

#[test]
fn a_pulse_does_not_remove_the_final_scan_of_a_held_action() {
    // N holds Q in scans 2..3; P0 keeps Q TRUE in scan 4 (the step is left); the final scan
    // comes in scan 5 because the Q period was held by N.
    let script = ["-", "G qa", "qa", "L qa", "a", "-"];
    assert_eq!(play("Act(N); Act(P0);", "", "", &script), (4, 1));
    let script = ["-", "G qa", "qa", "L a", "-"];
    assert_eq!(play("Act(P1); Act(N);", "", "", &script), (3, 1));
}

#[test]
fn one_action_control_ors_the_associations_of_every_step() {
    // N in Work and in After: Q stays TRUE across the transition, no final scan between.
    let script = ["-", "G qa", "qa", "L qa", "qa", "B a", "-"];
    assert_eq!(play("Act(N);", "Act(N);", "", &script), (5, 1));
    // L in both: the limit timer does not restart in After (its input never fell).
    let script = ["-", "G qa", "qa", "L qa", "qa", "qa", "a", "-"];
    assert_eq!(play("Act(L, T#50ms);", "Act(L, T#50ms);", "", &script), (6, 1));
    // R in Clear resets what S stored in Work, while N in After had kept it active too.
    let script = ["-", "G qa", "L qa", "B a", "-"];
    assert_eq!(play("Act(S);", "Act(N);", "Act(R);", &script), (3, 1));
}

#[test]
fn a_boolean_action_follows_q() {
    let mut run = Run::new(&chart("Lamp(N);", "", ""), &["Go", "Leave", "Back"]);
    let mut lamp = Vec::new();
    for on in [&[][..], &["Go"], &[], &["Leave"], &[]] {
        run.scan(on);
        lamp.push(run.bool("Lamp"));
    }
    assert_eq!(lamp, [false, true, true, false, false]);
    let mut run = Run::new(&chart("Lamp(S);", "", "Lamp(R);"), &["Go", "Leave", "Back"]);
    let mut lamp = Vec::new();
    for on in [&[][..], &["Go"], &["Leave"], &[], &["Back"], &[]] {
        run.scan(on);
        lamp.push(run.bool("Lamp"));
    }
    assert_eq!(lamp, [false, true, true, true, false, false]);
}
