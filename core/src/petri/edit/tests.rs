#![allow(clippy::unwrap_used)]

use super::*;
use crate::petri::{compile, GenerationOptions, MacroPlace, Net, Process};
use crate::project::History;

fn empty(name: &str) -> PetriPou {
    PetriPou {
        name: name.into(),
        declarations: "VAR_INPUT\n    Go : BOOL;\nEND_VAR\n".into(),
        prologue: String::new(),
        epilogue: String::new(),
        net: Net::default(),
        options: GenerationOptions::default(),
    }
}

fn at(x: f64, y: f64) -> Position {
    Position { x, y }
}

/// Applies edits in order, failing the test at the first refused one.
fn build(mut pou: PetriPou, edits: &[NetEdit]) -> PetriPou {
    for e in edits {
        pou = pou.apply(e).unwrap_or_else(|err| panic!("{e:?}: {err}"));
    }
    pou
}

fn arc(from: &str, to: &str) -> NetEdit {
    NetEdit::AddArc { from: from.into(), to: to.into() }
}

/// The three-place cycle P1 → T1 → P2 → T2 → P3 → T3 → P1 of the issue, drawn as a user
/// draws it: places and transitions where clicked, ids from `next_id`, then the arcs.
fn cycle() -> PetriPou {
    let mut pou = empty("Cycle");
    for (i, prefix) in ["P", "T", "P", "T", "P", "T"].iter().enumerate() {
        let id = pou.next_id(prefix);
        let position = at(100.0 * i as f64, 50.0);
        let edit = if *prefix == "P" {
            NetEdit::AddPlace { id, at: position }
        } else {
            NetEdit::AddTransition { id, at: position }
        };
        pou = pou.apply(&edit).unwrap();
    }
    build(
        pou,
        &[
            arc("P1", "T1"),
            arc("T1", "P2"),
            arc("P2", "T2"),
            arc("T2", "P3"),
            arc("P3", "T3"),
            arc("T3", "P1"),
            NetEdit::SetTokens { id: "P1".into(), tokens: 1 },
            NetEdit::SetGuard { id: "T1".into(), text: "Go".into() },
        ],
    )
}

#[test]
fn a_cycle_drawn_element_by_element_compiles_to_case_code() {
    let pou = cycle();
    let ids: Vec<&str> = pou.net.places.iter().map(|p| p.id.as_str()).collect();
    assert_eq!(ids, ["P1", "P2", "P3"]);
    let labels: Vec<i64> = pou.net.places.iter().map(|p| p.label).collect();
    assert_eq!(labels, [1, 2, 3], "each new place gets the next CASE label");
    assert_eq!(pou.net.transitions[1].guard, "", "a new transition's guard is empty (TRUE)");
    assert_eq!(pou.net.places[1].position, Some(at(200.0, 50.0)));
    let compiled = compile(&pou).unwrap();
    assert!(compiled.generated.st.contains("CASE"), "{}", compiled.generated.st);
    assert!(compiled.generated.st.contains("Go"), "{}", compiled.generated.st);
}

#[test]
fn ids_are_the_next_free_number_of_their_kind() {
    let pou = cycle();
    assert_eq!(pou.next_id("P"), "P4");
    assert_eq!(pou.next_id("T"), "T4");
    // A deleted element's number is not reused while a higher one exists.
    let pou = pou.apply(&NetEdit::Delete { id: "P2".into() }).unwrap();
    assert_eq!(pou.next_id("P"), "P4");
    let pou = pou.apply(&NetEdit::Delete { id: "P3".into() }).unwrap();
    assert_eq!(pou.next_id("P"), "P2");
}

#[test]
fn bad_edits_are_refused_with_a_reason_and_change_nothing() {
    let pou = cycle();
    let refused = |e: NetEdit| pou.apply(&e).unwrap_err();
    assert_eq!(refused(arc("P1", "P2")), NetEditError::SameKind("P1".into(), "P2".into()));
    assert_eq!(refused(arc("T1", "T2")), NetEditError::SameKind("T1".into(), "T2".into()));
    assert_eq!(refused(arc("P1", "T1")), NetEditError::ArcExists("P1".into(), "T1".into()));
    assert_eq!(refused(arc("P1", "X")), NetEditError::NoSuchElement("X".into()));
    assert_eq!(
        refused(NetEdit::AddPlace { id: "T1".into(), at: at(0.0, 0.0) }),
        NetEditError::IdTaken("T1".into())
    );
    assert_eq!(
        refused(NetEdit::AddPlace { id: "1P".into(), at: at(0.0, 0.0) }),
        NetEditError::NotAnId("1P".into())
    );
    assert_eq!(
        refused(NetEdit::SetGuard { id: "P1".into(), text: "TRUE".into() }),
        NetEditError::WrongKind("P1".into(), "a transition")
    );
    assert_eq!(
        refused(NetEdit::SetTokens { id: "T1".into(), tokens: 2 }),
        NetEditError::WrongKind("T1".into(), "a place")
    );
    assert_eq!(
        refused(NetEdit::SetWeight { from: "P1".into(), to: "T1".into(), weight: 0 }),
        NetEditError::ZeroWeight
    );
    assert_eq!(
        refused(NetEdit::SetLabel { id: "P1".into(), label: 2 }),
        NetEditError::LabelTaken(2, "P2".into())
    );
    assert_eq!(
        refused(NetEdit::DeleteArc { from: "P1".into(), to: "T2".into() }),
        NetEditError::NoSuchArc("P1".into(), "T2".into())
    );
    assert!(refused(arc("P1", "P2")).to_string().contains("a place and a transition"));
}

#[test]
fn deleting_an_element_takes_its_arcs_and_every_mention_with_it() {
    let mut pou = cycle();
    pou.net.macro_places.push(MacroPlace {
        id: "M1".into(),
        name: String::new(),
        places: vec!["P2".into(), "P3".into()],
        position: None,
        comment: String::new(),
    });
    pou.net.processes.push(Process {
        name: "A".into(),
        step_variable: "StepA".into(),
        places: vec!["P1".into(), "P2".into(), "P3".into()],
    });
    pou.net.emergency = Some(Emergency { place: "P2".into(), condition: "Go".into() });
    assert_eq!(pou.apply(&arc("M1", "T1")), Err(NetEditError::ArcOnMacroPlace("M1".into())));
    let after = pou.apply(&NetEdit::Delete { id: "P2".into() }).unwrap();
    assert!(after.net.arcs.iter().all(|a| a.from != "P2" && a.to != "P2"));
    assert_eq!(after.net.arcs.len(), 4);
    assert_eq!(after.net.macro_places[0].places, ["P3"]);
    assert_eq!(after.net.processes[0].places, ["P1", "P3"]);
    assert_eq!(after.net.emergency, None);
    let after = after.apply(&NetEdit::Delete { id: "T1".into() }).unwrap();
    assert_eq!(after.net.arcs.len(), 3);
    assert_eq!(
        pou.apply(&NetEdit::Delete { id: "Q".into() }),
        Err(NetEditError::NoSuchElement("Q".into()))
    );
}

#[test]
fn every_property_is_an_edit() {
    let pou = build(
        cycle(),
        &[
            NetEdit::SetName { id: "P1".into(), name: " ready ".into() },
            NetEdit::SetName { id: "T2".into(), name: "done".into() },
            NetEdit::SetLabel { id: "P3".into(), label: 30 },
            NetEdit::SetActions { id: "P2".into(), text: "Busy := TRUE;".into() },
            NetEdit::SetPriority { id: "T3".into(), priority: 2 },
            NetEdit::SetWeight { from: "T3".into(), to: "P1".into(), weight: 2 },
            NetEdit::Move { id: "T2".into(), to: at(7.0, 8.0) },
            NetEdit::DeleteArc { from: "P2".into(), to: "T2".into() },
            NetEdit::SetDeclarations { text: "VAR_INPUT Go : BOOL; END_VAR".into() },
        ],
    );
    let net = &pou.net;
    assert_eq!(net.places[0].name, "ready");
    assert_eq!(net.transitions[1].name, "done");
    assert_eq!(net.places[2].label, 30);
    assert_eq!(net.places[1].actions, "Busy := TRUE;");
    assert_eq!(net.transitions[2].priority, 2);
    assert_eq!(net.arcs.iter().find(|a| a.from == "T3").unwrap().weight, 2);
    assert_eq!(net.transitions[1].position, Some(at(7.0, 8.0)));
    assert!(!net.arcs.iter().any(|a| a.from == "P2" && a.to == "T2"));
    assert_eq!(pou.declarations, "VAR_INPUT Go : BOOL; END_VAR");
}

#[test]
fn twenty_mixed_edits_undo_and_redo_to_the_exact_states() {
    let edits = [
        NetEdit::AddPlace { id: "P4".into(), at: at(1.0, 2.0) },
        NetEdit::AddTransition { id: "T4".into(), at: at(3.0, 4.0) },
        arc("P4", "T4"),
        arc("T4", "P1"),
        NetEdit::Move { id: "P1".into(), to: at(9.0, 9.0) },
        NetEdit::SetTokens { id: "P4".into(), tokens: 2 },
        NetEdit::SetGuard { id: "T4".into(), text: "NOT Go".into() },
        NetEdit::SetName { id: "P4".into(), name: "spare".into() },
        NetEdit::SetPriority { id: "T4".into(), priority: 1 },
        NetEdit::SetWeight { from: "P4".into(), to: "T4".into(), weight: 2 },
        NetEdit::SetActions { id: "P1".into(), text: "x := 1;".into() },
        NetEdit::SetLabel { id: "P4".into(), label: 40 },
        NetEdit::Delete { id: "T2".into() },
        NetEdit::DeleteArc { from: "T4".into(), to: "P1".into() },
        NetEdit::Move { id: "T4".into(), to: at(5.0, 5.0) },
        NetEdit::AddPlace { id: "P5".into(), at: at(0.0, 0.0) },
        arc("P5", "T4"),
        NetEdit::Delete { id: "P5".into() },
        NetEdit::SetDeclarations { text: "VAR_INPUT Go, Stop : BOOL; END_VAR".into() },
        NetEdit::SetGuard { id: "T1".into(), text: "Go AND NOT Stop".into() },
    ];
    let mut history: History<PetriPou> = History::new(100);
    let mut current = cycle();
    let mut states = vec![current.clone()];
    for e in &edits {
        let next = current.apply(e).unwrap();
        history.record(current);
        current = next;
        states.push(current.clone());
    }
    for expected in states.iter().rev().skip(1) {
        current = history.undo(current).unwrap();
        assert_eq!(&current, expected);
    }
    assert!(!history.can_undo());
    for expected in states.iter().skip(1) {
        current = history.redo(current).unwrap();
        assert_eq!(&current, expected);
    }
}

#[test]
fn a_capacity_bounds_the_place_in_the_firing_rule_and_the_analysis() {
    // T1 has no input place: it may always fire, filling P1, here up to its capacity of 2.
    let pou = build(
        empty("Fill"),
        &[
            NetEdit::AddPlace { id: "P1".into(), at: at(0.0, 0.0) },
            NetEdit::AddTransition { id: "T1".into(), at: at(100.0, 0.0) },
            arc("T1", "P1"),
            NetEdit::SetCapacity { id: "P1".into(), capacity: Some(2) },
        ],
    );
    let net = crate::petri::build(&pou.net).unwrap();
    let mut m = net.initial.clone();
    for expected in [1, 2] {
        assert!(net.enabled(&m, 0));
        m = net.fire(&m, 0);
        assert_eq!(m, [expected]);
    }
    assert!(!net.enabled(&m, 0), "a third token would pass the capacity");
    let a = crate::petri::analyze(&net, 1000);
    assert_eq!((a.states, a.bounded), (3, Some(true)));
    assert_eq!(
        pou.apply(&NetEdit::SetTokens { id: "P1".into(), tokens: 3 }),
        Err(NetEditError::OverCapacity("P1".into(), 3, 2))
    );
    let full = pou.apply(&NetEdit::SetTokens { id: "P1".into(), tokens: 2 }).unwrap();
    assert_eq!(
        full.apply(&NetEdit::SetCapacity { id: "P1".into(), capacity: Some(1) }),
        Err(NetEditError::OverCapacity("P1".into(), 2, 1))
    );
    let unlimited = full.apply(&NetEdit::SetCapacity { id: "P1".into(), capacity: None }).unwrap();
    assert!(crate::petri::build(&unlimited.net).unwrap().enabled(&[2], 0));
    // PNML keeps it.
    let back = crate::pnml::import(&crate::pnml::export(&pou)).unwrap();
    assert_eq!(back.net.places[0].capacity, Some(2));
}
