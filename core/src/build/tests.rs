#![allow(clippy::unwrap_used)]

use super::*;
use crate::ladder::{Cell, CoilKind, ContactKind, Element, LadderPou, LadderPouKind, Rung};
use crate::petri::{Arc, Net, PetriPou, Place, Transition};
use crate::semantic::TextPasses;
use crate::sim::ScanOutcome;

/// `Start` (NO contact) → coil `Motor` in one rung of PROGRAM `name`.
fn ladder(name: &str, coil_operand: &str, decls: &str) -> LadderPou {
    let cell = |element| Cell { element, link_down: false };
    LadderPou {
        name: name.into(),
        kind: LadderPouKind::Program,
        declarations: decls.into(),
        rungs: vec![Rung {
            comment: "latch".into(),
            label: None,
            cells: vec![vec![
                cell(Element::Contact { kind: ContactKind::NormallyOpen, operand: "Start".into() }),
                cell(Element::Coil { kind: CoilKind::Normal, operand: coil_operand.into() }),
            ]],
        }],
    }
}

const DECLS: &str = "VAR_INPUT Start : BOOL; END_VAR VAR_OUTPUT Motor : BOOL; END_VAR";

/// A two-place loop `A -go-> B -back-> A` in PROGRAM `Loop`.
fn looping(guard: &str, actions_a: &str) -> PetriPou {
    let mut net = Net::default();
    net.places.push(Place { actions: actions_a.into(), ..Place::new("A", 1, 1) });
    net.places.push(Place::new("B", 2, 0));
    net.transitions.push(Transition::new("go", guard));
    net.transitions.push(Transition::new("back", ""));
    for (a, b) in [("A", "go"), ("go", "B"), ("B", "back"), ("back", "A")] {
        net.arcs.push(Arc::new(a, b));
    }
    PetriPou {
        name: "Loop".into(),
        declarations: "VAR n : INT; d : INT; END_VAR".into(),
        prologue: String::new(),
        epilogue: String::new(),
        net,
        options: Default::default(),
    }
}

fn project(source: &str) -> Project {
    let mut p = Project::new("t");
    p.source = source.into();
    p
}

#[test]
fn st_problems_keep_their_line_column_and_span_in_the_st_source() {
    let p = project("PROGRAM Main\nVAR x : INT; END_VAR\nx := y;\nEND_PROGRAM\n");
    let b = build_project(&p);
    assert!(b.has_errors());
    let d = b.diagnostics.iter().find(|d| d.code == Code::UndeclaredName).unwrap();
    // `y` is the 6th character of line 3, bytes 39..40 of the source.
    let start = p.source.find("y;").unwrap() as u32;
    assert_eq!(
        d.site,
        Site::St { line: 3, column: 6, span: Span { start, end: start + 1 } },
        "{d:?}"
    );
    assert_eq!(d.located_message(), d.message, "ST messages carry no prefix");
    assert!(b.program.is_none());
}

#[test]
fn ladder_errors_are_located_at_their_cell_and_stop_the_build() {
    let mut p = project("");
    p.ladder.push(ladder("Latch", "", DECLS));
    let b = build_project(&p);
    assert!(b.source.is_none() && b.program.is_none());
    let d = b.diagnostics.iter().find(|d| d.code == Code::LadderMissingOperand).unwrap();
    assert_eq!(d.site, Site::Ladder { pou: "Latch".into(), cell: Some((0, 0, 1)) });
    assert!(d.located_message().starts_with("POU Latch, rung 1, row 1, column 2: "));
}

#[test]
fn st_errors_inside_a_ladder_pou_point_at_the_cell() {
    // `Motr` is not declared: the ladder validator lets the ST checker find it, and the
    // checker's line of generated text maps back to the coil's cell.
    let mut p = project("");
    p.ladder.push(ladder("Latch", "Motr", DECLS));
    let b = build_project(&p);
    let d = b.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!(d.site.pou(), Some("Latch"));
    assert!(matches!(d.site, Site::Ladder { cell: Some((0, 0, 1)), .. }), "{:?}", b.diagnostics);
}

#[test]
fn problems_in_a_ladder_pous_declarations_point_at_their_line_and_column() {
    // `TONN` is no type: the checker's line of the lowered POU maps back into the
    // declarations text, where the declarations editor marks it.
    let decls = "VAR_INPUT Start : BOOL; END_VAR\nVAR\n  T1 : TONN;\nEND_VAR\nVAR_OUTPUT Motor : BOOL; END_VAR";
    let mut p = project("");
    p.ladder.push(ladder("Latch", "Motor", decls));
    let b = build_project(&p);
    let d = b.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!(d.site, Site::Declarations { pou: "Latch".into(), line: 3, column: 8 }, "{d:?}");
    assert!(d.located_message().starts_with("POU Latch, declarations line 3, column 8: "));
}

#[test]
fn petri_errors_are_located_at_the_element() {
    let mut p = project("");
    p.petri.push(looping("n + 1", ""));
    let b = build_project(&p);
    let d = b.diagnostics.iter().find(|d| d.code == Code::ConditionNotBool).unwrap();
    match &d.site {
        Site::Petri { pou, element: Some(NetElement::Transition(t)), at: Some(at) } => {
            assert_eq!((pou.as_str(), t.as_str()), ("Loop", "go"));
            assert_eq!((at.line, at.column), (1, 1));
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn several_programs_are_listed_and_each_can_run() {
    let mut p = project("PROGRAM First\nVAR n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n");
    p.ladder.push(ladder("Latch", "Motor", DECLS));
    p.petri.push(looping("TRUE", ""));
    let b = build_project(&p);
    assert!(!b.has_errors(), "{:?}", b.diagnostics);
    assert_eq!(b.program_names(), ["First", "Latch", "Loop"]);
    let mut sim = b.simulator(Some("latch")).unwrap();
    sim.hold("Start", "TRUE").unwrap();
    assert_eq!(sim.run_scans(1), ScanOutcome::Completed);
    assert_eq!(sim.read("Motor").unwrap(), crate::vm::Value::Bool(true));
    let first = b.simulator(None).unwrap();
    assert_eq!(first.program().pou(first.main_pou()).name, "First");
    let missing = b.simulator(Some("Nope")).unwrap_err();
    assert_eq!(missing.code, Code::UnknownProgram);
}

#[test]
fn a_fault_span_maps_back_to_the_petri_place() {
    let mut p = project("");
    p.petri.push(looping("TRUE", "n := 1 / d;"));
    let b = build_project(&p);
    let mut sim = b.simulator(None).unwrap();
    let ScanOutcome::Fault(info) = sim.run_scans(1) else { panic!("no fault") };
    match b.site_of(info.span) {
        Site::Petri { element: Some(NetElement::Place(id)), .. } => assert_eq!(id, "A"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn hidden_variables_are_recognised() {
    assert!(is_hidden_variable("LdPow_0_0_1"));
    assert!(is_hidden_variable("pnscan_p"));
    assert!(!is_hidden_variable("Motor"));
    assert!(is_hidden_variable("__IMAGE_Q"));
}

#[test]
fn empty_project_source_is_st_source() {
    let project = Project::new("p");
    let src = project_source(&project).unwrap();
    assert_eq!(src.text, project.source);
    assert_eq!(src.map.origin(1), Origin::St(1));
}

/// The web app builds with the passes it has loaded: an ST-only project needs none and
/// builds the same; a project with diagram POUs says which passes it lacks, and with every
/// pass builds as `build_project` does.
#[test]
fn a_build_by_the_loaded_passes_names_what_it_lacks() {
    let st = project("PROGRAM Main\nVAR x : INT; END_VAR\nx := x + 1;\nEND_PROGRAM\n");
    assert!(Lowerings::NONE.lacks(&st).is_empty());
    let same = |a: &ProjectBuild, b: &ProjectBuild| {
        a.diagnostics == b.diagnostics
            && a.source.as_ref().map(|s| &s.text) == b.source.as_ref().map(|s| &s.text)
    };
    assert!(same(&build_project_by(&st, &Lowerings::NONE), &build_project(&st)));
    let mut mixed = project("");
    mixed.ladder.push(ladder(
        "Latch",
        "Motor",
        "VAR_INPUT Start : BOOL; END_VAR\nVAR_OUTPUT Motor : BOOL; END_VAR\n",
    ));
    mixed.petri.push(looping("TRUE", ""));
    assert_eq!(Lowerings::NONE.lacks(&mixed), ["ladder", "petri"]);
    assert!(Lowerings::ALL.lacks(&mixed).is_empty());
    let only_ladder = Lowerings { ladder: Lowerings::ALL.ladder, ..Lowerings::NONE };
    assert_eq!(only_ladder.lacks(&mixed), ["petri"]);
    assert!(same(&build_project_by(&mixed, &Lowerings::ALL), &build_project(&mixed)));
}

/// Textual SFC and Instruction List bodies need their passes (the page loads each the
/// first time a project has such a body); with both, the build is `build_project`'s.
#[test]
fn textual_sfc_and_il_bodies_name_the_text_passes_they_lack() {
    let sfc = project(
        "PROGRAM Main\nVAR go : BOOL; lamp : BOOL; END_VAR\nINITIAL_STEP Idle: END_STEP\n\
         TRANSITION FROM Idle TO Run := go; END_TRANSITION\nSTEP Run: lamp(N); END_STEP\n\
         TRANSITION FROM Run TO Idle := NOT go; END_TRANSITION\nEND_PROGRAM\n",
    );
    assert_eq!(Lowerings::NONE.lacks(&sfc), ["sfc"]);
    let il =
        project("PROGRAM Main\nVAR a : BOOL; b : BOOL; END_VAR\nLD a\nANDN b\nST b\nEND_PROGRAM\n");
    assert_eq!(Lowerings::NONE.lacks(&il), ["il"]);
    let with_sfc =
        Lowerings { text: TextPasses { sfc: TextPasses::ALL.sfc, il: None }, ..Lowerings::NONE };
    assert!(with_sfc.lacks(&sfc).is_empty());
    assert_eq!(with_sfc.lacks(&il), ["il"]);
    for p in [&sfc, &il] {
        assert!(Lowerings::ALL.lacks(p).is_empty());
        let (by, all) = (build_project_by(p, &Lowerings::ALL), build_project(p));
        assert!(!by.has_errors(), "{:?}", by.diagnostics);
        assert_eq!(by.diagnostics, all.diagnostics);
        assert!(by.program.is_some());
    }
}

#[test]
fn a_sites_message_is_its_english_place_and_is_translated() {
    use crate::i18n::Lang;
    use crate::petri::{TextPart, TextPosition};
    let pou = || "Latch".to_string();
    let at = |part| Some(TextPosition { part, line: 1, column: 2 });
    let mut sites = vec![
        Site::Ladder { pou: pou(), cell: Some((0, 0, 1)) },
        Site::Ladder { pou: pou(), cell: None },
        Site::Declarations { pou: pou(), line: 3, column: 8 },
        Site::Network { pou: pou(), element: Some("7".into()) },
        Site::Network { pou: pou(), element: None },
        Site::Petri { pou: pou(), element: None, at: None },
    ];
    let elements = [
        NetElement::Pou,
        NetElement::Declarations,
        NetElement::Prologue,
        NetElement::Epilogue,
        NetElement::Place("P1".into()),
        NetElement::Transition("T1".into()),
        NetElement::Arc(1),
        NetElement::MacroPlace("M".into()),
        NetElement::Process("Mix".into()),
        NetElement::Emergency,
    ];
    for e in elements {
        sites.push(Site::Petri { pou: pou(), element: Some(e.clone()), at: None });
        for part in [TextPart::Guard, TextPart::Actions, TextPart::Condition, TextPart::Text] {
            sites.push(Site::Petri { pou: pou(), element: Some(e.clone()), at: at(part) });
        }
    }
    for site in &sites {
        let said = site.message().unwrap();
        assert_eq!(Some(said.english.clone()), site.describe(), "{site:?}");
        assert_eq!(said.message.render(Lang::En), said.english, "{site:?}");
        assert!(said.message.render(Lang::Pl).starts_with("POU Latch"), "{site:?}");
    }
    assert_eq!(Site::Project.message(), None);
    let rung = Site::Ladder { pou: pou(), cell: Some((0, 0, 1)) }.message().unwrap();
    assert_eq!(rung.message.render(Lang::Pl), "POU Latch, szczebel 1, wiersz 1, kolumna 2");
    assert_eq!(rung.message.render(Lang::Cs), "POU Latch, příčka 1, řádek 1, sloupec 2");
    let guard = Site::Petri {
        pou: pou(),
        element: Some(NetElement::Transition("T1".into())),
        at: at(TextPart::Guard),
    };
    assert_eq!(
        guard.detail().unwrap().message.render(Lang::Cs),
        "přechod T1 (podmínka přechodu, řádek 1, sloupec 2)"
    );
}

#[test]
fn a_reported_problem_with_a_place_renders_place_and_message_in_the_language_asked_for() {
    use crate::i18n::Lang;
    let mut p = project("");
    p.ladder.push(ladder("Latch", "", DECLS));
    let options = crate::run::RunOptions { cycles: 0, ..Default::default() };
    let report = crate::run::run_project(&p, &options);
    let d = report.diagnostics.iter().find(|d| d.message.starts_with("POU Latch")).unwrap();
    assert!(d.message.starts_with("POU Latch, rung 1, row 1, column 2: "), "{d:?}");
    assert_eq!(d.render(Lang::En), d.message);
    let pl = d.render(Lang::Pl);
    assert!(pl.starts_with("POU Latch, szczebel 1, wiersz 1, kolumna 2: "), "{pl}");
    assert_ne!(pl, d.message);
    let cs = d.render(Lang::Cs);
    assert!(cs.starts_with("POU Latch, příčka 1, řádek 1, sloupec 2: "), "{cs}");
}
