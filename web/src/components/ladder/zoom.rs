//! How big the rungs are drawn and whether the ST and IL views stand beside them: the
//! `Zoom in` / `Zoom out` / `Fit` buttons and the side panel's switch, both remembered in
//! local storage for every ladder POU.
//!
//! The drawing's units are CSS pixels at 100 %: a cell of contacts is 86 × 58 px with its
//! operand in 12 px text. Zoom never goes below 100 %, so cells are never smaller than
//! 44 × 32 px and operand names never under 12 px; a rung wider than its column scrolls
//! in its own box.

use leptos::prelude::*;
use plc_core::ladder::LadderPou;
use plc_core::project::StorageBackend;

use super::geometry::rung_geometry;
use crate::i18n::{t, K};
use crate::storage::LocalStorage;

/// Where the zoom is kept.
const ZOOM_KEY: &str = "plc-trainer/v1/ladder-zoom";
/// Where the side panel's state is kept (`hidden` when collapsed).
const SIDE_KEY: &str = "plc-trainer/v1/ladder-side";
/// The smallest zoom: the drawing's own size (see the module's note).
pub const MIN_ZOOM: f64 = 1.0;
/// The largest zoom.
pub const MAX_ZOOM: f64 = 2.0;
/// One press of `Zoom in` or `Zoom out`.
const ZOOM_STEP: f64 = 0.25;

/// `zoom` kept within its range, in whole percent.
pub fn clamp_zoom(zoom: f64) -> f64 {
    if !zoom.is_finite() {
        return MIN_ZOOM;
    }
    (zoom.clamp(MIN_ZOOM, MAX_ZOOM) * 100.0).floor() / 100.0
}

/// The zoom at which a drawing `width` px wide at 100 % fills `room` px.
pub fn fit_zoom(width: f64, room: f64) -> f64 {
    if width <= 0.0 || room <= 0.0 {
        return MIN_ZOOM;
    }
    clamp_zoom(room / width)
}

/// The next zoom step up (`up`) or down from `zoom`.
pub fn step_zoom(zoom: f64, up: bool) -> f64 {
    let steps = zoom / ZOOM_STEP;
    let next = if up { steps.floor() + 1.0 } else { steps.ceil() - 1.0 };
    clamp_zoom(next * ZOOM_STEP)
}

/// The rung view's zoom and side panel (handles, so it is `Copy`).
#[derive(Clone, Copy)]
pub struct ViewPrefs {
    /// The zoom (1.0 = 100 %).
    pub zoom: RwSignal<f64>,
    /// Whether the ST and IL views stand beside the rungs.
    pub side: RwSignal<bool>,
}

impl ViewPrefs {
    /// The prefs as last kept (100 % and the side panel shown at first).
    pub fn load() -> Self {
        let store = LocalStorage::open();
        let zoom = store
            .get(ZOOM_KEY)
            .ok()
            .flatten()
            .and_then(|z| crate::dom::number_of(&z))
            .map_or(MIN_ZOOM, clamp_zoom);
        let side = store.get(SIDE_KEY).ok().flatten().as_deref() != Some("hidden");
        ViewPrefs { zoom: RwSignal::new(zoom), side: RwSignal::new(side) }
    }

    /// Sets and keeps the zoom.
    pub fn set_zoom(&self, zoom: f64) {
        let zoom = clamp_zoom(zoom);
        self.zoom.set(zoom);
        let _ = LocalStorage::open().set(ZOOM_KEY, &format!("{zoom}"));
    }

    /// Shows or hides the side panel, and keeps it.
    pub fn toggle_side(&self) {
        let side = !self.side.get_untracked();
        self.side.set(side);
        let _ = LocalStorage::open().set(SIDE_KEY, if side { "shown" } else { "hidden" });
    }
}

/// The room for a rung's drawing: the width of the rung list's box (`.ld-rungs`) in `view`.
fn rung_room(view_id: &str) -> Option<f64> {
    let document = web_sys::window()?.document()?;
    let list = document.query_selector(&format!("#{view_id} .ld-rungs")).ok()??;
    // The rung's border and its box's scrollbar take a few pixels.
    Some(f64::from(list.client_width()) - 8.0)
}

/// The zoom buttons, for the view whose element id is `view_id`.
#[component]
pub fn ZoomControls(
    prefs: ViewPrefs,
    pou: Memo<Option<LadderPou>>,
    view_id: String,
) -> impl IntoView {
    let zoom = prefs.zoom;
    let fit = move |_| {
        let widest = pou.with_untracked(|p| {
            p.as_ref()
                .map_or(0.0, |p| p.rungs.iter().map(|r| rung_geometry(r).width).fold(0.0, f64::max))
        });
        if let Some(room) = rung_room(&view_id) {
            prefs.set_zoom(fit_zoom(widest, room));
        }
    };
    view! {
        <span class="ld-zoom" role="group" aria-label=t(K::ladder_zoom_label)>
            <button
                disabled=move || { zoom.get() <= MIN_ZOOM }
                on:click=move |_| prefs.set_zoom(step_zoom(zoom.get_untracked(), false))>{t(K::ladder_zoom_out)}</button>
            <output class="ld-zoom-value" aria-live="polite">{move || format!("{:.0} %", zoom.get() * 100.0)}</output>
            <button
                disabled=move || { zoom.get() >= MAX_ZOOM }
                on:click=move |_| prefs.set_zoom(step_zoom(zoom.get_untracked(), true))>{t(K::ladder_zoom_in)}</button>
            <button title=t(K::ladder_fit_title) on:click=fit>{t(K::ladder_fit)}</button>
        </span>
    }
}

/// The switch that shows or hides the ST and IL views beside (or below) the rungs.
#[component]
pub fn SideToggle(prefs: ViewPrefs) -> impl IntoView {
    view! {
        <button class="ld-side-toggle" title=t(K::ladder_side_title)
            aria-pressed=move || if prefs.side.get() { "true" } else { "false" }
            on:click=move |_| prefs.toggle_side()>{t(K::ladder_side)}</button>

    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zoom_stays_readable_and_steps_by_quarters() {
        assert_eq!(clamp_zoom(0.4), MIN_ZOOM);
        assert_eq!(clamp_zoom(f64::NAN), MIN_ZOOM);
        assert_eq!(clamp_zoom(9.0), MAX_ZOOM);
        assert_eq!(step_zoom(1.0, true), 1.25);
        assert_eq!(step_zoom(1.1, true), 1.25);
        assert_eq!(step_zoom(1.1, false), 1.0);
        assert_eq!(step_zoom(1.0, false), 1.0);
        assert_eq!(step_zoom(2.0, true), 2.0);
        // Fit: as large as the room allows, never under 100 %.
        assert_eq!(fit_zoom(500.0, 700.0), 1.4);
        assert_eq!(fit_zoom(910.0, 600.0), 1.0);
        assert_eq!(fit_zoom(0.0, 600.0), 1.0);
    }
}
