//! Unit tests of the SFC checks: every diagnostic with its code and exact location (the
//! text it points at), contextual keywords, and the structure warnings.

#![allow(clippy::unwrap_used)]

use crate::diagnostics::{LineIndex, Severity};
use crate::semantic::analyze;

/// (code, line, column, the text the diagnostic points at) for every diagnostic of `src`.
fn problems(src: &str) -> Vec<(&'static str, u32, u32, String)> {
    let index = LineIndex::new(src);
    analyze(src)
        .diagnostics
        .iter()
        .map(|d| {
            let at = index.location(d.span.start);
            let text = src[d.span.start as usize..d.span.end as usize].to_string();
            (d.code.as_str(), at.line, at.column, text)
        })
        .collect()
}

/// The (code, pointed text) pairs of `src`'s diagnostics.
fn found(src: &str) -> Vec<(&'static str, String)> {
    problems(src).into_iter().map(|(c, _, _, t)| (c, t)).collect()
}

fn one(code: &'static str, text: &str) -> Vec<(&'static str, String)> {
    vec![(code, text.to_string())]
}

/// A program whose body is `chart`, with a few variables to use.
fn program(chart: &str) -> String {
    format!(
        "PROGRAM Main\nVAR Count : INT; Flag : BOOL; Delay : TIME; END_VAR\n{chart}\nACTION Act : Count := Count + 1; END_ACTION\nEND_PROGRAM\n"
    )
}

const TWO_STEPS: &str = "INITIAL_STEP A : Act(N); END_STEP
TRANSITION FROM A TO B := Flag; END_TRANSITION
STEP B : END_STEP
TRANSITION FROM B TO A := NOT Flag; END_TRANSITION";

#[test]
fn a_correct_chart_has_no_diagnostic() {
    assert_eq!(found(&program(TWO_STEPS)), []);
}

#[test]
fn an_unknown_step_in_a_transition_is_located_at_its_name() {
    let src = program(&TWO_STEPS.replace("FROM B TO A", "FROM B TO Bogus"));
    assert_eq!(problems(&src), [("E0550", 6, 22, "Bogus".to_string())]);
}

#[test]
fn a_second_initial_step_in_one_network() {
    let src = program(&TWO_STEPS.replace("STEP B :", "INITIAL_STEP B :"));
    assert_eq!(found(&src), one("E0552", "INITIAL_STEP B"));
}

#[test]
fn separate_networks_each_have_their_own_initial_step() {
    let src = program(&format!(
        "{TWO_STEPS}\nINITIAL_STEP C : END_STEP\nTRANSITION FROM C TO D := Flag; END_TRANSITION\nSTEP D : END_STEP"
    ));
    assert_eq!(found(&src), []);
    let src = program(&format!("{TWO_STEPS}\nSTEP C : END_STEP\nTRANSITION FROM C TO D := Flag; END_TRANSITION\nSTEP D : END_STEP"));
    assert_eq!(found(&src), one("E0553", "STEP C"), "the network C-D has no initial step");
}

#[test]
fn a_chart_without_an_initial_step() {
    let src = program(&TWO_STEPS.replace("INITIAL_STEP A", "STEP A"));
    assert_eq!(found(&src), one("E0553", "STEP A"));
    let src = "PROGRAM Empty\nACTION Act : ; END_ACTION\nEND_PROGRAM";
    let f = found(src);
    assert!(f.contains(&("E0553", "Empty".to_string())), "{f:?}");
}

#[test]
fn an_action_used_but_not_declared() {
    let src = program(&TWO_STEPS.replace("Act(N)", "Missing(N)"));
    let f = found(&src);
    assert!(f.contains(&("E0554", "Missing".to_string())), "{f:?}");
    assert!(f.contains(&("W0023", "ACTION Act".to_string())), "Act is now unused: {f:?}");
}

#[test]
fn a_transition_condition_that_is_not_bool() {
    let src = program(&TWO_STEPS.replace(":= Flag;", ":= Count;"));
    let d = analyze(&src).diagnostics;
    assert_eq!(found(&src), one("E0558", "Count"));
    assert_eq!(d[0].message, "the condition of transition `FROM A TO B` must be BOOL, not INT");
}

#[test]
fn timed_qualifiers_need_a_time_duration() {
    let src = program(&TWO_STEPS.replace("Act(N)", "Act(L)"));
    assert_eq!(found(&src), one("E0555", "L"));
    for q in ["D", "SD", "DS", "SL"] {
        let src = program(&TWO_STEPS.replace("Act(N)", &format!("Act({q})")));
        assert_eq!(found(&src), one("E0555", q), "{q}");
    }
    let src = program(&TWO_STEPS.replace("Act(N)", "Act(D, Count)"));
    assert_eq!(found(&src), one("E0559", "Count"));
    let src = program(&TWO_STEPS.replace("Act(N)", "Act(D, Delay)"));
    assert_eq!(found(&src), [], "a TIME variable is a duration");
}

#[test]
fn untimed_qualifiers_take_no_duration_and_unknown_qualifiers_are_named() {
    let src = program(&TWO_STEPS.replace("Act(N)", "Act(N, T#1s)"));
    assert_eq!(found(&src), one("E0556", "T#1s"));
    let src = program(&TWO_STEPS.replace("Act(N)", "Act(Q)"));
    assert_eq!(found(&src), one("E0557", "Q"));
}

#[test]
fn step_flags_and_action_controls_are_read_only() {
    let src = program(TWO_STEPS).replace("Count := Count + 1;", "A.X := TRUE; Act.Q := FALSE;");
    assert_eq!(found(&src), [("E0560", "A.X".to_string()), ("E0560", "Act.Q".to_string())]);
    let src = program(TWO_STEPS).replace("Count := Count + 1;", "Count := SEL(B.X, 1, 2);");
    assert_eq!(found(&src), [], "reading them is fine");
}

#[test]
fn sfc_bodies_only_in_programs_and_function_blocks_and_not_mixed_with_statements() {
    let src =
        "FUNCTION F : INT\nINITIAL_STEP A : END_STEP\nEND_FUNCTION\nPROGRAM Main F(); END_PROGRAM";
    assert!(found(src).contains(&("E0561", "F".to_string())), "{:?}", found(src));
    let src = program(&format!("Count := 1;\n{TWO_STEPS}"));
    assert_eq!(found(&src), one("E0561", "Count := 1;"));
    let src = program(&format!("{TWO_STEPS}\nCount := 1;"));
    assert_eq!(found(&src), one("E0561", "Count := 1;"));
}

#[test]
fn the_step_type_name_is_reserved_in_a_file_with_a_chart() {
    let src = format!("TYPE SFC_STEP : INT; END_TYPE\n{}", program(TWO_STEPS));
    assert_eq!(found(&src), one("E0562", "SFC_STEP"));
    assert_eq!(found("TYPE SFC_STEP : INT; END_TYPE\nPROGRAM P END_PROGRAM"), []);
}

#[test]
fn transition_bodies_need_a_name_and_should_assign_it() {
    let src = program(
        &TWO_STEPS
            .replace("TRANSITION FROM A TO B := Flag;", "TRANSITION FROM A TO B : Count := 1;"),
    );
    assert_eq!(found(&src), one("E0563", "TRANSITION FROM A TO B"));
    let src =
        program(&TWO_STEPS.replace(
            "TRANSITION FROM A TO B := Flag;",
            "TRANSITION Ready FROM A TO B : Count := 1;",
        ));
    assert_eq!(found(&src), one("W0024", "Ready"));
}

#[test]
fn names_are_shared_by_steps_actions_transitions_and_variables() {
    let src = program(&TWO_STEPS.replace(
        "STEP B : END_STEP",
        "STEP B : END_STEP\nTRANSITION FROM B TO Act := Flag; END_TRANSITION\nSTEP Act : END_STEP",
    ));
    assert_eq!(found(&src), one("E0551", "Act"), "the ACTION named like step `Act`");
    let src = program(
        &TWO_STEPS
            .replace("STEP B", "STEP Count")
            .replace("TO B", "TO Count")
            .replace("FROM B", "FROM Count"),
    );
    assert_eq!(found(&src), one("E0551", "Count"));
    let src = program(&TWO_STEPS.replace("FROM A TO B", "FROM (A, A) TO B"));
    assert_eq!(found(&src), one("E0564", "A"));
}

#[test]
fn a_boolean_action_needs_a_bool_variable() {
    let src = program(&TWO_STEPS.replace("Act(N)", "Flag(N); Count(N)"));
    let f = found(&src);
    assert!(f.contains(&("E0565", "Count".to_string())), "{f:?}");
    assert_eq!(f.iter().filter(|(c, _)| c.starts_with('E')).count(), 1, "Flag is fine: {f:?}");
}

#[test]
fn return_is_refused_in_actions() {
    let src = program(TWO_STEPS).replace("Count := Count + 1;", "IF Flag THEN RETURN; END_IF;");
    assert_eq!(found(&src), one("E0566", "RETURN;"));
}

#[test]
fn indicators_must_be_variables() {
    let src = program(&TWO_STEPS.replace("Act(N)", "Act(N, Flag)"));
    assert_eq!(found(&src), []);
    let src = program(&TWO_STEPS.replace("Act(N)", "Act(L, T#1s, Nowhere)"));
    assert_eq!(found(&src), one("E0100", "Nowhere"));
}

#[test]
fn a_missing_end_step_is_reported_at_the_step() {
    let src = program(&TWO_STEPS.replace("STEP B : END_STEP", "STEP B :"));
    assert_eq!(found(&src), one("E0007", "STEP"));
}

#[test]
fn sfc_words_stay_usable_as_names() {
    let src = "PROGRAM Main
VAR Step : INT; Transition : BOOL; Action : INT; From : INT; Priority : INT; END_VAR
Step := Step + 1;
Transition := Step > 2;
Action := From + Priority;
END_PROGRAM";
    assert_eq!(found(src), []);
}

#[test]
fn unreachable_steps_and_dead_transitions_are_warnings() {
    // B and C are alternatives: the join (B, C) can never fire, so D is unreachable; E has
    // no way in at all.
    let chart = "INITIAL_STEP A : Act(N); END_STEP
TRANSITION FROM A TO B := Flag; END_TRANSITION
TRANSITION FROM A TO C := NOT Flag; END_TRANSITION
STEP B : END_STEP
STEP C : END_STEP
TRANSITION FROM (B, C) TO D := TRUE; END_TRANSITION
STEP D : END_STEP
STEP E : END_STEP
TRANSITION FROM E TO A := TRUE; END_TRANSITION";
    let d = analyze(&program(chart)).diagnostics;
    assert!(d.iter().all(|d| d.severity == Severity::Warning));
    assert_eq!(
        found(&program(chart)),
        [
            ("W0022", "TRANSITION FROM (B, C) TO D".to_string()),
            ("W0020", "STEP D".to_string()),
            ("W0020", "STEP E".to_string()),
        ]
    );
}

#[test]
fn an_unsafe_chart_is_a_warning_with_the_path_that_shows_it() {
    // A forks into B and C, but they are joined as alternatives into D: D is activated
    // twice.
    let chart = "INITIAL_STEP A : Act(N); END_STEP
TRANSITION FROM A TO (B, C) := Flag; END_TRANSITION
STEP B : END_STEP
STEP C : END_STEP
TRANSITION FROM B TO D := TRUE; END_TRANSITION
TRANSITION FROM C TO D := TRUE; END_TRANSITION
STEP D : END_STEP";
    let src = program(chart);
    let f = found(&src);
    assert_eq!(f, one("W0021", "TRANSITION FROM C TO D"), "only the first found is reported");
    let d = analyze(&src).diagnostics;
    assert!(
        d[0].message
            .contains("after firing transition `FROM A TO (B, C)`, transition `FROM B TO D`"),
        "{}",
        d[0].message
    );
}

#[test]
fn equal_priorities_on_one_step_are_a_warning() {
    let chart = TWO_STEPS
        .replace("TRANSITION FROM A TO B", "TRANSITION (PRIORITY := 1) FROM A TO B")
        .replace("STEP B : END_STEP", "STEP B : END_STEP\nTRANSITION Other (PRIORITY := 1) FROM A TO B := Flag; END_TRANSITION");
    assert_eq!(found(&program(&chart)), one("W0025", "(PRIORITY := 1)"));
}
