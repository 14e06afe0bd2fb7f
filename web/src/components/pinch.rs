//! Two-finger pinch zoom for the drawings students touch: the Petri net canvas and the
//! rungs (issue 34). Each editor tells its [`Pinch`] of every press, move and release; a
//! second finger on the drawing starts a pinch (the editor drops the drag the first finger
//! began), and while both stay down the zoom follows the distance between them.

use leptos::prelude::*;

/// A pinch on one drawing: the fingers down on it and, while two are, where it began.
#[derive(Debug, Clone, Copy)]
pub struct Pinch {
    state: StoredValue<Fingers>,
}

#[derive(Debug, Default)]
struct Fingers {
    /// Each finger down: its pointer id and where it is (client pixels).
    down: Vec<(i32, f64, f64)>,
    /// While pinching: the fingers' distance when the pinch began, and the drawing's zoom
    /// then (taken at the pinch's first move).
    start: Option<(f64, Option<f64>)>,
}

impl Fingers {
    fn distance(&self) -> Option<f64> {
        let [(_, ax, ay), (_, bx, by), ..] = self.down[..] else { return None };
        Some((ax - bx).hypot(ay - by))
    }
}

/// The zoom a pinch asks for: the zoom when it began (`zoom`), scaled by how far the
/// fingers are now (`now`) against how far they were then (`began`).
pub fn pinched_zoom(zoom: f64, began: f64, now: f64) -> f64 {
    if began < 1.0 || !now.is_finite() {
        return zoom;
    }
    zoom * now / began
}

impl Default for Pinch {
    fn default() -> Self {
        Self::new()
    }
}

impl Pinch {
    /// No finger down.
    pub fn new() -> Self {
        Pinch { state: StoredValue::new(Fingers::default()) }
    }

    /// A pointer went down on the drawing: true when it is a second finger, so a pinch
    /// begins and the press is not an edit.
    pub fn down(&self, ev: &web_sys::PointerEvent) -> bool {
        if ev.pointer_type() != "touch" {
            return false;
        }
        let id = ev.pointer_id();
        let at = (f64::from(ev.client_x()), f64::from(ev.client_y()));
        let mut pinching = false;
        self.state.update_value(|f| {
            // The first finger of a touch begins a new gesture: fingers left from an
            // earlier one (a release the page did not see) do not count.
            if ev.is_primary() {
                *f = Fingers::default();
            }
            f.down.retain(|(i, _, _)| *i != id);
            f.down.push((id, at.0, at.1));
            if f.down.len() >= 2 {
                if f.start.is_none() {
                    f.start = f.distance().map(|d| (d, None));
                }
                pinching = true;
            }
        });
        pinching
    }

    /// A pointer moved over a drawing whose zoom is `zoom`: the zoom the pinch asks for
    /// now, while pinching.
    pub fn moved(&self, ev: &web_sys::PointerEvent, zoom: f64) -> Option<f64> {
        if ev.pointer_type() != "touch" {
            return None;
        }
        let id = ev.pointer_id();
        let at = (f64::from(ev.client_x()), f64::from(ev.client_y()));
        let mut asked = None;
        self.state.update_value(|f| {
            let Some(finger) = f.down.iter_mut().find(|(i, _, _)| *i == id) else { return };
            (finger.1, finger.2) = at;
            let now = f.distance();
            if let (Some((began, z)), Some(now)) = (f.start.as_mut(), now) {
                let from = *z.get_or_insert(zoom);
                asked = Some(pinched_zoom(from, *began, now));
            }
        });
        asked
    }

    /// A pointer went up or was cancelled: the pinch ends when fewer than two fingers stay.
    pub fn up(&self, ev: &web_sys::PointerEvent) {
        let id = ev.pointer_id();
        self.state.update_value(|f| {
            f.down.retain(|(i, _, _)| *i != id);
            if f.down.len() < 2 {
                f.start = None;
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fingers_apart_zoom_in_and_together_zoom_out() {
        assert_eq!(pinched_zoom(1.0, 100.0, 200.0), 2.0);
        assert_eq!(pinched_zoom(2.0, 100.0, 50.0), 1.0);
        // Fingers on one spot (no distance to scale by) leave the zoom.
        assert_eq!(pinched_zoom(1.5, 0.0, 80.0), 1.5);
        assert_eq!(pinched_zoom(1.5, 100.0, f64::NAN), 1.5);
    }
}
