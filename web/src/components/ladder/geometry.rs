//! Where a rung's parts go on screen, and which of its nodes carry power: pure functions of
//! the rung grid (and of the power leaving each element), tested natively.
//!
//! Columns holding a block are wider; rows grow so that a block's pin lines fit in the
//! rows it spans. A node is the left edge of a cell, joined to the node below by the cell's
//! vertical link, as in the core's power-flow network.

use plc_core::ladder::{Block, Element, Rung};

/// x of the left power rail.
pub const RAIL_X: f64 = 14.0;
/// Width of a column of contacts, coils and wires.
pub const CELL_W: f64 = 86.0;
/// Width of a column holding a block.
pub const BLOCK_W: f64 = 164.0;
/// The smallest row height.
pub const ROW_H: f64 = 58.0;
/// Vertical distance between two pin lines of a block.
pub const PIN_STEP: f64 = 15.0;
/// Where the wire of a row runs, as a fraction of the row's height from its top (room for
/// operand names above).
const WIRE_AT: f64 = 0.62;
/// Room above a block's first pin line for its type name.
const BLOCK_HEAD: f64 = 20.0;
/// Free space left and right of a block inside its column.
pub const BLOCK_MARGIN: f64 = 10.0;
/// Space after the grid for the right rail.
const RIGHT_GAP: f64 = 22.0;

/// What one line inside a block shows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PinLine {
    /// The power pins (`IN` … `Q`) on the block's first row.
    Power {
        /// The power input's name.
        input: String,
        /// The power output's name.
        output: String,
    },
    /// An input bound to an operand (index into `Block::inputs`).
    Input(usize),
    /// An output writing a variable (index into `Block::outputs`).
    Output(usize),
    /// A VAR_IN_OUT pin (index into `Block::in_outs`).
    InOut(usize),
    /// A live value of the instance that no pin shows (`ET`, `CV`).
    Instance(&'static str),
}

/// The instance outputs worth showing live for a standard FB type (`TON` → `ET`).
pub fn instance_values(type_name: &str) -> &'static [&'static str] {
    match type_name.trim().to_ascii_uppercase().as_str() {
        "TON" | "TOF" | "TP" | "RTO" => &["ET"],
        "CTU" | "CTD" | "CTUD" => &["CV"],
        _ => &[],
    }
}

/// The lines inside a block, top to bottom (wired inputs sit on their own rows instead).
pub fn pin_lines(block: &Block) -> Vec<PinLine> {
    let mut lines = vec![PinLine::Power {
        input: block.power_input().to_string(),
        output: block.power_output().to_string(),
    }];
    lines.extend(
        block
            .inputs
            .iter()
            .enumerate()
            .filter(|(_, p)| p.wired_row.is_none())
            .map(|(i, _)| PinLine::Input(i)),
    );
    lines.extend((0..block.in_outs.len()).map(PinLine::InOut));
    lines.extend((0..block.outputs.len()).map(PinLine::Output));
    if block.instance.is_some() {
        for name in instance_values(&block.type_name) {
            let shown = block.outputs.iter().any(|p| p.name.eq_ignore_ascii_case(name));
            if !shown {
                lines.push(PinLine::Instance(name));
            }
        }
    }
    lines
}

/// The positions of a rung's columns and rows.
#[derive(Debug, Clone, PartialEq)]
pub struct RungGeometry {
    /// x of the left edge of each column; one more entry for the right edge of the last.
    pub col_x: Vec<f64>,
    /// Height of every row.
    pub row_h: f64,
    /// Number of rows.
    pub rows: usize,
    /// x of the right power rail.
    pub right_rail_x: f64,
    /// Total width of the drawing.
    pub width: f64,
    /// Total height of the drawing.
    pub height: f64,
}

impl RungGeometry {
    /// y of the wire of `row`.
    pub fn wire_y(&self, row: usize) -> f64 {
        self.row_h * (row as f64 + WIRE_AT)
    }

    /// Left and right x of column `col` (clamped to the grid).
    pub fn col_span(&self, col: usize) -> (f64, f64) {
        let last = self.col_x.len().saturating_sub(1);
        let a = self.col_x.get(col.min(last)).copied().unwrap_or(RAIL_X);
        let b = self.col_x.get((col + 1).min(last)).copied().unwrap_or(a);
        (a, b)
    }

    /// The box of a block anchored at `(row, col)`: (left, top, right, bottom).
    pub fn block_box(&self, block: &Block, row: usize, col: usize) -> (f64, f64, f64, f64) {
        let (x0, x1) = self.col_span(col);
        let top = self.wire_y(row) - BLOCK_HEAD;
        let lines = pin_lines(block).len().max(1) as f64;
        let pins_bottom = self.wire_y(row) + (lines - 1.0) * PIN_STEP + 8.0;
        let rows_bottom = self.wire_y(row + block.height.max(1) as usize - 1) + 8.0;
        (x0 + BLOCK_MARGIN, top, x1 - BLOCK_MARGIN, pins_bottom.max(rows_bottom))
    }

    /// y of line `k` (0 = the power pins) inside a block anchored on `row`.
    pub fn pin_y(&self, row: usize, k: usize) -> f64 {
        self.wire_y(row) + k as f64 * PIN_STEP
    }
}

/// Lays out a rung.
pub fn rung_geometry(rung: &Rung) -> RungGeometry {
    let rows = rung.rows().max(1);
    let cols = rung.cells.iter().map(Vec::len).max().unwrap_or(0);
    let mut col_x = Vec::with_capacity(cols + 1);
    let mut x = RAIL_X;
    let mut row_h = ROW_H;
    for c in 0..cols {
        col_x.push(x);
        let mut width = CELL_W;
        for row in &rung.cells {
            if let Some(Element::Block(b)) = row.get(c).map(|cell| &cell.element) {
                width = BLOCK_W;
                // The block's pin lines must fit in the rows it spans.
                let h = b.height.max(1) as f64;
                let lines = pin_lines(b).len() as f64;
                let needed = ((lines - 1.0) * PIN_STEP + 14.0) / (h - WIRE_AT);
                row_h = row_h.max(needed.ceil());
            }
        }
        x += width;
    }
    col_x.push(x);
    let right_rail_x = x + RIGHT_GAP;
    RungGeometry {
        col_x,
        row_h,
        rows,
        right_rail_x,
        width: right_rail_x + RAIL_X,
        height: row_h * rows as f64,
    }
}

/// Whether an element has a power variable of its own (everything but empty and covered
/// cells).
pub fn has_power(element: &Element) -> bool {
    !matches!(element, Element::Empty | Element::Covered)
}

/// Which nodes of a rung carry power, given the power leaving each element
/// (`power(row, col)`, FALSE for cells without an element).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NodePower {
    /// Per column boundary `c` (0 = the left rail, up to the number of columns), per row.
    powered: Vec<Vec<bool>>,
}

impl NodePower {
    /// Computes the nodes' power.
    pub fn new(rung: &Rung, power: impl Fn(usize, usize) -> bool) -> Self {
        let rows = rung.rows();
        let cols = rung.cells.iter().map(Vec::len).max().unwrap_or(0);
        let mut powered = vec![vec![true; rows]];
        for c in 1..=cols {
            // Rows joined by vertical links at this boundary form one node.
            let mut column = vec![false; rows];
            let mut start = 0;
            while start < rows {
                let mut end = start;
                while end + 1 < rows && rung.cell(end, c).is_some_and(|cell| cell.link_down) {
                    end += 1;
                }
                let on = (start..=end).any(|r| {
                    rung.cell(r, c - 1).is_some_and(|cell| has_power(&cell.element))
                        && power(r, c - 1)
                });
                column[start..=end].iter_mut().for_each(|p| *p = on);
                start = end + 1;
            }
            powered.push(column);
        }
        NodePower { powered }
    }

    /// Whether the node at the left edge of cell `(row, col)` carries power (`col` may be
    /// the number of columns: the right edge of the grid).
    pub fn at(&self, row: usize, col: usize) -> bool {
        self.powered.get(col).and_then(|c| c.get(row)).copied().unwrap_or(false)
    }
}

/// Whether a row ends at a terminal element at `col` with nothing after it, so a wire is
/// drawn from it to the right rail.
pub fn runs_to_right_rail(rung: &Rung, row: usize, col: usize) -> bool {
    let Some(cells) = rung.cells.get(row) else { return false };
    let terminal = matches!(
        cells.get(col).map(|c| &c.element),
        Some(Element::Coil { .. } | Element::Jump { .. } | Element::Return)
    );
    terminal && cells[col + 1..].iter().all(|c| c.element == Element::Empty)
}

/// `text` cut to `max` characters with an ellipsis.
pub fn clip(text: &str, max: usize) -> String {
    if text.chars().count() <= max {
        text.to_string()
    } else {
        let mut s: String = text.chars().take(max.saturating_sub(1)).collect();
        s.push('…');
        s
    }
}

#[cfg(test)]
mod tests;
