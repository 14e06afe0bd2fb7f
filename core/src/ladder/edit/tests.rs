#![allow(clippy::unwrap_used)]

use super::*;
use crate::ladder::model::{CoilKind, ContactKind, LadderPouKind};
use crate::ladder::validate;
use crate::project::History;
use proptest::prelude::*;

fn empty(rows: u32, columns: u32) -> LadderPou {
    LadderPou {
        name: "Main".into(),
        kind: LadderPouKind::Program,
        declarations: String::new(),
        rungs: vec![Rung::new(rows, columns)],
    }
}

fn at(rung: usize, row: usize, col: usize) -> CellRef {
    CellRef::new(rung, row, col)
}

fn no(op: &str) -> Element {
    Element::Contact { kind: ContactKind::NormallyOpen, operand: op.into() }
}

fn nc(op: &str) -> Element {
    Element::Contact { kind: ContactKind::NormallyClosed, operand: op.into() }
}

fn coil(op: &str) -> Element {
    Element::Coil { kind: CoilKind::Normal, operand: op.into() }
}

fn ton(instance: &str, height: u32) -> Element {
    let mut b = Block::new("TON", Some(instance));
    b.height = height;
    Element::Block(b)
}

fn apply_all(mut pou: LadderPou, edits: &[LadderEdit]) -> LadderPou {
    for e in edits {
        pou = pou.apply(e).unwrap_or_else(|err| panic!("{e:?}: {err}"));
    }
    pou
}

#[test]
fn the_start_stop_latch_is_built_by_edits_and_validates() {
    let pou = apply_all(
        empty(2, 4),
        &[
            LadderEdit::SetDeclarations {
                text: "VAR_INPUT Start, Stop : BOOL; END_VAR VAR_OUTPUT Motor : BOOL; END_VAR"
                    .into(),
            },
            LadderEdit::Place { at: at(0, 0, 0), element: no("") },
            LadderEdit::SetOperand { at: at(0, 0, 0), operand: " Start ".into() },
            LadderEdit::Place { at: at(0, 0, 1), element: nc("Stop") },
            LadderEdit::Place { at: at(0, 0, 2), element: Element::Wire },
            LadderEdit::Place { at: at(0, 0, 3), element: coil("Motor") },
            LadderEdit::Place { at: at(0, 1, 0), element: no("Motor") },
            LadderEdit::ToggleLinkDown { at: at(0, 0, 1) },
        ],
    );
    assert_eq!(pou.rungs[0].cells[0][0].element, no("Start"), "operands are trimmed");
    assert!(pou.rungs[0].cells[0][1].link_down);
    let errors: Vec<_> = validate(&pou).into_iter().filter(|d| d.is_error()).collect();
    assert!(errors.is_empty(), "{errors:?}");
    assert_eq!(describe_cell(&pou.rungs[0].cells[0][1]), "NC contact Stop, linked down");
    assert_eq!(describe_cell(&pou.rungs[0].cells[1][1]), "empty");
}

#[test]
fn a_block_claims_its_footprint_and_releases_it_when_moved_or_cleared() {
    let pou = empty(4, 4).apply(&LadderEdit::Place { at: at(0, 0, 1), element: ton("T1", 2) });
    let pou = pou.unwrap();
    assert_eq!(pou.rungs[0].cells[1][1].element, Element::Covered);
    assert_eq!(describe_cell(&pou.rungs[0].cells[0][1]), "TON T1");
    assert_eq!(describe_cell(&pou.rungs[0].cells[1][1]), "covered");
    // Nothing goes onto a covered cell; the block itself can move one row down over it.
    let onto = pou.apply(&LadderEdit::Place { at: at(0, 1, 1), element: no("x") });
    assert_eq!(onto, Err(EditError::CoveredByBlock(at(0, 1, 1))));
    let down = pou.apply(&LadderEdit::Move { from: at(0, 1, 1), to: at(0, 1, 1) }).unwrap();
    assert_eq!(down.rungs[0].cells[0][1].element, Element::Empty);
    assert!(matches!(down.rungs[0].cells[1][1].element, Element::Block(_)));
    assert_eq!(down.rungs[0].cells[2][1].element, Element::Covered);
    // Too tall for the rows left, or onto taken cells: refused, nothing changes.
    let low = down.apply(&LadderEdit::Move { from: at(0, 1, 1), to: at(0, 3, 0) });
    assert_eq!(low, Err(EditError::BlockDoesNotFit { at: at(0, 3, 0), height: 2 }));
    let taken = down.apply(&LadderEdit::Place { at: at(0, 2, 0), element: no("a") }).unwrap();
    let blocked = taken.apply(&LadderEdit::Copy { from: at(0, 1, 1), to: at(0, 1, 0) });
    assert_eq!(blocked, Err(EditError::BlockDoesNotFit { at: at(0, 1, 0), height: 2 }));
    // Clearing a covered cell clears the whole block.
    let cleared = down.apply(&LadderEdit::Clear { at: at(0, 2, 1) }).unwrap();
    assert!(cleared.rungs[0].cells.iter().flatten().all(|c| c.element == Element::Empty));
}

#[test]
fn blocks_resize_take_pins_and_instances() {
    let pou = empty(3, 3).apply(&LadderEdit::Place { at: at(0, 0, 0), element: ton("T1", 1) });
    let pou = apply_all(
        pou.unwrap(),
        &[
            LadderEdit::ResizeBlock { at: at(0, 0, 0), height: 3 },
            LadderEdit::SetPin {
                at: at(0, 2, 0),
                kind: PinKind::Input,
                pin: "PT".into(),
                operand: "T#2s".into(),
            },
            LadderEdit::SetPin {
                at: at(0, 0, 0),
                kind: PinKind::Output,
                pin: "ET".into(),
                operand: "elapsed".into(),
            },
            LadderEdit::SetOperand { at: at(0, 1, 0), operand: "Delay".into() },
        ],
    );
    let Element::Block(b) = &pou.rungs[0].cells[0][0].element else { panic!() };
    assert_eq!((b.height, b.instance.as_deref()), (3, Some("Delay")));
    assert_eq!(b.inputs, vec![Pin::operand("PT", "T#2s")]);
    assert_eq!(b.outputs, vec![Pin::operand("ET", "elapsed")]);
    assert_eq!(pou.rungs[0].cells[2][0].element, Element::Covered);
    let shorter = pou.apply(&LadderEdit::ResizeBlock { at: at(0, 0, 0), height: 1 }).unwrap();
    assert_eq!(shorter.rungs[0].cells[1][0].element, Element::Empty);
    let unbound = pou
        .apply(&LadderEdit::SetPin {
            at: at(0, 0, 0),
            kind: PinKind::Input,
            pin: "pt".into(),
            operand: String::new(),
        })
        .unwrap();
    let Element::Block(b) = &unbound.rungs[0].cells[0][0].element else { panic!() };
    assert!(b.inputs.is_empty());
    // A pin wired to a row the block would lose keeps the block tall.
    let mut wired = pou.clone();
    if let Element::Block(b) = &mut wired.rungs[0].cells[0][0].element {
        b.inputs.push(Pin::wired("R", 2));
    }
    let e = wired.apply(&LadderEdit::ResizeBlock { at: at(0, 0, 0), height: 2 }).unwrap_err();
    assert_eq!(e, EditError::PinOnRow { pin: "R".into(), row: 2 });
    let no_operand = pou.apply(&LadderEdit::SetOperand { at: at(0, 0, 2), operand: "x".into() });
    assert_eq!(no_operand, Err(EditError::NoOperand(at(0, 0, 2))));
}

#[test]
fn rows_columns_and_rungs() {
    let pou = empty(2, 3).apply(&LadderEdit::Place { at: at(0, 0, 1), element: ton("T1", 2) });
    let pou = pou.unwrap();
    assert_eq!(
        pou.apply(&LadderEdit::InsertRow { rung: 0, row: 1 }),
        Err(EditError::CutsThroughBlock(at(0, 1, 1)))
    );
    assert_eq!(
        pou.apply(&LadderEdit::DeleteRow { rung: 0, row: 0 }),
        Err(EditError::CutsThroughBlock(at(0, 0, 1)))
    );
    let grown = apply_all(
        pou.clone(),
        &[
            LadderEdit::InsertRow { rung: 0, row: 2 },
            LadderEdit::InsertColumn { rung: 0, col: 0 },
            LadderEdit::InsertColumn { rung: 0, col: 4 },
            LadderEdit::SetComment { rung: 0, text: "Timer".into() },
            LadderEdit::SetLabel { rung: 0, label: Some("  ".into()) },
        ],
    );
    assert_eq!((grown.rungs[0].rows(), grown.rungs[0].columns()), (3, 5));
    assert!(matches!(grown.rungs[0].cells[0][2].element, Element::Block(_)));
    assert_eq!(grown.rungs[0].label, None, "a blank label is no label");
    let mut linked = apply_all(
        empty(2, 1),
        &[
            LadderEdit::ToggleLinkDown { at: at(0, 0, 0) },
            LadderEdit::DeleteRow { rung: 0, row: 1 },
        ],
    );
    assert!(!linked.rungs[0].cells[0][0].link_down, "no link down from the last row");
    assert_eq!(
        linked.apply(&LadderEdit::DeleteColumn { rung: 0, col: 0 }),
        Err(EditError::LastOne("column"))
    );
    assert_eq!(linked.apply(&LadderEdit::DeleteRung { index: 0 }), Err(EditError::LastOne("rung")));
    linked = apply_all(
        linked,
        &[
            LadderEdit::InsertRung { index: 1, rung: Rung::new(1, 1) },
            LadderEdit::SetComment { rung: 1, text: "second".into() },
            LadderEdit::MoveRung { from: 1, to: 0 },
        ],
    );
    assert_eq!(linked.rungs[0].comment, "second");
    let one = linked.apply(&LadderEdit::DeleteRung { index: 0 }).unwrap();
    assert_eq!((one.rungs.len(), one.rungs[0].comment.as_str()), (1, ""));
    assert_eq!(one.apply(&LadderEdit::DeleteRung { index: 5 }), Err(EditError::NoSuchRung(5)));
    assert_eq!(
        one.apply(&LadderEdit::Place { at: at(0, 3, 0), element: Element::Wire }),
        Err(EditError::OutsideGrid(at(0, 3, 0)))
    );
    assert_eq!(
        EditError::OutsideGrid(at(0, 3, 0)).to_string(),
        "rung 1, row 4, column 1 is outside the rung's grid"
    );
}

#[test]
fn fresh_instances_skip_declared_and_used_names() {
    let mut pou = empty(1, 3);
    pou.declarations = "VAR T1 : TON; t2, Other : TON; END_VAR".into();
    let pou = pou.apply(&LadderEdit::Place { at: at(0, 0, 0), element: ton("T3", 1) }).unwrap();
    assert_eq!(pou.fresh_instance("T"), "T4");
    assert_eq!(pou.fresh_instance("C"), "C1");
}

/// What an editor keeps for undo: the POU and the selected cell.
#[derive(Debug, Clone, PartialEq)]
struct EditorState {
    pou: LadderPou,
    selected: CellRef,
}

#[test]
fn twenty_mixed_edits_undo_and_redo_to_exact_states() {
    let edits = vec![
        LadderEdit::Place { at: at(0, 0, 0), element: no("Start") },
        LadderEdit::Place { at: at(0, 0, 1), element: nc("Stop") },
        LadderEdit::Place { at: at(0, 0, 3), element: coil("Motor") },
        LadderEdit::Place { at: at(0, 0, 2), element: Element::Wire },
        LadderEdit::Place { at: at(0, 1, 0), element: no("Motor") },
        LadderEdit::ToggleLinkDown { at: at(0, 0, 1) },
        LadderEdit::SetComment { rung: 0, text: "Latch".into() },
        LadderEdit::InsertRung { index: 1, rung: Rung::new(3, 4) },
        LadderEdit::Place { at: at(1, 0, 1), element: ton("T1", 2) },
        LadderEdit::SetPin {
            at: at(1, 0, 1),
            kind: PinKind::Input,
            pin: "PT".into(),
            operand: "T#2s".into(),
        },
        LadderEdit::Place { at: at(1, 0, 0), element: no("Motor") },
        LadderEdit::Place { at: at(1, 0, 3), element: coil("Lamp") },
        LadderEdit::Move { from: at(1, 1, 1), to: at(1, 1, 2) },
        LadderEdit::Copy { from: at(0, 0, 0), to: at(0, 1, 2) },
        LadderEdit::SetOperand { at: at(0, 1, 2), operand: "Jog".into() },
        LadderEdit::InsertColumn { rung: 0, col: 4 },
        LadderEdit::Clear { at: at(0, 1, 2) },
        LadderEdit::SetLabel { rung: 1, label: Some("Timer".into()) },
        LadderEdit::MoveRung { from: 1, to: 0 },
        LadderEdit::SetDeclarations { text: "VAR T1 : TON; END_VAR".into() },
    ];
    assert_eq!(edits.len(), 20);
    let mut history = History::default();
    let mut state = EditorState { pou: empty(2, 4), selected: at(0, 0, 0) };
    let mut seen = vec![state.clone()];
    for (i, e) in edits.iter().enumerate() {
        let next = EditorState {
            pou: state.pou.apply(e).unwrap_or_else(|err| panic!("{e:?}: {err}")),
            selected: at(0, i % 2, i % 4),
        };
        history.record(state);
        state = next;
        seen.push(state.clone());
    }
    for expected in seen.iter().rev().skip(1) {
        state = history.undo(state).unwrap();
        assert_eq!(&state, expected);
    }
    assert!(!history.can_undo());
    for expected in seen.iter().skip(1) {
        state = history.redo(state).unwrap();
        assert_eq!(&state, expected);
    }
}

/// Every covered cell lies under a block anchor whose height reaches it.
fn footprints_hold(pou: &LadderPou) -> bool {
    pou.rungs.iter().all(|rung| {
        (0..rung.columns()).all(|col| {
            let mut owed = 0u32;
            (0..rung.rows()).all(|row| {
                let element = &rung.cells[row][col].element;
                let ok = match element {
                    Element::Covered => owed > 0,
                    _ => owed == 0,
                };
                owed = match element {
                    Element::Block(b) => b.height.max(1) - 1,
                    Element::Covered => owed - 1,
                    _ => 0,
                };
                ok
            }) && owed == 0
        })
    })
}

fn any_edit() -> impl Strategy<Value = LadderEdit> {
    let cell = (0usize..2, 0usize..4, 0usize..4).prop_map(|(r, row, col)| at(r, row, col));
    let element = prop_oneof![
        Just(Element::Empty),
        Just(Element::Wire),
        Just(no("a")),
        Just(coil("q")),
        (1u32..4).prop_map(|h| ton("T1", h)),
    ];
    prop_oneof![
        (cell.clone(), element).prop_map(|(at, element)| LadderEdit::Place { at, element }),
        (cell.clone(), cell.clone()).prop_map(|(from, to)| LadderEdit::Move { from, to }),
        (cell.clone(), cell.clone()).prop_map(|(from, to)| LadderEdit::Copy { from, to }),
        cell.clone().prop_map(|at| LadderEdit::Clear { at }),
        cell.clone().prop_map(|at| LadderEdit::ToggleLinkDown { at }),
        (cell.clone(), 0u32..5).prop_map(|(at, height)| LadderEdit::ResizeBlock { at, height }),
        (0usize..2, 0usize..5).prop_map(|(rung, row)| LadderEdit::InsertRow { rung, row }),
        (0usize..2, 0usize..5).prop_map(|(rung, row)| LadderEdit::DeleteRow { rung, row }),
        (0usize..2, 0usize..5).prop_map(|(rung, col)| LadderEdit::DeleteColumn { rung, col }),
        (0usize..3).prop_map(|index| LadderEdit::InsertRung { index, rung: Rung::new(3, 3) }),
        (0usize..3).prop_map(|index| LadderEdit::DeleteRung { index }),
        (0usize..3, 0usize..3).prop_map(|(from, to)| LadderEdit::MoveRung { from, to }),
    ]
}

proptest! {
    #[test]
    fn no_edit_sequence_panics_or_breaks_a_block_footprint(
        edits in proptest::collection::vec(any_edit(), 1..40)
    ) {
        let mut pou = empty(4, 4);
        pou.rungs.push(Rung::new(4, 4));
        for e in &edits {
            match pou.apply(e) {
                Ok(next) => {
                    prop_assert!(footprints_hold(&next), "after {:?}: {:?}", e, next.rungs);
                    pou = next;
                }
                Err(err) => prop_assert!(!err.to_string().is_empty()),
            }
        }
    }
}

#[test]
fn declarations_get_new_variables_in_the_right_block() {
    let text = "VAR_INPUT\n    Start : BOOL;\nEND_VAR\nVAR\nEND_VAR\n";
    let one = declare(text, "VAR", "T1", "TON");
    assert_eq!(one, "VAR_INPUT\n    Start : BOOL;\nEND_VAR\nVAR\n    T1 : TON;\nEND_VAR\n");
    assert_eq!(declare(&one, "VAR", "t1", "TON"), one, "declared already");
    let out = declare(&one, "VAR_OUTPUT", "Lamp", "BOOL");
    assert!(out.ends_with("VAR_OUTPUT\n    Lamp : BOOL;\nEND_VAR\n"), "{out}");
    assert_eq!(declare("", "VAR", "x", "INT"), "VAR\n    x : INT;\nEND_VAR\n");
}

#[test]
fn an_undeclared_operand_implies_its_declaration() {
    let pou = apply_all(
        empty(1, 3),
        &[
            LadderEdit::Place { at: at(0, 0, 0), element: no("Start") },
            LadderEdit::Place { at: at(0, 0, 1), element: ton("T1", 1) },
            LadderEdit::Place { at: at(0, 0, 2), element: coil("Lamp") },
        ],
    );
    assert_eq!(implied_declaration(&pou, at(0, 0, 0), "start"), Some(("VAR_INPUT", "BOOL".into())));
    assert_eq!(implied_declaration(&pou, at(0, 0, 1), "T1"), Some(("VAR", "TON".into())));
    assert_eq!(implied_declaration(&pou, at(0, 0, 2), "Lamp"), Some(("VAR_OUTPUT", "BOOL".into())));
    assert_eq!(implied_declaration(&pou, at(0, 0, 2), "Other"), None);
    let member = empty(1, 1).apply(&LadderEdit::Place { at: at(0, 0, 0), element: no("T1.Q") });
    assert_eq!(
        implied_declaration(&member.unwrap(), at(0, 0, 0), "T1"),
        None,
        "a member implies no type"
    );
}

#[test]
fn a_misspelled_operand_is_replaced_by_the_name_suggested() {
    let mut pou = apply_all(
        empty(1, 3),
        &[
            LadderEdit::Place { at: at(0, 0, 0), element: no("Strat") },
            LadderEdit::Place { at: at(0, 0, 1), element: ton("T11", 1) },
            LadderEdit::Place { at: at(0, 0, 2), element: coil("Tmr.Q") },
        ],
    );
    let fix = replace_name(&pou, at(0, 0, 0), "strat", "Start").unwrap();
    assert_eq!(fix, LadderEdit::SetOperand { at: at(0, 0, 0), operand: "Start".into() });
    let fix = replace_name(&pou, at(0, 0, 2), "Tmr", "T1").unwrap();
    assert_eq!(fix, LadderEdit::SetOperand { at: at(0, 0, 2), operand: "T1.Q".into() });
    let fix = replace_name(&pou, at(0, 0, 1), "T11", "T1").unwrap();
    assert_eq!(fix, LadderEdit::SetOperand { at: at(0, 0, 1), operand: "T1".into() });
    pou = pou
        .apply(&LadderEdit::SetPin {
            at: at(0, 0, 1),
            kind: PinKind::Input,
            pin: "PT".into(),
            operand: "Dealy".into(),
        })
        .unwrap();
    let fix = replace_name(&pou, at(0, 0, 1), "Dealy", "Delay").unwrap();
    assert_eq!(
        fix,
        LadderEdit::SetPin {
            at: at(0, 0, 1),
            kind: PinKind::Input,
            pin: "PT".into(),
            operand: "Delay".into()
        }
    );
    let fixed = pou.apply(&fix).unwrap();
    assert_eq!(replace_name(&fixed, at(0, 0, 1), "Dealy", "Delay"), None, "nothing left to fix");
    assert_eq!(replace_name(&pou, at(0, 0, 0), "Other", "X"), None);
}
