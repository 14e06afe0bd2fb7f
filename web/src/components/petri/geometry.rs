//! The shapes of a drawn net: transition bars turned across the flow, arcs from border to
//! border (two arcs between the same pair drawn apart), macro-place outlines and the
//! drawing's bounds. Pure functions, tested natively.

use super::layout::Point;

/// Radius of a place.
pub const PLACE_R: f64 = 18.0;
/// Length of a transition bar.
pub const BAR_LONG: f64 = 36.0;
/// Thickness of a transition bar.
pub const BAR_THICK: f64 = 9.0;
/// Space between a macro-place's outline and its places.
const MACRO_PAD: f64 = 30.0;
/// How far two arcs joining the same pair are drawn apart.
const TWIN_OFFSET: f64 = 5.0;

/// How a transition bar lies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bar {
    /// Lying flat: tokens flow up or down through it.
    Horizontal,
    /// Standing: tokens flow left or right through it.
    Vertical,
}

impl Bar {
    /// Half width and half height of the bar.
    pub fn half(self) -> (f64, f64) {
        match self {
            Bar::Horizontal => (BAR_LONG / 2.0, BAR_THICK / 2.0),
            Bar::Vertical => (BAR_THICK / 2.0, BAR_LONG / 2.0),
        }
    }
}

/// The bar of a transition at `t` with input places at `inputs` and outputs at `outputs`:
/// across the mean direction of the flow through it.
pub fn bar_of(t: Point, inputs: &[Point], outputs: &[Point]) -> Bar {
    let unit = |dx: f64, dy: f64| {
        let len = dx.hypot(dy);
        if len > 0.0 {
            (dx / len, dy / len)
        } else {
            (0.0, 0.0)
        }
    };
    let (mut fx, mut fy) = (0.0, 0.0);
    for p in inputs {
        let (x, y) = unit(t.x - p.x, t.y - p.y);
        fx += x;
        fy += y;
    }
    for p in outputs {
        let (x, y) = unit(p.x - t.x, p.y - t.y);
        fx += x;
        fy += y;
    }
    if fx.abs() > fy.abs() {
        Bar::Vertical
    } else {
        Bar::Horizontal
    }
}

/// The point where the segment from `centre` towards `to` leaves a circle of radius `r`.
pub fn circle_exit(centre: Point, to: Point, r: f64) -> Point {
    let (dx, dy) = (to.x - centre.x, to.y - centre.y);
    let len = dx.hypot(dy);
    if len == 0.0 {
        return centre;
    }
    Point { x: centre.x + dx / len * r, y: centre.y + dy / len * r }
}

/// The point where the segment from `centre` towards `to` leaves a box of half sizes
/// `(hw, hh)` around `centre`.
pub fn box_exit(centre: Point, to: Point, (hw, hh): (f64, f64)) -> Point {
    let (dx, dy) = (to.x - centre.x, to.y - centre.y);
    if dx == 0.0 && dy == 0.0 {
        return centre;
    }
    let sx = if dx != 0.0 { hw / dx.abs() } else { f64::INFINITY };
    let sy = if dy != 0.0 { hh / dy.abs() } else { f64::INFINITY };
    let s = sx.min(sy);
    Point { x: centre.x + dx * s, y: centre.y + dy * s }
}

/// The line of an arc between a place at `place` and a transition bar at `trans`, from its
/// source's border to its target's border; `twin` moves it aside when an arc joins the same
/// pair in the other direction.
pub fn arc_line(
    place: Point,
    trans: Point,
    bar: Bar,
    place_first: bool,
    twin: bool,
) -> (Point, Point) {
    let (dx, dy) = (trans.x - place.x, trans.y - place.y);
    let len = dx.hypot(dy).max(1e-9);
    // Each direction of a twin pair moves to its own right.
    let side = if place_first { 1.0 } else { -1.0 };
    let (ox, oy) = if twin {
        (-dy / len * TWIN_OFFSET * side, dx / len * TWIN_OFFSET * side)
    } else {
        (0.0, 0.0)
    };
    let p = Point { x: place.x + ox, y: place.y + oy };
    let t = Point { x: trans.x + ox, y: trans.y + oy };
    let a = circle_exit(p, t, PLACE_R);
    let b = box_exit(t, p, bar.half());
    if place_first {
        (a, b)
    } else {
        (b, a)
    }
}

/// The outline of a macro-place around the centres of its places: (x, y, width, height).
pub fn macro_box(places: &[Point]) -> Option<(f64, f64, f64, f64)> {
    let first = places.first()?;
    let (mut x0, mut y0, mut x1, mut y1) = (first.x, first.y, first.x, first.y);
    for p in places {
        x0 = x0.min(p.x);
        y0 = y0.min(p.y);
        x1 = x1.max(p.x);
        y1 = y1.max(p.y);
    }
    Some((x0 - MACRO_PAD, y0 - MACRO_PAD, x1 - x0 + 2.0 * MACRO_PAD, y1 - y0 + 2.0 * MACRO_PAD))
}

/// About how wide a transition's name and guard are drawn (26 characters of guard at 10 px).
pub const LABEL_W: f64 = 130.0;

/// The box `(x, y, width, height)` of the name and guard beside a transition at `c` whose
/// bar is `hw` half wide: right of the bar, or left of it when `left`.
pub fn label_box(c: Point, hw: f64, left: bool) -> (f64, f64, f64, f64) {
    let x = if left { c.x - hw - 6.0 - LABEL_W } else { c.x + hw + 6.0 };
    (x, c.y - 14.0, LABEL_W, 30.0)
}

fn box_hits_place(b: (f64, f64, f64, f64), places: &[Point]) -> bool {
    let (x, y, w, h) = b;
    places.iter().any(|p| {
        let nx = p.x.clamp(x, x + w);
        let ny = p.y.clamp(y, y + h);
        (p.x - nx).powi(2) + (p.y - ny).powi(2) < PLACE_R * PLACE_R
    })
}

/// Whether a transition's labels go left of its bar: when they would cover a place on the
/// right and not on the left.
pub fn label_on_left(c: Point, hw: f64, places: &[Point]) -> bool {
    box_hits_place(label_box(c, hw, false), places)
        && !box_hits_place(label_box(c, hw, true), places)
}

/// The view box `(x, y, width, height)` around points, with room for labels.
pub fn view_box(points: &[Point], extra: &[(f64, f64, f64, f64)]) -> (f64, f64, f64, f64) {
    let mut x0 = f64::INFINITY;
    let mut y0 = f64::INFINITY;
    let mut x1 = f64::NEG_INFINITY;
    let mut y1 = f64::NEG_INFINITY;
    for p in points {
        x0 = x0.min(p.x - PLACE_R - 32.0);
        y0 = y0.min(p.y - PLACE_R - 22.0);
        // Names and guards are written right of transitions.
        x1 = x1.max(p.x + PLACE_R + 120.0);
        y1 = y1.max(p.y + PLACE_R + 22.0);
    }
    for &(x, y, w, h) in extra {
        x0 = x0.min(x - 4.0);
        y0 = y0.min(y - 20.0);
        x1 = x1.max(x + w + 4.0);
        y1 = y1.max(y + h + 4.0);
    }
    if !x0.is_finite() {
        return (0.0, 0.0, 200.0, 100.0);
    }
    (x0, y0, x1 - x0, y1 - y0)
}

/// The editing canvas around a drawing's box: it takes in the origin and at least 640 × 400
/// units, with room right of and below the net to add elements.
pub fn canvas_box((x, y, w, h): (f64, f64, f64, f64)) -> (f64, f64, f64, f64) {
    let x0 = x.min(0.0);
    let y0 = y.min(0.0);
    let x1 = (x + w + 160.0).max(640.0);
    let y1 = (y + h + 120.0).max(400.0);
    (x0, y0, x1 - x0, y1 - y0)
}

#[cfg(test)]
mod tests;
