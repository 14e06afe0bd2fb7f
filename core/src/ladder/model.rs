//! The ladder diagram model behind the rung grid (serde, part of the project file).
//!
//! A rung is a grid of `rows × columns` cells. Power flows from the left rail through the
//! cells of a row; the node on the left edge of cell `(row, col)` is `(row, col)`, the left
//! rail is column 0, and an element in cell `(row, col)` connects node `(row, col)` to node
//! `(row, col + 1)`. A vertical link (`Cell::link_down`) joins node `(row, col)` to node
//! `(row + 1, col)`, so parallel branches open and close at column boundaries. A block
//! spans `height` rows from its anchor cell; the cells it covers below hold `Covered`.

use crate::syntax::Cmp;
use serde::{Deserialize, Serialize};

/// Default grid limits (the PLCSim thesis's simulator of GE Fanuc PLCs: 8 rows × 10
/// columns), configurable per project.
pub const DEFAULT_ROWS: u32 = 8;
/// Default number of columns of a rung.
pub const DEFAULT_COLUMNS: u32 = 10;

/// A ladder POU: declarations in ST syntax and a list of rungs.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LadderPou {
    /// The POU's name.
    pub name: String,
    /// PROGRAM or FUNCTION_BLOCK.
    pub kind: LadderPouKind,
    /// The variable declarations, as ST `VAR… END_VAR` blocks.
    pub declarations: String,
    /// The rungs, top to bottom.
    pub rungs: Vec<Rung>,
}

/// What kind of POU a ladder diagram is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum LadderPouKind {
    /// A PROGRAM.
    Program,
    /// A FUNCTION_BLOCK.
    FunctionBlock,
}

/// One rung: a comment, an optional label (a jump target) and a grid of cells.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Rung {
    /// The rung comment (kept in the ST view).
    #[serde(default)]
    pub comment: String,
    /// A label that jumps can target.
    #[serde(default)]
    pub label: Option<String>,
    /// Cells by row, then column; every row has the same length.
    pub cells: Vec<Vec<Cell>>,
}

impl Rung {
    /// An empty rung of `rows × columns` cells.
    pub fn new(rows: u32, columns: u32) -> Self {
        Rung {
            comment: String::new(),
            label: None,
            cells: vec![vec![Cell::default(); columns as usize]; rows as usize],
        }
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.cells.len()
    }

    /// Number of columns (of the first row).
    pub fn columns(&self) -> usize {
        self.cells.first().map_or(0, Vec::len)
    }

    /// The cell at `(row, col)`, if inside the grid.
    pub fn cell(&self, row: usize, col: usize) -> Option<&Cell> {
        self.cells.get(row)?.get(col)
    }
}

/// One grid cell.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Cell {
    /// What the cell holds.
    #[serde(default)]
    pub element: Element,
    /// A vertical link from this cell's left node down to the left node of the cell below.
    #[serde(default)]
    pub link_down: bool,
}

/// What a cell holds.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(tag = "type")]
pub enum Element {
    /// Nothing: an open circuit.
    #[default]
    Empty,
    /// A horizontal wire.
    Wire,
    /// A contact reading a BOOL operand.
    Contact {
        /// NO, NC, P or N.
        kind: ContactKind,
        /// The operand: a variable, member, element or direct address (`%IX0.0`).
        operand: String,
    },
    /// A coil writing a BOOL operand.
    Coil {
        /// Normal, negated, set, reset, rising or falling.
        kind: CoilKind,
        /// The operand.
        operand: String,
    },
    /// A function block or function spanning `height` rows.
    Block(Block),
    /// Part of a block anchored above.
    Covered,
    /// Jump to the rung labelled `label` when powered.
    Jump {
        /// The target label.
        label: String,
    },
    /// Return from the POU when powered.
    Return,
}

impl Element {
    /// The text a user types for the element: a contact's or coil's operand, a jump's
    /// label; `None` for elements without one.
    pub fn operand(&self) -> Option<&str> {
        match self {
            Element::Contact { operand, .. } | Element::Coil { operand, .. } => Some(operand),
            Element::Jump { label } => Some(label),
            _ => None,
        }
    }
}

/// Contact kinds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum ContactKind {
    /// Normally open `-| |-`.
    NormallyOpen,
    /// Normally closed `-|/|-`.
    NormallyClosed,
    /// Rising edge `-|P|-`.
    Rising,
    /// Falling edge `-|N|-`.
    Falling,
}

/// Coil kinds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum CoilKind {
    /// `-( )-`
    Normal,
    /// `-(/)-`
    Negated,
    /// `-(S)-` latch.
    Set,
    /// `-(R)-` unlatch.
    Reset,
    /// `-(P)-` pulse on a rising edge of power.
    Rising,
    /// `-(N)-` pulse on a falling edge of power.
    Falling,
}

/// A block in a rung: a standard FB (TON, CTU, …), an operation (ADD, GT, MOVE, …) or a user
/// FUNCTION_BLOCK / FUNCTION of the project.
///
/// Power enters the block at one input and leaves it at one output ([`Block::power_input`],
/// [`Block::power_output`]). When the power input is `EN`, the block runs only on scans where
/// power reaches it (IEC 61131-3 execution control): otherwise it is skipped, its outputs keep
/// their values and `ENO` is FALSE. When the power input is a BOOL input (`IN` of a timer),
/// the block runs on every scan with that input following the power.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Block {
    /// The block type as named in ST (`TON`, `CTU`, `GT`, `ADD`, `MOVE`, `MyFb`).
    pub type_name: String,
    /// The instance variable for function blocks (`T1`); `None` for functions.
    #[serde(default)]
    pub instance: Option<String>,
    /// Rows the block spans (at least 1).
    pub height: u32,
    /// Input pins other than the power input: bound to operands (`PT` ← `T#2s`) or wired to
    /// a contact network on one of the block's rows (`R` of a counter).
    #[serde(default)]
    pub inputs: Vec<Pin>,
    /// Output pins other than the power output, with the variables they write (`ET` → `t1`).
    #[serde(default)]
    pub outputs: Vec<Pin>,
    /// VAR_IN_OUT pins, with the variables passed to them.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub in_outs: Vec<Pin>,
    /// The input that takes the rung's power; `None` is the type's own: `IN`, `CU`, `CD`,
    /// `CLK`, `S1` or `S` for the standard FBs, `EN` for everything else.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub power_in: Option<String>,
    /// The output that carries power on; `None` is the type's own: `Q`, `QU` or `Q1` for the
    /// standard FBs, `OUT` for comparisons, `ENO` for everything else.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub power_out: Option<String>,
}

/// The standard FBs and the pins that carry power through them (IEC 61131-3: the first
/// BOOL input and the first BOOL output).
const STANDARD_FB_POWER: &[(&str, &str, &str)] = &[
    ("TON", "IN", "Q"),
    ("TOF", "IN", "Q"),
    ("TP", "IN", "Q"),
    ("RTO", "IN", "Q"),
    ("CTU", "CU", "Q"),
    ("CTD", "CD", "Q"),
    ("CTUD", "CU", "QU"),
    ("R_TRIG", "CLK", "Q"),
    ("F_TRIG", "CLK", "Q"),
    ("SR", "S1", "Q1"),
    ("RS", "S", "Q1"),
];

/// The power pins of a standard FB type (`TON` → `("IN", "Q")`), if it is one.
pub fn standard_fb_power(type_name: &str) -> Option<(&'static str, &'static str)> {
    STANDARD_FB_POWER
        .iter()
        .find(|(n, _, _)| n.eq_ignore_ascii_case(type_name.trim()))
        .map(|&(_, i, o)| (i, o))
}

/// Whether `type_name` is a comparison function (`GT`, `EQ`, …).
pub fn is_comparison(type_name: &str) -> bool {
    Cmp::from_function(type_name.trim()).is_some()
}

impl Block {
    /// A one-row block of `type_name` with an optional instance and no pins.
    pub fn new(type_name: &str, instance: Option<&str>) -> Self {
        Block {
            type_name: type_name.to_string(),
            instance: instance.map(str::to_string),
            height: 1,
            inputs: Vec::new(),
            outputs: Vec::new(),
            in_outs: Vec::new(),
            power_in: None,
            power_out: None,
        }
    }

    /// The input that takes the rung's power (`EN`, `IN`, `CU`, …).
    pub fn power_input(&self) -> &str {
        match &self.power_in {
            Some(p) if !p.trim().is_empty() => p.trim(),
            _ => standard_fb_power(&self.type_name).map_or("EN", |(i, _)| i),
        }
    }

    /// The output that carries power on (`ENO`, `Q`, `OUT`, …).
    pub fn power_output(&self) -> &str {
        match &self.power_out {
            Some(p) if !p.trim().is_empty() => p.trim(),
            _ => match standard_fb_power(&self.type_name) {
                Some((_, o)) => o,
                None if is_comparison(&self.type_name) => "OUT",
                None => "ENO",
            },
        }
    }

    /// Whether the block runs only when power reaches its `EN` input.
    pub fn has_enable(&self) -> bool {
        self.power_input().eq_ignore_ascii_case("EN")
    }
}

/// A block pin bound to an operand, or (inputs only) wired to a contact network.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Pin {
    /// The formal parameter name (`PT`, `IN2`, `CV`).
    pub name: String,
    /// The operand: a variable, literal or direct address; empty for a wired pin.
    #[serde(default)]
    pub operand: String,
    /// For a BOOL input driven by its own contact network, as CODESYS and OpenPLC draw the
    /// reset input of a counter: the block row (1 = the row below the block's top row, up to
    /// `height - 1`) whose left edge the network ends at. The pin then takes the power that
    /// reaches the left edge of the block on that row.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wired_row: Option<u32>,
}

impl Pin {
    /// A pin bound to an operand.
    pub fn operand(name: &str, operand: &str) -> Self {
        Pin { name: name.to_string(), operand: operand.to_string(), wired_row: None }
    }

    /// An input wired to the contact network ending on block row `row`.
    pub fn wired(name: &str, row: u32) -> Self {
        Pin { name: name.to_string(), operand: String::new(), wired_row: Some(row) }
    }
}
