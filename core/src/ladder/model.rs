//! The ladder diagram model behind the rung grid (serde, part of the project file).
//!
//! A rung is a grid of `rows × columns` cells. Power flows from the left rail through the
//! cells of a row; the node on the left edge of cell `(row, col)` is `(row, col)`, the left
//! rail is column 0, and an element in cell `(row, col)` connects node `(row, col)` to node
//! `(row, col + 1)`. A vertical link (`Cell::link_down`) joins node `(row, col)` to node
//! `(row + 1, col)`, so parallel branches open and close at column boundaries. A block
//! spans `height` rows from its anchor cell; the cells it covers below hold `Covered`.

use serde::{Deserialize, Serialize};

/// Default grid limits (seed 002's PLCSim: 8 rows × 10 columns), configurable per project.
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
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Block {
    /// The block type as named in ST (`TON`, `CTU`, `GT`, `ADD`, `MOVE`, `MyFb`).
    pub type_name: String,
    /// The instance variable for function blocks (`T1`); `None` for functions.
    #[serde(default)]
    pub instance: Option<String>,
    /// Rows the block spans (at least 1).
    pub height: u32,
    /// Input pins other than the power input, with their operands (`PT` ← `T#2s`).
    #[serde(default)]
    pub inputs: Vec<Pin>,
    /// Output pins other than the power output, with the variables they write (`ET` → `t1`).
    #[serde(default)]
    pub outputs: Vec<Pin>,
}

/// A block pin bound to an operand.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Pin {
    /// The formal parameter name (`PT`, `IN2`, `CV`).
    pub name: String,
    /// The operand: a variable, literal or direct address.
    pub operand: String,
}
