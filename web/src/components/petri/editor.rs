//! Editing a Petri net POU in the page: the tool, the selection, pointer gestures on the
//! canvas, keys on the elements and undo/redo. Every change is a [`NetEdit`] of the core
//! applied to the POU in the project; this module maps gestures to edits and keeps whole
//! states (the POU and the selection) for undo.

use leptos::prelude::*;
use plc_core::petri::{NetEdit, PetriPou, Position};
use plc_core::project::History;

use super::layout::{layout, Point};
use crate::i18n::{tf, K};
use crate::state::AppState;

/// The canvas grid: new and moved elements snap to it, arrow keys move by one step.
pub const GRID: f64 = 20.0;

/// How far (CSS pixels) the pointer moves before a press becomes a drag.
const DRAG_THRESHOLD: f64 = 4.0;

/// The canvas tools (toggle buttons; a tool stays chosen until another is, or Escape).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NetTool {
    /// Select, move, pan.
    Select,
    /// A click on empty canvas adds a place.
    Place,
    /// A click on empty canvas adds a transition.
    Transition,
    /// Press on one element and release on another (or click both) to join them.
    Arc,
}

impl NetTool {
    /// Every tool with its button text (its accessible name).
    pub fn all() -> [(NetTool, K); 4] {
        [
            (NetTool::Select, K::petri_select),
            (NetTool::Place, K::petri_place),
            (NetTool::Transition, K::petri_transition),
            (NetTool::Arc, K::petri_arc),
        ]
    }
}

/// What is selected on the canvas.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Selection {
    /// A place, transition or macro-place, by id.
    Element(String),
    /// The arc from one id to another.
    Arc(String, String),
}

/// A press on the canvas in progress.
#[derive(Debug, Clone, PartialEq)]
pub struct NetDrag {
    /// The element pressed (`None`: the empty canvas, which pans).
    pub id: Option<String>,
    /// Where the pointer went down (client pixels).
    start: (f64, f64),
    /// The element's centre when the press began, and the pointer there (net units).
    origin: (Point, Point),
    /// Where the element would be now (net units, snapped).
    pub at: Point,
    /// The container's scroll when a pan began.
    scroll: (i32, i32),
    /// Whether it has moved far enough to be a drag.
    pub moved: bool,
}

/// What undo restores: the POU and the selection.
type Snapshot = (PetriPou, Option<Selection>);

/// Snaps a coordinate to the grid.
pub fn snap(v: f64) -> f64 {
    (v / GRID).round() * GRID
}

/// The editing state of one net view (all handles, so it is `Copy`).
#[derive(Clone, Copy)]
pub struct NetEditor {
    state: AppState,
    name: StoredValue<String>,
    /// The chosen tool.
    pub tool: RwSignal<NetTool>,
    /// The selection.
    pub selected: RwSignal<Option<Selection>>,
    /// The start of an arc being drawn with two clicks.
    pub arc_from: RwSignal<Option<String>>,
    /// The press or drag in progress.
    pub drag: RwSignal<Option<NetDrag>>,
    /// The drawing's scale (1 = one net unit per CSS pixel).
    pub zoom: RwSignal<f64>,
    /// Two fingers on the canvas zoom it.
    pub pinch: crate::components::pinch::Pinch,
    history: StoredValue<History<Snapshot>>,
    /// Bumped on every edit, undo and redo.
    pub version: RwSignal<u64>,
}

impl NetEditor {
    /// An editor of the net POU `name`.
    pub fn new(state: AppState, name: &str) -> Self {
        NetEditor {
            state,
            name: StoredValue::new(name.to_string()),
            tool: RwSignal::new(NetTool::Select),
            selected: RwSignal::new(None),
            arc_from: RwSignal::new(None),
            drag: RwSignal::new(None),
            zoom: RwSignal::new(1.0),
            pinch: crate::components::pinch::Pinch::new(),
            history: StoredValue::new(History::default()),
            version: RwSignal::new(0),
        }
    }

    /// The POU as it is now.
    pub fn pou(&self) -> Option<PetriPou> {
        let name = self.name.get_value();
        self.state.project.with_untracked(|p| p.petri.iter().find(|n| n.name == name).cloned())
    }

    /// Sets the drawing's scale, kept between a quarter and four times.
    pub fn set_zoom(&self, zoom: f64) {
        self.zoom.set(zoom.clamp(0.25, 4.0));
    }

    /// The id of the SVG canvas in the page.
    pub fn canvas_id(&self) -> String {
        format!("pn-canvas-{}", self.name.get_value())
    }

    fn replace(&self, pou: PetriPou) {
        let name = self.name.get_value();
        self.state.project.update(|p| {
            if let Some(n) = p.petri.iter_mut().find(|n| n.name == name) {
                *n = pou;
            }
        });
        self.version.update(|v| *v += 1);
        self.state.check_soon();
    }

    /// Applies edits as one undo step (or joins the open `group`, so typing in a property
    /// is one step). A net drawn by the automatic layout gets its positions first, in the
    /// same step, so what the user sees is what is edited. Shows why when it cannot be made.
    pub fn apply(&self, edits: &[NetEdit], group: Option<&str>) -> bool {
        let Some(pou) = self.pou() else { return false };
        let mut next = pou.clone();
        let drawn = layout(&pou.net);
        if drawn.automatic {
            let at = |p: Point| Position { x: snap(p.x), y: snap(p.y) };
            for (place, p) in pou.net.places.iter().zip(&drawn.places) {
                next.net.places.iter_mut().filter(|q| q.id == place.id).for_each(|q| {
                    q.position = Some(at(*p));
                });
            }
            for (t, p) in pou.net.transitions.iter().zip(&drawn.transitions) {
                next.net.transitions.iter_mut().filter(|q| q.id == t.id).for_each(|q| {
                    q.position = Some(at(*p));
                });
            }
        }
        for e in edits {
            match next.apply(e) {
                Ok(p) => next = p,
                Err(err) => {
                    self.state.error(tf(K::petri_not_changed, &[("error", &err.to_string())]));
                    return false;
                }
            }
        }
        if next == pou {
            return true;
        }
        let before = (pou, self.selected.get_untracked());
        self.history.update_value(|h| match group {
            Some(g) => h.record_grouped(before, g),
            None => {
                h.close_group();
                h.record(before);
            }
        });
        self.replace(next);
        true
    }

    /// Ends the open group of edits (a property field was left).
    pub fn close_group(&self) {
        self.history.update_value(History::close_group);
    }

    fn restore(&self, (pou, selected): Snapshot) {
        self.replace(pou);
        self.selected.set(selected);
        self.focus_selected();
    }

    /// Undoes the last step.
    pub fn undo(&self) {
        let Some(current) = self.pou() else { return };
        let mut result = None;
        self.history.update_value(|h| {
            h.close_group();
            result = h.undo((current, self.selected.get_untracked())).ok();
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
            result = h.redo((current, self.selected.get_untracked())).ok();
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

    /// The page id of an element's group.
    pub fn element_dom_id(&self, id: &str) -> String {
        format!("pn-el-{}-{id}", self.name.get_value())
    }

    /// Gives the focus to the selected element once the drawing is updated.
    pub fn focus_selected(&self) {
        let Some(Selection::Element(id)) = self.selected.get_untracked() else { return };
        let dom = self.element_dom_id(&id);
        request_animation_frame(move || {
            if let Some(el) = crate::dom::by_id::<web_sys::SvgElement>(&dom) {
                let _ = el.focus();
            }
        });
    }

    /// Chooses a tool (an arc in progress is dropped).
    pub fn choose(&self, tool: NetTool) {
        self.tool.set(tool);
        self.arc_from.set(None);
    }

    /// The point of the net under client pixel `(x, y)`.
    pub fn net_point(&self, x: f64, y: f64) -> Option<Point> {
        let svg: web_sys::Element = crate::dom::by_id(&self.canvas_id())?;
        let rect = svg.get_bounding_client_rect();
        let vb = svg.get_attribute("viewBox")?;
        let v: Vec<f64> = vb.split_whitespace().filter_map(|s| s.parse().ok()).collect();
        let [vx, vy, vw, vh] = v[..] else { return None };
        if rect.width() <= 0.0 || rect.height() <= 0.0 {
            return None;
        }
        Some(Point {
            x: vx + (x - rect.left()) * vw / rect.width(),
            y: vy + (y - rect.top()) * vh / rect.height(),
        })
    }

    /// Adds a place or transition (by the tool) at `p`, snapped, and selects it.
    fn add_at(&self, p: Point) {
        let Some(pou) = self.pou() else { return };
        let at = Position { x: snap(p.x), y: snap(p.y) };
        let edit = match self.tool.get_untracked() {
            NetTool::Place => NetEdit::AddPlace { id: pou.next_id("P"), at },
            NetTool::Transition => NetEdit::AddTransition { id: pou.next_id("T"), at },
            _ => return,
        };
        let id = match &edit {
            NetEdit::AddPlace { id, .. } | NetEdit::AddTransition { id, .. } => id.clone(),
            _ => return,
        };
        if self.apply(&[edit], None) {
            self.selected.set(Some(Selection::Element(id)));
            self.focus_selected();
        }
    }

    /// Joins `from` and `to` with an arc and selects it.
    fn join(&self, from: &str, to: &str) {
        self.arc_from.set(None);
        if self.apply(&[NetEdit::AddArc { from: from.to_string(), to: to.to_string() }], None) {
            self.selected.set(Some(Selection::Arc(from.to_string(), to.to_string())));
        }
    }

    /// A pointer went down on the canvas: on element `id` (its centre `centre`), or on the
    /// empty canvas (`None`).
    pub fn press(&self, id: Option<String>, centre: Option<Point>, ev: &web_sys::PointerEvent) {
        // A second finger pinches: the first one's drag or pan ends.
        if self.pinch.down(ev) {
            self.drag.set(None);
            return;
        }
        if ev.button() != 0 {
            return;
        }
        let (cx, cy) = (f64::from(ev.client_x()), f64::from(ev.client_y()));
        let Some(p) = self.net_point(cx, cy) else { return };
        match (self.tool.get_untracked(), &id) {
            (NetTool::Place | NetTool::Transition, None) => {
                self.add_at(p);
                return;
            }
            (NetTool::Arc, Some(target)) => {
                match self.arc_from.get_untracked() {
                    Some(from) if from != *target => self.join(&from, target),
                    _ => self.arc_from.set(Some(target.clone())),
                }
                return;
            }
            (NetTool::Arc, None) => {
                self.arc_from.set(None);
                return;
            }
            (_, Some(target)) => self.selected.set(Some(Selection::Element(target.clone()))),
            (NetTool::Select, None) => self.selected.set(None),
        }
        let scroll = self.scroller().map_or((0, 0), |s| (s.scroll_left(), s.scroll_top()));
        let origin = (centre.unwrap_or(p), p);
        self.drag.set(Some(NetDrag {
            id,
            start: (cx, cy),
            origin,
            at: origin.0,
            scroll,
            moved: false,
        }));
    }

    fn scroller(&self) -> Option<web_sys::Element> {
        let svg: web_sys::Element = crate::dom::by_id(&self.canvas_id())?;
        svg.closest(".pn-net").ok().flatten()
    }

    /// The pointer moved: a pressed element follows it (snapped); the empty canvas pans.
    pub fn pointer_move(&self, x: f64, y: f64) {
        let Some(mut drag) = self.drag.get_untracked() else { return };
        let moved = (x - drag.start.0).hypot(y - drag.start.1) > DRAG_THRESHOLD;
        if !moved && !drag.moved {
            return;
        }
        drag.moved = true;
        match &drag.id {
            Some(_) => {
                let Some(p) = self.net_point(x, y) else { return };
                let (centre, grab) = drag.origin;
                let at =
                    Point { x: snap(centre.x + p.x - grab.x), y: snap(centre.y + p.y - grab.y) };
                if at == drag.at {
                    self.drag.set(Some(drag));
                    return;
                }
                drag.at = at;
            }
            None => {
                if let Some(s) = self.scroller() {
                    s.set_scroll_left(drag.scroll.0 - (x - drag.start.0) as i32);
                    s.set_scroll_top(drag.scroll.1 - (y - drag.start.1) as i32);
                }
            }
        }
        self.drag.set(Some(drag));
    }

    /// The pointer went up: a moved element is one Move edit; an arc pressed on one element
    /// and released on another joins them.
    pub fn release(&self, x: f64, y: f64) {
        if let (NetTool::Arc, Some(from)) =
            (self.tool.get_untracked(), self.arc_from.get_untracked())
        {
            if let Some(to) = element_at_point(x, y).filter(|to| *to != from) {
                self.join(&from, &to);
            }
            return;
        }
        let Some(drag) = self.drag.get_untracked() else { return };
        self.drag.set(None);
        if let (Some(id), true) = (&drag.id, drag.moved) {
            if drag.at != drag.origin.0 {
                let to = Position { x: drag.at.x, y: drag.at.y };
                self.apply(&[NetEdit::Move { id: id.clone(), to }], None);
            }
            self.focus_selected();
        }
    }

    /// The element being moved and where it is now (the drawing shows it there).
    pub fn moving(&self) -> Option<(String, Point)> {
        self.drag.with(|d| {
            let d = d.as_ref().filter(|d| d.moved)?;
            Some((d.id.clone()?, d.at))
        })
    }

    /// Deletes the selection.
    pub fn delete_selection(&self) {
        let edit = match self.selected.get_untracked() {
            Some(Selection::Element(id)) => NetEdit::Delete { id },
            Some(Selection::Arc(from, to)) => NetEdit::DeleteArc { from, to },
            None => return,
        };
        if self.apply(&[edit], None) {
            self.selected.set(None);
            // The focus stays on the canvas (its keys, undo among them, keep working).
            use wasm_bindgen::JsCast;
            if let Some(c) = self.scroller().and_then(|c| c.dyn_into::<web_sys::HtmlElement>().ok())
            {
                let _ = c.focus();
            }
        }
    }

    /// Moves the selected element by whole grid steps (arrow keys).
    pub fn nudge(&self, id: &str, centre: Point, dx: f64, dy: f64) {
        let to = Position { x: snap(centre.x) + dx * GRID, y: snap(centre.y) + dy * GRID };
        self.apply(&[NetEdit::Move { id: id.to_string(), to }], None);
        self.focus_selected();
    }

    /// A key on the canvas or an element; true when it was used.
    pub fn key(&self, key: &str, ctrl: bool, shift: bool) -> bool {
        match (key, ctrl) {
            ("z" | "Z", true) if !shift => self.undo(),
            ("z" | "Z", true) | ("y" | "Y", true) => self.redo(),
            ("Escape", false) => {
                self.choose(NetTool::Select);
            }
            ("Delete" | "Backspace", false) => self.delete_selection(),
            _ => return false,
        }
        true
    }
}

/// The id of the net element under client pixel `(x, y)` (`data-id` of its group).
fn element_at_point(x: f64, y: f64) -> Option<String> {
    let document = web_sys::window()?.document()?;
    let el = document.element_from_point(x as f32, y as f32)?;
    let group = el.closest("[data-id]").ok()??;
    group.get_attribute("data-id")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_snap_to_the_grid() {
        assert_eq!(snap(29.0), 20.0);
        assert_eq!(snap(31.0), 40.0);
        assert_eq!(snap(-11.0), -20.0);
        let names: Vec<&str> = NetTool::all().iter().map(|(_, n)| n.en()).collect();
        assert_eq!(names, ["Select", "Place", "Transition", "Arc"]);
    }
}
