use super::*;
use plc_core::ladder::{Block, Cell, CoilKind, ContactKind, Pin};

fn contact(op: &str, kind: ContactKind) -> Element {
    Element::Contact { kind, operand: op.into() }
}

fn cell(element: Element, link_down: bool) -> Cell {
    Cell { element, link_down }
}

/// The example latch: `Start` (row 0) parallel to `Motor` (row 1), then `NOT Stop`, then
/// the coil `Motor`; the branch closes at the left edge of column 1.
fn latch() -> Rung {
    let coil = Element::Coil { kind: CoilKind::Normal, operand: "Motor".into() };
    Rung {
        comment: String::new(),
        label: None,
        cells: vec![
            vec![
                cell(contact("Start", ContactKind::NormallyOpen), false),
                cell(contact("Stop", ContactKind::NormallyClosed), true),
                cell(coil, false),
            ],
            vec![
                cell(contact("Motor", ContactKind::NormallyOpen), false),
                cell(Element::Empty, false),
                cell(Element::Empty, false),
            ],
        ],
    }
}

#[test]
fn a_branch_node_is_powered_from_either_row() {
    let rung = latch();
    // Only the self-holding contact (row 1) conducts: the joined node of both rows at
    // column boundary 1 is powered, so is the node after `NOT Stop`.
    let power = |r: usize, c: usize| matches!((r, c), (1, 0) | (0, 1) | (0, 2));
    let nodes = NodePower::new(&rung, power);
    assert!(nodes.at(0, 0) && nodes.at(1, 0), "the rail");
    assert!(nodes.at(0, 1) && nodes.at(1, 1), "one node through the vertical link");
    assert!(nodes.at(0, 2) && nodes.at(0, 3));
    assert!(!nodes.at(1, 2), "nothing feeds the empty cell's right edge");
    let dark = NodePower::new(&rung, |_, _| false);
    assert!(!dark.at(0, 1) && !dark.at(1, 1) && !dark.at(0, 3));
    assert!(dark.at(1, 0), "the rail is always powered");
    assert!(!dark.at(5, 9), "outside the grid");
}

fn ton(outputs: Vec<Pin>) -> Block {
    Block {
        inputs: vec![Pin::operand("PT", "T#2s")],
        outputs,
        height: 2,
        ..Block::new("TON", Some("T1"))
    }
}

#[test]
fn block_lines_list_power_pins_operands_and_live_instance_values() {
    let lines = pin_lines(&ton(Vec::new()));
    assert_eq!(
        lines,
        vec![
            PinLine::Power { input: "IN".into(), output: "Q".into() },
            PinLine::Input(0),
            PinLine::Instance("ET"),
        ]
    );
    // ET written to a variable is shown by its pin, not twice.
    let lines = pin_lines(&ton(vec![Pin::operand("ET", "t1")]));
    assert_eq!(lines.last(), Some(&PinLine::Output(0)));
    assert!(!lines.contains(&PinLine::Instance("ET")));
    // A wired reset input sits on its own row, not among the lines.
    let mut ctu = Block::new("CTU", Some("C1"));
    ctu.height = 2;
    ctu.inputs = vec![Pin::wired("R", 1), Pin::operand("PV", "5")];
    assert_eq!(pin_lines(&ctu)[1..], [PinLine::Input(1), PinLine::Instance("CV")]);
    assert_eq!(
        pin_lines(&Block::new("ADD", None))[0],
        PinLine::Power { input: "EN".into(), output: "ENO".into() }
    );
}

#[test]
fn block_columns_are_wider_and_rows_grow_to_fit_pins() {
    let mut rung = latch();
    let geo = rung_geometry(&rung);
    assert_eq!(
        geo.col_x,
        vec![RAIL_X, RAIL_X + CELL_W, RAIL_X + 2.0 * CELL_W, RAIL_X + 3.0 * CELL_W]
    );
    assert_eq!(geo.row_h, ROW_H);
    assert_eq!(geo.height, 2.0 * ROW_H);
    assert!(geo.right_rail_x > geo.col_x[3]);

    // A one-row block with five lines needs (4 pin steps + 14 px) below 38 % of the row.
    let mut add = Block::new("ADD", Some("x"));
    add.inputs = vec![Pin::operand("IN1", "a"), Pin::operand("IN2", "b")];
    add.outputs = vec![Pin::operand("OUT", "c"), Pin::operand("X", "d")];
    rung.cells[0][1] = cell(Element::Block(add.clone()), true);
    let geo = rung_geometry(&rung);
    assert_eq!(geo.col_x[2] - geo.col_x[1], BLOCK_W);
    let expected = ((4.0 * PIN_STEP + 14.0) / (1.0 - 0.62_f64)).ceil();
    assert_eq!(geo.row_h, expected);
    let (left, top, right, bottom) = geo.block_box(&add, 0, 1);
    assert_eq!((left, right), (geo.col_x[1] + BLOCK_MARGIN, geo.col_x[2] - BLOCK_MARGIN));
    assert!(top < geo.wire_y(0) && bottom >= geo.pin_y(0, 4));
    assert!(bottom <= geo.row_h, "the block stays inside its row");
}

#[test]
fn coils_get_a_wire_to_the_right_rail_only_at_the_end_of_their_row() {
    let rung = latch();
    assert!(runs_to_right_rail(&rung, 0, 2));
    assert!(!runs_to_right_rail(&rung, 0, 1), "a contact is not terminal");
    assert!(!runs_to_right_rail(&rung, 1, 0));
    assert!(!runs_to_right_rail(&rung, 7, 0), "outside the grid");
}

#[test]
fn long_operands_are_clipped() {
    assert_eq!(clip("Start", 8), "Start");
    assert_eq!(clip("VeryLongName", 8), "VeryLon…");
    assert_eq!(clip("čččččččččč", 3), "čč…");
}
