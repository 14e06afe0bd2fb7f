//! The recording's controls (issue 36): the `Recorded scan` slider over the scans kept,
//! and the banner `Showing scan N of M — Return to now` while the page shows a past scan.
//! A chunk of its own (`lazy::recorded_view`), shown once there is a scan to go back to.

use leptos::prelude::*;

use crate::i18n::{t, K};
use crate::state::{past_words, AppState};

/// The recording: a `Recorded scan` slider over the scans kept, and the banner that says
/// the page shows a past scan, with `Return to now`.
#[component]
pub fn Recorded() -> impl IntoView {
    let state = expect_context::<AppState>();
    let range = Memo::new(move |_| state.recorded_range());
    let shown = move || state.displayed_scan();
    let first = move || range.get().map_or(0, |r| r.0);
    let last = move || range.get().map_or(0, |r| r.1);
    view! {
            <div class="control-row recorded">
                <label class="field grow">
                    <span>{t(K::sim_recorded_scan)}</span>
                    <input type="range" aria-label=t(K::sim_recorded_scan)
                        prop:min=move || first().to_string() prop:max=move || last().to_string() step="1"
                        prop:disabled=move || first() == last()
                        prop:value=move || shown().to_string()
                        on:input=move |ev| {
                            if let Ok(n) = event_target_value(&ev).trim().parse::<u64>() {
                                state.show_scan(n);
                            }
                        }/>
                </label>
                <output class="mono" aria-label=t(K::sim_recorded_scans)>{move || format!("{}–{}", first(), last())}</output>
            </div>
        {move || state.shown.get().map(|n| {
            let last = range.get().map_or(n, |r| r.1);
            view! {
                <div class="past-banner" role="status">
                    <span>{past_words::showing(n, last)}</span>
                    " — "
                    <button class="link" on:click=move |_| state.return_to_now()>{past_words::RETURN_TO_NOW}</button>
                </div>
            }
        })}
    }
}
