//! Code generation: the exact text for small nets, the place map, and every error a net
//! can have before its code exists, located at the element.

use super::*;
use crate::diagnostics::Code;

fn codes(diags: &[PetriDiagnostic]) -> Vec<&str> {
    diags.iter().map(|d| d.code.as_str()).collect()
}

fn two_step() -> PetriPou {
    // P1 -T1 (g1)-> P2 -T2 (g2)-> P1, one token in P1.
    let mut p =
        pou(net(&[("P1", 1), ("P2", 0)], &[("T1", &["P1"], &["P2"]), ("T2", &["P2"], &["P1"])]), 2);
    p.net.transitions[0].guard = "g1".into();
    p.net.transitions[1].guard = "g2".into();
    p.net.places[0].actions = "x := x + 1;".into();
    p.declarations.push_str("VAR\n    x : INT;\nEND_VAR\n");
    p
}

#[test]
fn a_sequence_generates_the_seeds_case_of() {
    let c = compile(&two_step()).unwrap();
    let want = "\
(* Generated from the Petri net Net by the CASE OF method: edit the net, not this text. *)
PROGRAM Net
VAR_INPUT
    g1 : BOOL;
    g2 : BOOL;
END_VAR
VAR
    x : INT;
END_VAR
VAR (* step variables of the net's processes *)
    p : INT := 1; (* process Main: 1 = P1, 2 = P2 *)
END_VAR

(* ---- process Main (step variable p) ---- *)
CASE p OF
    1: (* P1 *)
        x := x + 1;
        IF g1 THEN (* T1: P1 -> P2 *)
            p := 2;
        END_IF;
    2: (* P2 *)
        IF g2 THEN (* T2: P2 -> P1 *)
            p := 1;
        END_IF;
END_CASE;
END_PROGRAM
";
    assert_eq!(c.generated.st, want);
    assert_eq!(c.processes.len(), 1);
    assert_eq!(c.generated.place_map.places[1].step_variable, "p");
    assert_eq!(c.generated.place_map.places[1].value, 2);
    // The guard of T1 sits on line 18 after `        IF ` (11 characters).
    assert_eq!(
        c.generated.locate(18, 12),
        Some((
            NetElement::Transition("T1".into()),
            Some(TextPosition { part: TextPart::Guard, line: 1, column: 1 })
        ))
    );
    assert_eq!(
        c.generated.locate(17, 9),
        Some((
            NetElement::Place("P1".into()),
            Some(TextPosition { part: TextPart::Actions, line: 1, column: 1 })
        ))
    );
}

/// A choice at P1: T1 to P2 (guard g1) or T2 to P3 (guard g2), both back to P1.
fn choice() -> PetriPou {
    let mut p = pou(
        net(
            &[("P1", 1), ("P2", 0), ("P3", 0)],
            &[
                ("T1", &["P1"], &["P2"]),
                ("T2", &["P1"], &["P3"]),
                ("T3", &["P2"], &["P1"]),
                ("T4", &["P3"], &["P1"]),
            ],
        ),
        2,
    );
    p.net.transitions[0].guard = "g1".into();
    p.net.transitions[1].guard = "g2".into();
    p
}

#[test]
fn retain_and_priority_order() {
    // Two transitions leave P1; T2 has the lower priority number so it is tested first.
    let mut p = choice();
    p.options.retain = true;
    p.net.transitions[0].priority = 2;
    p.net.transitions[1].priority = 1;
    let st = compile(&p).unwrap().generated.st;
    assert!(st.contains("VAR RETAIN (* step variables"), "{st}");
    let t2 = st.find("IF g2 THEN").unwrap();
    let t1 = st.find("ELSIF g1 THEN").unwrap();
    assert!(t2 < t1, "{st}");
    // Empty guards are TRUE.
    assert!(st.contains("IF TRUE THEN (* T3: P2 -> P1 *)"), "{st}");
}

#[test]
fn place_map_reads_the_marking() {
    let c = compile(&two_step()).unwrap();
    let m = c.generated.place_map.marking(|v| (v == "p").then_some(2));
    assert_eq!(m, vec![0, 1]);
}

#[test]
fn a_net_no_process_covers_is_refused_naming_the_places() {
    // A bounded buffer of two: items + free is an invariant holding 2 tokens, so no
    // one-token state machine covers `items` and `free`.
    let n = producer_consumer();
    let err = compile(&pou(n, 0)).unwrap_err();
    assert_eq!(codes(&err), vec!["E0505"]);
    assert!(err[0].message.contains("items, free"), "{}", err[0].message);
}

#[test]
fn a_guard_that_is_not_an_expression_is_located_in_the_guard() {
    let mut p = two_step();
    p.net.transitions[1].guard = "g1 AND AND g2".into();
    let err = compile(&p).unwrap_err();
    assert_eq!(codes(&err), vec!["E0503"]);
    assert_eq!(err[0].element, NetElement::Transition("T2".into()));
    assert_eq!(err[0].at, Some(TextPosition { part: TextPart::Guard, line: 1, column: 8 }));
}

#[test]
fn actions_cannot_break_out_of_their_branch() {
    let mut p = two_step();
    p.net.places[1].actions = "x := 1;\nEND_CASE;\nx := 2;".into();
    let err = compile(&p).unwrap_err();
    assert_eq!(codes(&err), vec!["E0504"]);
    assert_eq!(err[0].element, NetElement::Place("P2".into()));
    assert_eq!(err[0].at.unwrap().line, 2);
    p.net.places[1].actions = "x := 1; END_PROGRAM PROGRAM Q".into();
    assert_eq!(codes(&compile(&p).unwrap_err()), vec!["E0504"]);
    p.net.places[1].actions = "VAR y : INT; END_VAR".into();
    assert_eq!(codes(&compile(&p).unwrap_err()), vec!["E0504"]);
}

#[test]
fn structural_errors_name_the_element() {
    let mut p = two_step();
    p.net.arcs.push(Arc::new("P1", "P2"));
    p.net.arcs.push(Arc::new("T1", "nowhere"));
    p.net.arcs.push(Arc { from: "P2".into(), to: "T2".into(), weight: 1 });
    p.net.arcs.push(Arc { from: "P1".into(), to: "T1".into(), weight: 0 });
    let err = compile(&p).unwrap_err();
    assert_eq!(codes(&err), vec!["E0501", "E0501", "E0502", "E0501"]);
    assert_eq!(err[0].element, NetElement::Arc(4));
    assert!(err[0].message.contains("`P1` is a place and `P2` is a place"), "{}", err[0].message);
    assert!(err[1].message.contains("`nowhere` is nothing in the net"), "{}", err[1].message);
}

#[test]
fn ids_are_unique_across_the_net() {
    let mut p = two_step();
    p.net.transitions.push(Transition::new("P1", ""));
    let err = compile(&p).unwrap_err();
    assert_eq!(codes(&err), vec!["E0500"]);
    assert_eq!(err[0].element, NetElement::Transition("P1".into()));
    assert!(err[0].message.contains("place P1"), "{}", err[0].message);
}

#[test]
fn arcs_end_on_places_not_macro_places() {
    let mut p = two_step();
    p.net.macro_places.push(MacroPlace {
        id: "M".into(),
        name: String::new(),
        places: vec!["P2".into(), "P9".into()],
        position: None,
        comment: String::new(),
    });
    p.net.arcs.push(Arc::new("T1", "M"));
    let err = compile(&p).unwrap_err();
    assert_eq!(codes(&err), vec!["E0501", "E0510"]);
    assert!(err[0].message.contains("macro-place"), "{}", err[0].message);
}

#[test]
fn labels_must_differ_inside_a_process_and_fit_an_int() {
    let mut p = two_step();
    p.net.places[1].label = 1;
    assert_eq!(codes(&compile(&p).unwrap_err()), vec!["E0507"]);
    p.net.places[1].label = 40_000;
    assert_eq!(codes(&compile(&p).unwrap_err()), vec!["E0512"]);
}

#[test]
fn a_process_must_hold_one_token() {
    let mut p = two_step();
    p.net.places[1].tokens = 1;
    assert_eq!(codes(&compile(&p).unwrap_err()), vec!["E0505"]);
    p.net.processes.push(Process {
        name: "Main".into(),
        step_variable: "p".into(),
        places: vec!["P1".into(), "P2".into()],
    });
    assert_eq!(codes(&compile(&p).unwrap_err()), vec!["E0506"]);
}

#[test]
fn declared_processes_are_checked() {
    let mut p = two_step();
    p.net.processes.push(Process {
        name: "Main".into(),
        step_variable: "p".into(),
        places: vec!["P1".into()],
    });
    let err = compile(&p).unwrap_err();
    assert_eq!(codes(&err), vec!["E0508"]);
    assert!(err[0].message.contains("T1, T2"), "{}", err[0].message);
    p.net.processes[0] = Process {
        name: "Main 1".into(),
        step_variable: "p".into(),
        places: vec!["P1".into(), "P2".into()],
    };
    assert_eq!(codes(&compile(&p).unwrap_err()), vec!["E0515"]);
}

#[test]
fn a_transition_needs_an_input_place() {
    let mut p = two_step();
    p.net.transitions.push(Transition::new("T3", ""));
    p.net.arcs.push(Arc::new("T3", "P1"));
    assert_eq!(codes(&compile(&p).unwrap_err()), vec!["E0514"]);
}

#[test]
fn the_emergency_place_must_exist() {
    let mut p = two_step();
    p.net.emergency = Some(Emergency { place: "P9".into(), condition: "g1".into() });
    assert_eq!(codes(&compile(&p).unwrap_err()), vec!["E0509"]);
    p.net.emergency = Some(Emergency { place: "P2".into(), condition: "g1 OR".into() });
    let err = compile(&p).unwrap_err();
    assert_eq!(codes(&err), vec!["E0503"]);
    assert_eq!(err[0].element, NetElement::Emergency);
}

fn fork_join(sync: SyncStyle) -> PetriPou {
    // Main: M1 -fork-> M2 -join-> M1; process A: A0 -fork-> A1 -a-> A2 -join-> A0;
    // process B: B0 -fork-> B1 -join-> B0.
    let mut p = pou(
        net(
            &[("M1", 1), ("M2", 0), ("A0", 1), ("A1", 0), ("A2", 0), ("B0", 1), ("B1", 0)],
            &[
                ("fork", &["M1", "A0", "B0"], &["M2", "A1", "B1"]),
                ("a", &["A1"], &["A2"]),
                ("join", &["M2", "A2", "B1"], &["M1", "A0", "B0"]),
            ],
        ),
        3,
    );
    p.net.transitions[0].guard = "g1".into();
    p.net.transitions[1].guard = "g2".into();
    p.net.transitions[2].guard = "g3".into();
    for (i, pl) in p.net.places.iter_mut().enumerate() {
        pl.label = [1, 2, 0, 1, 2, 0, 1][i];
    }
    let proc = |name: &str, var: &str, places: &[&str]| Process {
        name: name.into(),
        step_variable: var.into(),
        places: places.iter().map(|s| s.to_string()).collect(),
    };
    p.net.processes = vec![
        proc("Main", "p", &["M1", "M2"]),
        proc("PA", "pA", &["A0", "A1", "A2"]),
        proc("PB", "pB", &["B0", "B1"]),
    ];
    p.options.sync = sync;
    p
}

#[test]
fn fork_and_join_by_step_variables() {
    let st = compile(&fork_join(SyncStyle::StepVariables)).unwrap().generated.st;
    for line in [
        "PnScan_pA := pA;",
        "PnScan_pB := pB;",
        "CASE p OF",
        "IF (g1) AND pA = 0 AND pB = 0 THEN (* fork: M1, A0, B0 -> M2, A1, B1 *)",
        "IF (g3) AND pA = 2 AND pB = 1 THEN (* join: M2, A2, B1 -> M1, A0, B0 *)",
        "CASE PnScan_pA OF",
        "CASE PnScan_pB OF",
    ] {
        assert!(st.contains(line), "missing `{line}` in\n{st}");
    }
}

#[test]
fn fork_and_join_by_flags() {
    let st = compile(&fork_join(SyncStyle::Flags)).unwrap().generated.st;
    for line in [
        "IF (g1) AND PA_End_0 AND PB_End_0 THEN (* fork: M1, A0, B0 -> M2, A1, B1 *)",
        "PA_Start_0 := TRUE;",
        "IF PA_Start_0 THEN (* fork: M1, A0, B0 -> M2, A1, B1 decided by process Main *)",
        "PA_End_0 : BOOL := TRUE; (* PA waits at A0 *)",
        "PA_End_2 : BOOL := FALSE; (* PA waits at A2 *)",
        "CASE pA OF",
    ] {
        assert!(st.contains(line), "missing `{line}` in\n{st}");
    }
    assert!(!st.contains("PnScan_"), "{st}");
}

#[test]
fn flags_cannot_tell_two_shared_transitions_apart_at_one_place() {
    let mut p = fork_join(SyncStyle::Flags);
    // A second join from the same places, with another guard.
    p.net.transitions.push(Transition::new("join2", "NOT g3"));
    for (a, b) in [
        ("M2", "join2"),
        ("A2", "join2"),
        ("B1", "join2"),
        ("join2", "M1"),
        ("join2", "A0"),
        ("join2", "B0"),
    ] {
        p.net.arcs.push(Arc::new(a, b));
    }
    let err = compile(&p).unwrap_err();
    assert_eq!(codes(&err), vec!["E0513", "E0513"]);
    p.options.sync = SyncStyle::StepVariables;
    assert!(compile(&p).is_ok());
}

#[test]
fn equal_priorities_with_overlapping_guards_warn() {
    let mut p = choice();
    let w = compile(&p).unwrap().warnings;
    assert_eq!(codes(&w), vec!["W0010"]);
    assert_eq!(w[0].code, Code::PetriGuardConflict);
    p.net.transitions[1].guard = "NOT g1".into();
    assert!(compile(&p).unwrap().warnings.is_empty());
    p.net.transitions[1].guard = "g2".into();
    p.net.transitions[1].priority = 1;
    assert!(compile(&p).unwrap().warnings.is_empty());
}

#[test]
fn deadlocks_and_dead_transitions_warn() {
    // {P1, P2, P3} is one component (T1: P1 → P2, T2: P3 → P1) holding P1's token, so
    // the net compiles; but after T1 nothing is enabled, and T2 needs P3, never marked.
    let p = pou(
        net(
            &[("P1", 1), ("P2", 0), ("P3", 0)],
            &[("T1", &["P1"], &["P2"]), ("T2", &["P3"], &["P1"])],
        ),
        0,
    );
    let w = compile(&p).unwrap().warnings;
    assert_eq!(codes(&w), vec!["W0011", "W0012"]);
    assert!(w[0].message.contains("[T1]"), "{}", w[0].message);
    assert_eq!(w[1].element, NetElement::Transition("T2".into()));
}

#[test]
fn diagnostics_are_data_shown_in_polish_and_czech() {
    use crate::i18n::Lang;
    let mut p = two_step();
    p.net.arcs.push(Arc::new("T1", "nowhere"));
    let err = compile(&p).unwrap_err();
    let d = &err[0];
    assert_eq!(
        d.message,
        "an arc must join a place and a transition, but `T1` is a transition and `nowhere` is \
         nothing in the net"
    );
    assert_eq!(d.msg.render(Lang::En), d.message);
    assert_eq!(
        d.msg.render(Lang::Pl),
        "łuk musi łączyć miejsce z przejściem, tymczasem `T1` to przejście, a `nowhere` to coś, \
         czego nie ma w sieci"
    );
    assert_eq!(
        d.msg.render(Lang::Cs),
        "hrana musí spojovat místo a přechod, ale `T1` je přechod a `nowhere` je něco, co v síti \
         není"
    );
    // A warning, its list of transitions being program text.
    let p = pou(
        net(
            &[("P1", 1), ("P2", 0), ("P3", 0)],
            &[("T1", &["P1"], &["P2"]), ("T2", &["P3"], &["P1"])],
        ),
        0,
    );
    let w = compile(&p).unwrap().warnings;
    assert_eq!(w[0].msg.render(Lang::En), w[0].message);
    assert_eq!(
        w[0].msg.render(Lang::Pl),
        "sieć może się zatrzymać (warunki przejść pominięte): po odpaleniu [T1] żadne przejście \
         nie jest aktywne"
    );
    assert_eq!(
        w[0].msg.render(Lang::Cs),
        "síť se může zastavit (podmínky přechodů pominuty): po provedení [T1] není povolen žádný \
         přechod"
    );
}
