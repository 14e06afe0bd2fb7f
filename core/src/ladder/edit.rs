//! Editing a ladder POU: every change a user makes in the rung grid is one [`LadderEdit`],
//! applied by [`LadderPou::apply`] to give the new POU or a typed [`EditError`]. An edit
//! either applies whole or not at all (it works on a copy), so an editor can keep whole
//! states in a [`History`](crate::project::History) and undo is exact.
//!
//! Blocks span `height` rows from their anchor cell; the cells below hold
//! [`Element::Covered`]. Edits keep that invariant: placing a block claims its footprint,
//! clearing or moving it releases it, and row edits never cut through a block.

use std::fmt;

use super::model::{Block, Cell, Element, LadderPou, Pin, Rung};

/// A cell of a ladder POU: rung, row and column, all 0-based.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct CellRef {
    /// The rung (0 = the first).
    pub rung: usize,
    /// The row in the rung.
    pub row: usize,
    /// The column in the row.
    pub col: usize,
}

impl CellRef {
    /// The cell at `(rung, row, col)`.
    pub fn new(rung: usize, row: usize, col: usize) -> Self {
        CellRef { rung, row, col }
    }
}

/// Which list of a block's pins a pin belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PinKind {
    /// An input (`PT`, `IN2`).
    Input,
    /// An output (`ET`, `CV`).
    Output,
    /// A VAR_IN_OUT.
    InOut,
}

/// One change to a ladder POU.
#[derive(Debug, Clone, PartialEq)]
pub enum LadderEdit {
    /// Puts an element into a cell, replacing what is there (a block claims the cells below
    /// it for its height; the cell's vertical link stays).
    Place {
        /// The cell (a block's anchor).
        at: CellRef,
        /// What to put there.
        element: Element,
    },
    /// Sets the operand of a contact or coil, the label of a jump, or the instance of a block.
    SetOperand {
        /// The element's cell (any cell of a block).
        at: CellRef,
        /// The new operand.
        operand: String,
    },
    /// Moves an element (a block with its footprint) to another cell.
    Move {
        /// Where it is.
        from: CellRef,
        /// Where it goes (the anchor for a block).
        to: CellRef,
    },
    /// Copies an element to another cell.
    Copy {
        /// Where it is.
        from: CellRef,
        /// Where the copy goes.
        to: CellRef,
    },
    /// Empties a cell (a block: its whole footprint).
    Clear {
        /// The cell.
        at: CellRef,
    },
    /// Toggles the vertical link from a cell's left node down to the row below.
    ToggleLinkDown {
        /// The cell.
        at: CellRef,
    },
    /// Inserts an empty row before `row` (`row` = the row count appends one).
    InsertRow {
        /// The rung.
        rung: usize,
        /// The new row's index.
        row: usize,
    },
    /// Deletes a row.
    DeleteRow {
        /// The rung.
        rung: usize,
        /// The row.
        row: usize,
    },
    /// Inserts an empty column before `col` in every row (`col` = the column count
    /// appends one).
    InsertColumn {
        /// The rung.
        rung: usize,
        /// The new column's index.
        col: usize,
    },
    /// Deletes a column from every row.
    DeleteColumn {
        /// The rung.
        rung: usize,
        /// The column.
        col: usize,
    },
    /// Inserts a rung before `index` (`index` = the rung count appends it).
    InsertRung {
        /// Where it goes.
        index: usize,
        /// The rung (an empty one, or one copied earlier).
        rung: Rung,
    },
    /// Deletes a rung (not the only one).
    DeleteRung {
        /// The rung.
        index: usize,
    },
    /// Moves a rung so that it ends up at index `to`.
    MoveRung {
        /// The rung's index now.
        from: usize,
        /// Its index afterwards.
        to: usize,
    },
    /// Changes how many rows a block spans.
    ResizeBlock {
        /// Any cell of the block.
        at: CellRef,
        /// The new height (at least 1).
        height: u32,
    },
    /// Binds a block pin to an operand (an empty operand removes the binding).
    SetPin {
        /// Any cell of the block.
        at: CellRef,
        /// Which list the pin is in.
        kind: PinKind,
        /// The pin (`PT`).
        pin: String,
        /// What it is bound to (`T#2s`).
        operand: String,
    },
    /// Sets a rung's comment.
    SetComment {
        /// The rung.
        rung: usize,
        /// The comment.
        text: String,
    },
    /// Sets or removes a rung's label (a jump target).
    SetLabel {
        /// The rung.
        rung: usize,
        /// The label, or `None`.
        label: Option<String>,
    },
    /// Replaces the POU's declarations (ST `VAR … END_VAR` blocks).
    SetDeclarations {
        /// The text.
        text: String,
    },
}

/// Why an edit cannot be applied.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum EditError {
    /// No rung with that index.
    NoSuchRung(usize),
    /// The cell is outside its rung's grid.
    OutsideGrid(CellRef),
    /// A block needs more rows below its anchor than the rung has, or the cells it would
    /// cover are taken.
    BlockDoesNotFit {
        /// The anchor.
        at: CellRef,
        /// The rows it needs.
        height: u32,
    },
    /// The row edit would cut through a block.
    CutsThroughBlock(CellRef),
    /// The cell holds nothing that has an operand (or pins, for pin edits).
    NoOperand(CellRef),
    /// The cell is covered by a block above it: the block has to move or shrink first.
    CoveredByBlock(CellRef),
    /// The only row, column or rung cannot be deleted.
    LastOne(&'static str),
    /// A pin wired to a contact network on a block row the block would no longer have.
    PinOnRow {
        /// The pin.
        pin: String,
        /// Its block row.
        row: u32,
    },
}

impl fmt::Display for EditError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let cell =
            |c: &CellRef| format!("rung {}, row {}, column {}", c.rung + 1, c.row + 1, c.col + 1);
        match self {
            EditError::NoSuchRung(r) => write!(f, "there is no rung {}", r + 1),
            EditError::OutsideGrid(c) => write!(f, "{} is outside the rung's grid", cell(c)),
            EditError::BlockDoesNotFit { at, height } => write!(
                f,
                "a block {height} rows high does not fit at {}: the cells below it must exist and be empty",
                cell(at)
            ),
            EditError::CutsThroughBlock(c) => {
                write!(f, "that would cut through the block at {}", cell(c))
            }
            EditError::NoOperand(c) => write!(f, "{} holds nothing with an operand", cell(c)),
            EditError::CoveredByBlock(c) => {
                write!(f, "{} is covered by the block above it", cell(c))
            }
            EditError::LastOne(what) => write!(f, "the only {what} cannot be deleted"),
            EditError::PinOnRow { pin, row } => write!(
                f,
                "pin {pin} is wired to block row {}: unwire it before making the block shorter",
                row + 1
            ),
        }
    }
}

impl std::error::Error for EditError {}

impl LadderPou {
    /// The POU after `edit`, or why it cannot be made.
    pub fn apply(&self, edit: &LadderEdit) -> Result<LadderPou, EditError> {
        let mut pou = self.clone();
        pou.apply_in_place(edit)?;
        Ok(pou)
    }

    fn apply_in_place(&mut self, edit: &LadderEdit) -> Result<(), EditError> {
        match edit {
            LadderEdit::Place { at, element } => {
                self.check_cell(*at)?;
                self.clear(*at)?;
                self.put(*at, element.clone())
            }
            LadderEdit::SetOperand { at, operand } => {
                let anchor = self.anchor(*at)?;
                let operand = operand.trim().to_string();
                match &mut self.cell_mut(anchor)?.element {
                    Element::Contact { operand: o, .. } | Element::Coil { operand: o, .. } => {
                        *o = operand
                    }
                    Element::Jump { label } => *label = operand,
                    Element::Block(b) => {
                        b.instance = (!operand.is_empty()).then_some(operand);
                    }
                    _ => return Err(EditError::NoOperand(*at)),
                }
                Ok(())
            }
            LadderEdit::Move { from, to } => {
                let anchor = self.anchor(*from)?;
                let element = self.cell_at(anchor)?.element.clone();
                self.clear(anchor)?;
                self.check_cell(*to)?;
                self.clear(*to)?;
                self.put(*to, element)
            }
            LadderEdit::Copy { from, to } => {
                let anchor = self.anchor(*from)?;
                let element = self.cell_at(anchor)?.element.clone();
                self.check_cell(*to)?;
                self.clear(*to)?;
                self.put(*to, element)
            }
            LadderEdit::Clear { at } => self.clear(*at),
            LadderEdit::ToggleLinkDown { at } => {
                let cell = self.cell_mut(*at)?;
                cell.link_down = !cell.link_down;
                Ok(())
            }
            LadderEdit::InsertRow { rung, row } => self.insert_row(*rung, *row),
            LadderEdit::DeleteRow { rung, row } => self.delete_row(*rung, *row),
            LadderEdit::InsertColumn { rung, col } => {
                let r = self.rung_mut(*rung)?;
                if *col > r.columns() {
                    return Err(EditError::OutsideGrid(CellRef::new(*rung, 0, *col)));
                }
                for cells in &mut r.cells {
                    cells.insert(*col, Cell::default());
                }
                Ok(())
            }
            LadderEdit::DeleteColumn { rung, col } => {
                let r = self.rung_mut(*rung)?;
                if *col >= r.columns() {
                    return Err(EditError::OutsideGrid(CellRef::new(*rung, 0, *col)));
                }
                if r.columns() == 1 {
                    return Err(EditError::LastOne("column"));
                }
                for cells in &mut r.cells {
                    cells.remove(*col);
                }
                Ok(())
            }
            LadderEdit::InsertRung { index, rung } => {
                if *index > self.rungs.len() {
                    return Err(EditError::NoSuchRung(*index));
                }
                self.rungs.insert(*index, rung.clone());
                Ok(())
            }
            LadderEdit::DeleteRung { index } => {
                self.rung_mut(*index)?;
                if self.rungs.len() == 1 {
                    return Err(EditError::LastOne("rung"));
                }
                self.rungs.remove(*index);
                Ok(())
            }
            LadderEdit::MoveRung { from, to } => {
                self.rung_mut(*from)?;
                self.rung_mut(*to)?;
                let rung = self.rungs.remove(*from);
                self.rungs.insert(*to, rung);
                Ok(())
            }
            LadderEdit::ResizeBlock { at, height } => self.resize_block(*at, (*height).max(1)),
            LadderEdit::SetPin { at, kind, pin, operand } => {
                let anchor = self.anchor(*at)?;
                let Element::Block(block) = &mut self.cell_mut(anchor)?.element else {
                    return Err(EditError::NoOperand(*at));
                };
                set_pin(block, *kind, pin.trim(), operand.trim());
                Ok(())
            }
            LadderEdit::SetComment { rung, text } => {
                self.rung_mut(*rung)?.comment = text.clone();
                Ok(())
            }
            LadderEdit::SetLabel { rung, label } => {
                let label = label.as_deref().map(str::trim).filter(|l| !l.is_empty());
                self.rung_mut(*rung)?.label = label.map(str::to_string);
                Ok(())
            }
            LadderEdit::SetDeclarations { text } => {
                self.declarations = text.clone();
                Ok(())
            }
        }
    }

    fn rung_mut(&mut self, index: usize) -> Result<&mut Rung, EditError> {
        self.rungs.get_mut(index).ok_or(EditError::NoSuchRung(index))
    }

    /// The cell at `at`, if the POU has it.
    pub fn cell(&self, at: CellRef) -> Option<&Cell> {
        self.rungs.get(at.rung)?.cell(at.row, at.col)
    }

    fn cell_at(&self, at: CellRef) -> Result<&Cell, EditError> {
        let rung = self.rungs.get(at.rung).ok_or(EditError::NoSuchRung(at.rung))?;
        rung.cell(at.row, at.col).ok_or(EditError::OutsideGrid(at))
    }

    fn cell_mut(&mut self, at: CellRef) -> Result<&mut Cell, EditError> {
        let rung = self.rung_mut(at.rung)?;
        rung.cells.get_mut(at.row).and_then(|r| r.get_mut(at.col)).ok_or(EditError::OutsideGrid(at))
    }

    /// Checks that `at` is in the grid and not covered by a block (a place to put
    /// something).
    fn check_cell(&self, at: CellRef) -> Result<(), EditError> {
        if self.cell_at(at)?.element == Element::Covered {
            return Err(EditError::CoveredByBlock(at));
        }
        Ok(())
    }

    /// The anchor of the element at `at`: the cell itself, or for a covered cell the block
    /// above that covers it.
    fn anchor(&self, at: CellRef) -> Result<CellRef, EditError> {
        let mut cell = at;
        while self.cell_at(cell)?.element == Element::Covered {
            if cell.row == 0 {
                return Ok(at); // a stray covered cell (validation reports it)
            }
            cell.row -= 1;
        }
        Ok(cell)
    }

    /// Empties the element at `at` (a block with its footprint).
    fn clear(&mut self, at: CellRef) -> Result<(), EditError> {
        let anchor = self.anchor(at)?;
        let height = match &self.cell_at(anchor)?.element {
            Element::Block(b) => b.height.max(1) as usize,
            _ => 1,
        };
        for row in anchor.row..anchor.row + height {
            let cell = CellRef { row, ..anchor };
            let is_part = row == anchor.row || self.cell_at(cell)?.element == Element::Covered;
            if is_part {
                self.cell_mut(cell)?.element = Element::Empty;
            }
        }
        Ok(())
    }

    /// Puts `element` into the empty cell `at` (a block claims the cells below).
    fn put(&mut self, at: CellRef, element: Element) -> Result<(), EditError> {
        if let Element::Block(b) = &element {
            let height = b.height.max(1);
            self.claim(at, 1, height)?;
        }
        self.cell_mut(at)?.element = element;
        Ok(())
    }

    /// Makes the cells of rows `from..height` below the anchor `at` covered, if they all
    /// exist and hold nothing but wire.
    fn claim(&mut self, at: CellRef, from: u32, height: u32) -> Result<(), EditError> {
        let free = |c: &Cell| matches!(c.element, Element::Empty | Element::Wire);
        for k in from..height {
            let cell = CellRef { row: at.row + k as usize, ..at };
            match self.cell_at(cell) {
                Ok(c) if free(c) => {}
                _ => return Err(EditError::BlockDoesNotFit { at, height }),
            }
        }
        for k in from..height {
            self.cell_mut(CellRef { row: at.row + k as usize, ..at })?.element = Element::Covered;
        }
        Ok(())
    }

    fn resize_block(&mut self, at: CellRef, height: u32) -> Result<(), EditError> {
        let anchor = self.anchor(at)?;
        let Element::Block(block) = &self.cell_at(anchor)?.element else {
            return Err(EditError::NoOperand(at));
        };
        let old = block.height.max(1);
        if let Some(pin) = block.inputs.iter().find(|p| p.wired_row.is_some_and(|r| r >= height)) {
            return Err(EditError::PinOnRow {
                pin: pin.name.clone(),
                row: pin.wired_row.unwrap_or_default(),
            });
        }
        if height > old {
            self.claim(anchor, old, height)?;
        } else {
            for k in height..old {
                self.cell_mut(CellRef { row: anchor.row + k as usize, ..anchor })?.element =
                    Element::Empty;
            }
        }
        if let Element::Block(b) = &mut self.cell_mut(anchor)?.element {
            b.height = height;
        }
        Ok(())
    }

    /// The block (if any) whose span crosses the boundary above `row`: it starts above it
    /// and covers it.
    fn block_across(&self, rung: usize, row: usize) -> Result<Option<CellRef>, EditError> {
        let r = self.rungs.get(rung).ok_or(EditError::NoSuchRung(rung))?;
        if row == 0 || row >= r.rows() {
            return Ok(None);
        }
        for col in 0..r.columns() {
            if r.cell(row, col).is_some_and(|c| c.element == Element::Covered) {
                return Ok(Some(CellRef::new(rung, row, col)));
            }
        }
        Ok(None)
    }

    fn insert_row(&mut self, rung: usize, row: usize) -> Result<(), EditError> {
        let rows = self.rungs.get(rung).ok_or(EditError::NoSuchRung(rung))?.rows();
        if row > rows {
            return Err(EditError::OutsideGrid(CellRef::new(rung, row, 0)));
        }
        if let Some(at) = self.block_across(rung, row)? {
            return Err(EditError::CutsThroughBlock(at));
        }
        let r = self.rung_mut(rung)?;
        let columns = r.columns();
        r.cells.insert(row, vec![Cell::default(); columns]);
        Ok(())
    }

    fn delete_row(&mut self, rung: usize, row: usize) -> Result<(), EditError> {
        let r = self.rungs.get(rung).ok_or(EditError::NoSuchRung(rung))?;
        if row >= r.rows() {
            return Err(EditError::OutsideGrid(CellRef::new(rung, row, 0)));
        }
        if r.rows() == 1 {
            return Err(EditError::LastOne("row"));
        }
        for col in 0..r.columns() {
            let here = CellRef::new(rung, row, col);
            let tall = matches!(&r.cells[row][col].element, Element::Block(b) if b.height > 1);
            if tall || r.cells[row][col].element == Element::Covered {
                return Err(EditError::CutsThroughBlock(here));
            }
        }
        let r = self.rung_mut(rung)?;
        r.cells.remove(row);
        // A link down from what is now the last row would lead nowhere.
        let was_last = row == r.cells.len();
        if let Some(last) = r.cells.last_mut().filter(|_| was_last) {
            last.iter_mut().for_each(|c| c.link_down = false);
        }
        Ok(())
    }

    /// A fresh instance name `PREFIX1`, `PREFIX2`, … not declared in the POU and not used by
    /// any of its blocks (`T` for timers, `C` for counters, …).
    pub fn fresh_instance(&self, prefix: &str) -> String {
        let taken = |name: &str| {
            let in_blocks = self.rungs.iter().flat_map(|r| r.cells.iter().flatten()).any(|c| {
                matches!(&c.element, Element::Block(Block { instance: Some(i), .. }) if i.eq_ignore_ascii_case(name))
            });
            in_blocks || declares(&self.declarations, name)
        };
        (1..)
            .map(|n| format!("{prefix}{n}"))
            .find(|name| !taken(name))
            .unwrap_or_else(|| prefix.to_string())
    }
}

/// `declarations` with `name : ty;` added at the end of the first `VAR` block (or
/// `section`, e.g. `VAR_INPUT`), one being appended when there is none; unchanged when
/// `name` is declared already.
pub fn declare(declarations: &str, section: &str, name: &str, ty: &str) -> String {
    if declares(declarations, name) {
        return declarations.to_string();
    }
    let line = format!("    {name} : {ty};\n");
    let mut out = String::with_capacity(declarations.len() + line.len());
    let mut inside = false;
    let mut done = false;
    for l in declarations.split_inclusive('\n') {
        let word = l.split_whitespace().next().unwrap_or_default().to_ascii_uppercase();
        if !done && inside && word.starts_with("END_VAR") {
            out.push_str(&line);
            done = true;
        }
        if !done && word == section.to_ascii_uppercase() {
            inside = true;
        }
        out.push_str(l);
    }
    if !done {
        if !out.is_empty() && !out.ends_with('\n') {
            out.push('\n');
        }
        out.push_str(&format!("{section}\n{line}END_VAR\n"));
    }
    out
}

/// How to declare `name`, used undeclared at `at` (the fix offered for E0418): the section
/// and type its use implies — a contact's operand is a `VAR_INPUT` BOOL (a switch in the
/// I/O panel), a coil's a `VAR_OUTPUT` BOOL (a lamp), a block's instance a `VAR` of the
/// block's type. `None` when the use implies no type (a block pin, an expression).
pub fn implied_declaration(
    pou: &LadderPou,
    at: CellRef,
    name: &str,
) -> Option<(&'static str, String)> {
    let cell = pou.cell(at)?;
    let root = |operand: &str| {
        let head: String =
            operand.trim().chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
        head.eq_ignore_ascii_case(name) && head.len() == operand.trim().len()
    };
    match &cell.element {
        Element::Contact { operand, .. } if root(operand) => Some(("VAR_INPUT", "BOOL".into())),
        Element::Coil { operand, .. } if root(operand) => Some(("VAR_OUTPUT", "BOOL".into())),
        Element::Block(b)
            if b.instance.as_deref().is_some_and(|i| i.eq_ignore_ascii_case(name)) =>
        {
            Some(("VAR", b.type_name.clone()))
        }
        _ => None,
    }
}

/// `operand` with its root variable `name` (`Motr` of `Motr`, `T1` of `T1.Q`) spelled
/// `with`; `None` when its root is another name.
fn with_root(operand: &str, name: &str, with: &str) -> Option<String> {
    let text = operand.trim();
    let root_len =
        text.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(text.len());
    text[..root_len].eq_ignore_ascii_case(name).then(|| format!("{with}{}", &text[root_len..]))
}

/// The edit that puts `with` in place of the undeclared `name` at `at` (the fix offered
/// for an E0418 whose message ends in `did you mean WITH?`): a contact's or coil's
/// operand, a block's instance, or the first of a block's pins bound to it. `None` when
/// nothing at `at` names `name`.
pub fn replace_name(pou: &LadderPou, at: CellRef, name: &str, with: &str) -> Option<LadderEdit> {
    match &pou.cell(at)?.element {
        Element::Contact { operand, .. } | Element::Coil { operand, .. } => {
            Some(LadderEdit::SetOperand { at, operand: with_root(operand, name, with)? })
        }
        Element::Block(b) => {
            if b.instance.as_deref().is_some_and(|i| i.trim().eq_ignore_ascii_case(name)) {
                return Some(LadderEdit::SetOperand { at, operand: with.to_string() });
            }
            let lists = [
                (PinKind::Input, &b.inputs),
                (PinKind::Output, &b.outputs),
                (PinKind::InOut, &b.in_outs),
            ];
            lists.into_iter().find_map(|(kind, pins)| {
                pins.iter().find_map(|p| {
                    let operand = with_root(&p.operand, name, with)?;
                    Some(LadderEdit::SetPin { at, kind, pin: p.name.clone(), operand })
                })
            })
        }
        _ => None,
    }
}

/// Whether `declarations` declares `name` (read by the parser, as the checker reads it).
fn declares(declarations: &str, name: &str) -> bool {
    super::catalog::declared_names(declarations).iter().any(|n| n.eq_ignore_ascii_case(name))
}

/// Binds (or with an empty operand, unbinds) `pin` of `block`.
fn set_pin(block: &mut Block, kind: PinKind, pin: &str, operand: &str) {
    let list = match kind {
        PinKind::Input => &mut block.inputs,
        PinKind::Output => &mut block.outputs,
        PinKind::InOut => &mut block.in_outs,
    };
    let existing = list.iter().position(|p| p.name.eq_ignore_ascii_case(pin));
    match (existing, operand.is_empty()) {
        (Some(i), true) => {
            list.remove(i);
        }
        (Some(i), false) => {
            list[i].operand = operand.to_string();
            list[i].wired_row = None;
        }
        (None, true) => {}
        (None, false) => list.push(Pin::operand(pin, operand)),
    }
}

/// What a cell shows, in words (`NO contact Start`, `TON T1`, `covered`), with
/// `, linked down` when its vertical link is set: the accessible name of a grid cell after
/// its place.
pub fn describe_cell(cell: &Cell) -> String {
    use super::model::{CoilKind, ContactKind};
    let what = match &cell.element {
        Element::Empty => "empty".to_string(),
        Element::Wire => "wire".to_string(),
        Element::Contact { kind, operand } => {
            let kind = match kind {
                ContactKind::NormallyOpen => "NO contact",
                ContactKind::NormallyClosed => "NC contact",
                ContactKind::Rising => "rising edge contact",
                ContactKind::Falling => "falling edge contact",
            };
            format!("{kind} {operand}")
        }
        Element::Coil { kind, operand } => {
            let kind = match kind {
                CoilKind::Normal => "coil",
                CoilKind::Negated => "negated coil",
                CoilKind::Set => "set coil",
                CoilKind::Reset => "reset coil",
                CoilKind::Rising => "rising edge coil",
                CoilKind::Falling => "falling edge coil",
            };
            format!("{kind} {operand}")
        }
        Element::Block(b) => match &b.instance {
            Some(i) => format!("{} {i}", b.type_name),
            None => b.type_name.clone(),
        },
        Element::Covered => "covered".to_string(),
        Element::Jump { label } => format!("jump {label}"),
        Element::Return => "return".to_string(),
    };
    if cell.link_down {
        format!("{}, linked down", what.trim_end())
    } else {
        what.trim_end().to_string()
    }
}

#[cfg(test)]
mod tests;
