//! Editing a ladder POU in the page: the selected cell, the palette, keys, the operand box
//! and undo/redo. Every change is a [`LadderEdit`] of the core applied to the POU in the
//! project; this module only maps gestures to edits and keeps whole states for undo.

use leptos::prelude::*;
use plc_core::ladder::{
    declare, Block, CellRef, CoilKind, ContactKind, Element, LadderEdit, LadderPou, PinKind, Rung,
    DEFAULT_COLUMNS, DEFAULT_ROWS,
};
use plc_core::project::History;

use crate::i18n::{t, tf, K};
use crate::state::AppState;

/// The history group of a placement and the operand typed for it (one undo step).
const PLACE_GROUP: &str = "place-operand";

/// The standard blocks of the palette, in order.
pub const STANDARD_BLOCKS: &[&str] = &[
    "TON", "TOF", "TP", "CTU", "CTD", "CTUD", "R_TRIG", "F_TRIG", "SR", "RS", "GT", "GE", "EQ",
    "NE", "LE", "LT", "MOVE", "ADD", "SUB", "MUL", "DIV",
];

/// What a palette button or key puts into a cell.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Tool {
    /// A contact of this kind.
    Contact(ContactKind),
    /// A coil of this kind.
    Coil(CoilKind),
    /// A horizontal wire.
    Wire,
    /// Toggles the vertical link.
    LinkDown,
    /// A jump.
    Jump,
    /// A return.
    Return,
    /// A block of this type.
    Block(String),
}

impl Tool {
    /// The palette button's accessible name.
    pub fn label(&self) -> String {
        t(match self {
            Tool::Block(name) => return name.clone(),
            Tool::Contact(ContactKind::NormallyOpen) => K::ladder_tool_no_contact,
            Tool::Contact(ContactKind::NormallyClosed) => K::ladder_tool_nc_contact,
            Tool::Contact(ContactKind::Rising) => K::ladder_tool_rising_contact,
            Tool::Contact(ContactKind::Falling) => K::ladder_tool_falling_contact,
            Tool::Coil(CoilKind::Normal) => K::ladder_tool_coil,
            Tool::Coil(CoilKind::Negated) => K::ladder_tool_negated_coil,
            Tool::Coil(CoilKind::Set) => K::ladder_tool_set_coil,
            Tool::Coil(CoilKind::Reset) => K::ladder_tool_reset_coil,
            Tool::Coil(CoilKind::Rising) => K::ladder_tool_rising_coil,
            Tool::Coil(CoilKind::Falling) => K::ladder_tool_falling_coil,
            Tool::Wire => K::ladder_tool_wire,
            Tool::LinkDown => K::ladder_tool_link_down,
            Tool::Jump => K::ladder_tool_jump,
            Tool::Return => K::ladder_tool_return,
        })
        .to_string()
    }

    /// The element tools of the palette (blocks come after them).
    pub fn elements() -> Vec<Tool> {
        vec![
            Tool::Contact(ContactKind::NormallyOpen),
            Tool::Contact(ContactKind::NormallyClosed),
            Tool::Contact(ContactKind::Rising),
            Tool::Contact(ContactKind::Falling),
            Tool::Coil(CoilKind::Normal),
            Tool::Coil(CoilKind::Negated),
            Tool::Coil(CoilKind::Set),
            Tool::Coil(CoilKind::Reset),
            Tool::Wire,
            Tool::LinkDown,
            Tool::Jump,
            Tool::Return,
        ]
    }

    /// The tool of a key pressed on a cell (`c` NO contact, `n` NC contact, `o` coil, `s`
    /// set coil, `r` reset coil, `w` wire, `l` link down).
    pub fn of_key(key: &str) -> Option<Tool> {
        Some(match key {
            "c" => Tool::Contact(ContactKind::NormallyOpen),
            "n" => Tool::Contact(ContactKind::NormallyClosed),
            "o" => Tool::Coil(CoilKind::Normal),
            "s" => Tool::Coil(CoilKind::Set),
            "r" => Tool::Coil(CoilKind::Reset),
            "w" => Tool::Wire,
            "l" => Tool::LinkDown,
            _ => return None,
        })
    }

    /// Whether the element it places has an operand to type.
    fn asks_operand(&self) -> bool {
        matches!(self, Tool::Contact(_) | Tool::Coil(_) | Tool::Jump)
    }
}

/// The prefix of a new instance of block type `type_name` (`T` for timers, …).
fn instance_prefix(type_name: &str) -> String {
    match type_name.to_ascii_uppercase().as_str() {
        "TON" | "TOF" | "TP" | "RTO" => "T".into(),
        "CTU" | "CTD" | "CTUD" => "C".into(),
        "R_TRIG" => "RT".into(),
        "F_TRIG" => "FT".into(),
        "SR" | "RS" => "FF".into(),
        other => other.chars().filter(|c| c.is_ascii_alphanumeric()).collect(),
    }
}

/// Sensible operands for a new block's pins: a preset time for timers, a preset count for
/// counters.
fn default_pins(type_name: &str) -> Vec<(&'static str, &'static str)> {
    match type_name.to_ascii_uppercase().as_str() {
        "TON" | "TOF" | "TP" => vec![("PT", "T#1s")],
        "CTU" | "CTD" | "CTUD" => vec![("PV", "10")],
        _ => Vec::new(),
    }
}

/// What is being dragged: a palette tool, or the element of a cell.
#[derive(Debug, Clone, PartialEq)]
pub enum DragSource {
    /// A palette tool.
    Tool(Tool),
    /// The element in this cell (moved, or copied with Alt or Ctrl).
    Cell(CellRef),
}

/// A drag with the pointer (mouse, pen or touch) in progress.
#[derive(Debug, Clone, PartialEq)]
pub struct Drag {
    /// What is dragged.
    pub source: DragSource,
    /// Where the pointer went down.
    start: (f64, f64),
    /// Where it is now.
    pub at: (f64, f64),
    /// Whether it has moved far enough to be a drag (not a click).
    pub moved: bool,
    /// The cell under the pointer, and whether the element may go there.
    pub target: Option<(CellRef, bool)>,
    /// How many rows the dragged element covers (a block's height; 1 for the rest).
    pub footprint: usize,
}

/// How far (CSS pixels) the pointer moves before a press becomes a drag.
const DRAG_THRESHOLD: f64 = 5.0;

/// The cell a grid cell element stands for (`data-at="rung-row-col"`), or the cell of the
/// drawn element on top of it (an input's contact takes clicks to toggle the input while
/// its PROGRAM runs: `data-cell`, the same form).
fn cell_at_point(x: f64, y: f64) -> Option<CellRef> {
    let document = web_sys::window()?.document()?;
    let el = document.element_from_point(x as f32, y as f32)?;
    let at = match el.closest("[role=gridcell][data-at]").ok()? {
        Some(cell) => cell.get_attribute("data-at")?,
        None => el.closest("[data-cell]").ok()??.get_attribute("data-cell")?,
    };
    let mut parts = at.split('-').map(|p| p.parse::<usize>().ok());
    Some(CellRef::new(parts.next()??, parts.next()??, parts.next()??))
}

/// What undo restores: the POU and the selected cell.
type Snapshot = (LadderPou, Option<CellRef>);

/// The editing state of one ladder view (all handles, so it is `Copy`).
#[derive(Clone, Copy)]
pub struct LadderEditor {
    state: AppState,
    name: StoredValue<String>,
    /// The selected cell.
    pub selected: RwSignal<Option<CellRef>>,
    /// The cell whose operand box is open, and whether the box belongs to a placement (so
    /// Escape takes the placement back).
    pub operand_at: RwSignal<Option<(CellRef, bool)>>,
    /// The text in the operand box (kept here so that a redraw of the rungs keeps it).
    pub operand_text: RwSignal<String>,
    /// The highlighted choice of the operand box's list (arrow keys move it).
    pub choice_active: RwSignal<Option<usize>>,
    history: StoredValue<History<Snapshot>>,
    /// Bumped on every edit, undo and redo (the toolbar reads it).
    pub version: RwSignal<u64>,
    clipboard: StoredValue<Option<Rung>>,
    /// The drag in progress.
    pub drag: RwSignal<Option<Drag>>,
    /// Two fingers on the rungs zoom them.
    pub pinch: crate::components::pinch::Pinch,
    /// Whether the block picker (`b` on a cell) is open.
    pub picker_open: RwSignal<bool>,
}

impl LadderEditor {
    /// An editor of the ladder POU `name`.
    pub fn new(state: AppState, name: &str) -> Self {
        LadderEditor {
            state,
            name: StoredValue::new(name.to_string()),
            selected: RwSignal::new(None),
            operand_at: RwSignal::new(None),
            operand_text: RwSignal::new(String::new()),
            choice_active: RwSignal::new(None),
            history: StoredValue::new(History::default()),
            version: RwSignal::new(0),
            clipboard: StoredValue::new(None),
            drag: RwSignal::new(None),
            pinch: crate::components::pinch::Pinch::new(),
            picker_open: RwSignal::new(false),
        }
    }

    /// The POU as it is now.
    pub fn pou(&self) -> Option<LadderPou> {
        let name = self.name.get_value();
        self.state.project.with_untracked(|p| p.ladder.iter().find(|l| l.name == name).cloned())
    }

    fn replace(&self, pou: LadderPou) {
        let name = self.name.get_value();
        self.state.project.update(|p| {
            if let Some(l) = p.ladder.iter_mut().find(|l| l.name == name) {
                *l = pou;
            }
        });
        self.version.update(|v| *v += 1);
        self.state.check_soon();
    }

    /// Applies `edit` as one undo step (or joins the open `group`); shows why when it
    /// cannot be made. Returns whether it was applied.
    pub fn apply(&self, edit: &LadderEdit, group: Option<&str>) -> bool {
        let Some(pou) = self.pou() else { return false };
        match pou.apply(edit) {
            // An edit that changes nothing (the same operand again) is no undo step.
            Ok(next) if next == pou => true,
            Ok(next) => {
                let before = (pou, self.selected.get_untracked());
                self.history.update_value(|h| match group {
                    Some(g) => h.record_grouped(before, g),
                    None => h.record(before),
                });
                self.replace(next);
                true
            }
            Err(e) => {
                self.state.error(tf(K::ladder_not_changed, &[("error", &e.to_string())]));
                false
            }
        }
    }

    fn restore(&self, (pou, selected): Snapshot) {
        self.replace(pou);
        self.selected.set(selected);
        self.operand_at.set(None);
        self.focus_selected();
    }

    /// Ends the open group of edits (typing in the declarations): the next edit is a step
    /// of its own.
    pub fn close_group(&self) {
        self.history.update_value(History::close_group);
    }

    /// Undoes the last step.
    pub fn undo(&self) {
        let Some(current) = self.pou() else { return };
        let mut result = None;
        self.history.update_value(|h| {
            result = h.undo((current.clone(), self.selected.get_untracked())).ok();
        });
        if let Some(s) = result {
            self.restore(s);
        }
    }

    /// Redoes the last undone step.
    pub fn redo(&self) {
        let Some(current) = self.pou() else { return };
        let mut result = None;
        self.history.update_value(|h| {
            result = h.redo((current.clone(), self.selected.get_untracked())).ok();
        });
        if let Some(s) = result {
            self.restore(s);
        }
    }

    /// Whether there is a step to undo (tracks edits).
    pub fn can_undo(&self) -> bool {
        self.version.track();
        self.history.with_value(History::can_undo)
    }

    /// Whether there is a step to redo (tracks edits).
    pub fn can_redo(&self) -> bool {
        self.version.track();
        self.history.with_value(History::can_redo)
    }

    /// The id of a cell's element in the page.
    pub fn cell_id(&self, at: CellRef) -> String {
        format!("ld-cell-{}-{}-{}-{}", self.name.get_value(), at.rung, at.row, at.col)
    }

    /// Moves the focus to the selected cell (roving tabindex): as soon as the rungs are
    /// drawn (a microtask, before the next key arrives), and again on the next frame in
    /// case a redraw replaced the cell.
    pub fn focus_selected(&self) {
        let Some(at) = self.selected.get_untracked() else { return };
        let id = self.cell_id(at);
        let focus = move |id: &str| {
            use wasm_bindgen::JsCast;
            let document = web_sys::window().and_then(|w| w.document());
            let el = document
                .as_ref()
                .and_then(|d| d.get_element_by_id(id))
                .and_then(|e| e.dyn_into::<web_sys::HtmlElement>().ok());
            // A key pressed before this runs may have opened the operand box or the block
            // picker: they keep the focus they took.
            let elsewhere = document.and_then(|d| d.active_element()).is_some_and(|a| {
                a.class_list().contains("ld-operand-box")
                    || a.closest(".ld-picker").ok().flatten().is_some()
            });
            if let Some(el) = el.filter(|_| !elsewhere) {
                let _ = el.focus();
            }
        };
        let again = id.clone();
        wasm_bindgen_futures::spawn_local(async move { focus(&id) });
        request_animation_frame(move || focus(&again));
    }

    /// Moves the selection by rows and columns, from rung to rung at the edges.
    pub fn move_selection(&self, rows: isize, cols: isize) {
        let Some(pou) = self.pou() else { return };
        let at = self.selected.get_untracked().unwrap_or_default();
        let Some(rung) = pou.rungs.get(at.rung) else { return };
        let col = (at.col as isize + cols).clamp(0, rung.columns() as isize - 1) as usize;
        let row = at.row as isize + rows;
        let next = if row < 0 {
            match at.rung.checked_sub(1).and_then(|r| pou.rungs.get(r).map(|g| (r, g))) {
                Some((r, g)) => CellRef::new(r, g.rows() - 1, col.min(g.columns() - 1)),
                None => CellRef { row: 0, col, ..at },
            }
        } else if row as usize >= rung.rows() {
            match pou.rungs.get(at.rung + 1) {
                Some(g) => CellRef::new(at.rung + 1, 0, col.min(g.columns() - 1)),
                None => CellRef { row: rung.rows() - 1, col, ..at },
            }
        } else {
            CellRef { row: row as usize, col, ..at }
        };
        self.selected.set(Some(next));
        self.focus_selected();
    }

    /// The selected cell, or the first one (and says so) when none is.
    fn target(&self) -> CellRef {
        match self.selected.get_untracked() {
            Some(at) => at,
            None => {
                let at = CellRef::default();
                self.selected.set(Some(at));
                at
            }
        }
    }

    /// Uses a palette tool on `at` (the selected cell when `None`).
    pub fn use_tool(&self, tool: &Tool, at: Option<CellRef>) {
        let at = at.unwrap_or_else(|| self.target());
        self.selected.set(Some(at));
        let element = match tool {
            Tool::Contact(kind) => Element::Contact { kind: *kind, operand: String::new() },
            Tool::Coil(kind) => Element::Coil { kind: *kind, operand: String::new() },
            Tool::Wire => Element::Wire,
            Tool::Jump => Element::Jump { label: String::new() },
            Tool::Return => Element::Return,
            Tool::LinkDown => {
                self.apply(&LadderEdit::ToggleLinkDown { at }, None);
                self.focus_selected();
                return;
            }
            Tool::Block(type_name) => {
                self.place_block(type_name, at);
                return;
            }
        };
        let asks = tool.asks_operand();
        self.history.update_value(History::close_group);
        let group = asks.then_some(PLACE_GROUP);
        if self.apply(&LadderEdit::Place { at, element }, group) && asks {
            self.operand_text.set(String::new());
            self.operand_at.set(Some((at, true)));
        } else {
            self.focus_selected();
        }
    }

    /// Places a block of `type_name` at `at` with a fresh instance (declared for the user)
    /// and default pins, as one undo step.
    fn place_block(&self, type_name: &str, at: CellRef) {
        let Some(pou) = self.pou() else { return };
        let catalog = self.state.project.with_untracked(|p| p.catalog());
        let is_fb = catalog.block(type_name).is_some_and(|b| b.is_function_block());
        let instance = is_fb.then(|| pou.fresh_instance(&instance_prefix(type_name)));
        let mut block = Block::new(type_name, instance.as_deref());
        for (pin, operand) in default_pins(type_name) {
            block.inputs.push(plc_core::ladder::Pin::operand(pin, operand));
        }
        let mut edits = vec![LadderEdit::Place { at, element: Element::Block(block) }];
        if let Some(i) = &instance {
            edits.push(LadderEdit::SetDeclarations {
                text: declare(&pou.declarations, "VAR", i, type_name),
            });
        }
        self.apply_all(&edits);
        self.focus_selected();
    }

    /// Applies several edits as one undo step (all or none).
    pub fn apply_all(&self, edits: &[LadderEdit]) -> bool {
        let Some(pou) = self.pou() else { return false };
        let mut next = pou.clone();
        for e in edits {
            match next.apply(e) {
                Ok(p) => next = p,
                Err(e) => {
                    self.state.error(tf(K::ladder_not_changed, &[("error", &e.to_string())]));
                    return false;
                }
            }
        }
        let before = (pou, self.selected.get_untracked());
        self.history.update_value(|h| h.record(before));
        self.replace(next);
        true
    }

    /// Commits the operand box: the operand joins the placement's undo step.
    pub fn commit_operand(&self) {
        let text = self.operand_text.get_untracked();
        let text = text.as_str();
        let Some((at, placed)) = self.operand_at.get_untracked() else { return };
        self.operand_at.set(None);
        self.choice_active.set(None);
        let group = placed.then_some(PLACE_GROUP);
        self.apply(&LadderEdit::SetOperand { at, operand: text.to_string() }, group);
        self.history.update_value(History::close_group);
        self.focus_selected();
    }

    /// What the operand box offers for what is typed in it: the POU's variables, globals,
    /// instance outputs and addresses of the right type, or the rung labels for a jump.
    pub fn operand_choices(&self) -> Memo<Vec<plc_core::ladder::OperandChoice>> {
        let ed = *self;
        Memo::new(move |_| {
            let Some((at, _)) = ed.operand_at.get() else { return Vec::new() };
            let typed = ed.operand_text.get();
            let Some(pou) = ed.pou() else { return Vec::new() };
            let Some(element) = pou.cell(at).map(|c| c.element.clone()) else { return Vec::new() };
            let catalog = ed.state.project.with_untracked(|p| p.catalog());
            plc_core::ladder::operand_choices(&catalog, &pou, &element, &typed)
        })
    }

    /// Takes a choice of the operand box's list as the operand.
    pub fn take_choice(&self, text: &str) {
        self.operand_text.set(text.to_string());
        self.choice_active.set(None);
        self.commit_operand();
    }

    /// Closes the operand box; a placement it belonged to is taken back.
    pub fn cancel_operand(&self) {
        let Some((_, placed)) = self.operand_at.get_untracked() else { return };
        self.operand_at.set(None);
        self.choice_active.set(None);
        if placed {
            let mut before = None;
            self.history.update_value(|h| before = h.cancel());
            if let Some(s) = before {
                self.restore(s);
            }
        }
        self.focus_selected();
    }

    /// Opens the operand box on an element that has an operand; on a block, puts the focus
    /// into its first pin box (Enter or Escape there comes back to the cell).
    pub fn edit_operand(&self, at: CellRef) {
        let cell = self.pou().and_then(|p| p.cell(at).cloned());
        if matches!(cell.as_ref().map(|c| &c.element), Some(Element::Block(_) | Element::Covered)) {
            self.selected.set(Some(at));
            request_animation_frame(|| {
                use wasm_bindgen::JsCast;
                let first = web_sys::window()
                    .and_then(|w| w.document())
                    .and_then(|d| d.query_selector(".ld-pins input").ok().flatten())
                    .and_then(|e| e.dyn_into::<web_sys::HtmlInputElement>().ok());
                if let Some(el) = first {
                    let _ = el.focus();
                    el.select();
                }
            });
            return;
        }
        let current = cell.and_then(|c| c.element.operand().map(str::to_string));
        if let Some(current) = current {
            self.history.update_value(History::close_group);
            self.operand_text.set(current);
            self.operand_at.set(Some((at, false)));
        }
    }

    /// A key pressed on a grid cell; true when it was used.
    pub fn key(&self, at: CellRef, key: &str, ctrl: bool, shift: bool) -> bool {
        match (key, ctrl) {
            ("ArrowUp", false) => self.move_selection(-1, 0),
            ("ArrowDown", false) => self.move_selection(1, 0),
            ("ArrowLeft", false) => self.move_selection(0, -1),
            ("ArrowRight", false) => self.move_selection(0, 1),
            ("Delete" | "Backspace", false) => {
                self.apply(&LadderEdit::Clear { at }, None);
                self.focus_selected();
            }
            ("Enter" | "F2", false) => self.edit_operand(at),
            ("b", false) => self.picker_open.set(true),
            ("z" | "Z", true) if !shift => self.undo(),
            ("z" | "Z", true) | ("y" | "Y", true) => self.redo(),
            ("c", true) => {
                let rung = self.pou().and_then(|p| p.rungs.get(at.rung).cloned());
                self.clipboard.set_value(rung);
                self.state.info(tf(K::ladder_rung_copied, &[("rung", &(at.rung + 1).to_string())]));
            }
            ("v", true) => {
                if let Some(rung) = self.clipboard.get_value() {
                    self.apply(&LadderEdit::InsertRung { index: at.rung + 1, rung }, None);
                    self.focus_selected();
                }
            }
            (k, false) => match Tool::of_key(k) {
                Some(tool) => self.use_tool(&tool, Some(at)),
                None => return false,
            },
            _ => return false,
        }
        true
    }

    /// The edit a drop of `source` on `to` makes.
    fn drop_edit(&self, source: &DragSource, to: CellRef, copy: bool) -> Option<LadderEdit> {
        Some(match source {
            DragSource::Cell(from) if copy => LadderEdit::Copy { from: *from, to },
            DragSource::Cell(from) => LadderEdit::Move { from: *from, to },
            DragSource::Tool(Tool::LinkDown) => LadderEdit::ToggleLinkDown { at: to },
            DragSource::Tool(Tool::Block(t)) => {
                LadderEdit::Place { at: to, element: Element::Block(Block::new(t, None)) }
            }
            DragSource::Tool(_) => LadderEdit::Place { at: to, element: Element::Wire },
        })
    }

    /// A pointer went down on a palette tool or a placed element: a drag may start.
    pub fn press(&self, source: DragSource, ev: &web_sys::PointerEvent) {
        // A second finger pinches: the first one's drag ends.
        if self.pinch.down(ev) {
            self.drag.set(None);
            return;
        }
        if ev.button() != 0 {
            return;
        }
        let mut footprint = 1;
        if let DragSource::Cell(at) = &source {
            let element = self.pou().and_then(|p| p.cell(*at).map(|c| c.element.clone()));
            match element {
                None | Some(Element::Empty | Element::Covered) => return,
                Some(Element::Block(b)) => footprint = b.height.max(1) as usize,
                Some(_) => {}
            }
        }
        let at = (f64::from(ev.client_x()), f64::from(ev.client_y()));
        self.drag.set(Some(Drag { source, start: at, at, moved: false, target: None, footprint }));
    }

    /// The pointer moved: follows it and shows whether the cell under it takes the drop.
    pub fn pointer_move(&self, x: f64, y: f64) {
        let Some(mut drag) = self.drag.get_untracked() else { return };
        drag.at = (x, y);
        drag.moved |= (x - drag.start.0).hypot(y - drag.start.1) > DRAG_THRESHOLD;
        drag.target = cell_at_point(x, y).map(|to| {
            let ok = self
                .drop_edit(&drag.source, to, false)
                .zip(self.pou())
                .is_some_and(|(edit, pou)| pou.apply(&edit).is_ok());
            (to, ok)
        });
        self.drag.set(Some(drag));
    }

    /// The pointer went up: a drag drops on the cell under it (a press that did not move is
    /// left to the click).
    pub fn release(&self, x: f64, y: f64, copy: bool) {
        let Some(drag) = self.drag.get_untracked() else { return };
        self.drag.set(None);
        if !drag.moved {
            return;
        }
        let Some(to) = cell_at_point(x, y) else { return };
        match &drag.source {
            DragSource::Tool(tool) => self.use_tool(tool, Some(to)),
            DragSource::Cell(from) => {
                let edit = if copy {
                    LadderEdit::Copy { from: *from, to }
                } else {
                    LadderEdit::Move { from: *from, to }
                };
                self.history.update_value(History::close_group);
                if self.apply(&edit, None) {
                    self.selected.set(Some(to));
                    self.focus_selected();
                }
            }
        }
    }

    /// The block picker's choice (`None`: closed without one): the block goes into the
    /// selected cell.
    pub fn pick_block(&self, type_name: Option<String>) {
        self.picker_open.set(false);
        match type_name.filter(|t| !t.is_empty()) {
            Some(t) => self.use_tool(&Tool::Block(t), None),
            None => self.focus_selected(),
        }
    }

    /// A rung toolbar action on the selected cell's rung.
    pub fn rung_action(&self, action: RungAction) {
        let at = self.target();
        let rows = self.pou().and_then(|p| p.rungs.get(at.rung).map(Rung::rows)).unwrap_or(0);
        let edit = match action {
            RungAction::Add => LadderEdit::InsertRung {
                index: at.rung + 1,
                rung: Rung::new(DEFAULT_ROWS, DEFAULT_COLUMNS),
            },
            RungAction::Delete => LadderEdit::DeleteRung { index: at.rung },
            RungAction::Up => {
                if at.rung == 0 {
                    return;
                }
                LadderEdit::MoveRung { from: at.rung, to: at.rung - 1 }
            }
            RungAction::Down => LadderEdit::MoveRung { from: at.rung, to: at.rung + 1 },
            RungAction::InsertRow => LadderEdit::InsertRow { rung: at.rung, row: at.row },
            RungAction::DeleteRow => LadderEdit::DeleteRow { rung: at.rung, row: at.row },
            RungAction::InsertColumn => LadderEdit::InsertColumn { rung: at.rung, col: at.col },
            RungAction::DeleteColumn => LadderEdit::DeleteColumn { rung: at.rung, col: at.col },
        };
        if !self.apply(&edit, None) {
            return;
        }
        let count = self.pou().map_or(0, |p| p.rungs.len());
        let next = match action {
            RungAction::Add => CellRef::new(at.rung + 1, 0, 0),
            RungAction::Delete => CellRef::new(at.rung.min(count.saturating_sub(1)), 0, 0),
            RungAction::Up => CellRef { rung: at.rung - 1, ..at },
            RungAction::Down => CellRef { rung: at.rung + 1, ..at },
            RungAction::DeleteRow => CellRef { row: at.row.min(rows.saturating_sub(2)), ..at },
            _ => at,
        };
        self.selected.set(Some(next));
        self.focus_selected();
    }

    /// Binds a block pin (the pin boxes under a selected block).
    pub fn set_pin(&self, at: CellRef, kind: PinKind, pin: &str, operand: &str) {
        self.apply(
            &LadderEdit::SetPin { at, kind, pin: pin.to_string(), operand: operand.to_string() },
            None,
        );
    }
}

/// The rung toolbar's actions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RungAction {
    /// `Add rung` below the selected one.
    Add,
    /// `Delete rung`.
    Delete,
    /// `Move rung up`.
    Up,
    /// `Move rung down`.
    Down,
    /// `Insert row` at the selected row.
    InsertRow,
    /// `Delete row`.
    DeleteRow,
    /// `Insert column` at the selected column.
    InsertColumn,
    /// `Delete column`.
    DeleteColumn,
}

impl RungAction {
    /// Every action with the key of its button text (the accessible name).
    pub fn all() -> [(RungAction, K); 8] {
        [
            (RungAction::Add, K::ladder_add_rung),
            (RungAction::Delete, K::ladder_delete_rung),
            (RungAction::Up, K::ladder_move_rung_up),
            (RungAction::Down, K::ladder_move_rung_down),
            (RungAction::InsertRow, K::ladder_insert_row),
            (RungAction::DeleteRow, K::ladder_delete_row),
            (RungAction::InsertColumn, K::ladder_insert_column),
            (RungAction::DeleteColumn, K::ladder_delete_column),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_and_labels_match_the_issue() {
        assert_eq!(Tool::of_key("c").map(|t| t.label()).as_deref(), Some("NO contact"));
        assert_eq!(Tool::of_key("n").map(|t| t.label()).as_deref(), Some("NC contact"));
        assert_eq!(Tool::of_key("o").map(|t| t.label()).as_deref(), Some("Coil"));
        assert_eq!(Tool::of_key("l").map(|t| t.label()).as_deref(), Some("Link down"));
        assert_eq!(Tool::of_key("x"), None);
        let labels: Vec<String> = Tool::elements().iter().map(Tool::label).collect();
        assert!(labels.contains(&"Falling edge contact".to_string()));
        assert_eq!(instance_prefix("TON"), "T");
        assert_eq!(instance_prefix("CTUD"), "C");
        assert_eq!(default_pins("tp"), vec![("PT", "T#1s")]);
    }
}
