//! The page layout: header with the project menu, the `Start here` strip of a first
//! visit, the editor pane (POU navigator, the
//! selected POU's view, the problem list) and the simulation panels.

use leptos::prelude::*;

use crate::components::{
    controls::Controls,
    header::Header,
    io::IoPanel,
    pou_pane::PouPane,
    timeline::Timeline,
    tour::{tour_panel, Tour},
    variables::Variables,
};
use crate::exercises::{Exercises, Screen};
use crate::i18n::{t, K};
use crate::lazy::{self, lazy_view, What};
use crate::state::AppState;
use plc_core::build::Site;

/// The whole app.
#[component]
pub fn App() -> impl IntoView {
    let state = AppState::new();
    provide_context(state);
    let exercises = Exercises::new(state);
    provide_context(exercises);
    let tour = Tour::new();
    provide_context(tour);
    tour.watch(state, exercises);
    let i18n = crate::i18n::I18n::start();
    provide_context(i18n);
    // Drawn again when the language shown changes: the views hold plain texts, the state
    // stays where it is.
    move || {
        i18n.shown.track();
        i18n.ready.get().then(|| untrack(move || layout(state, exercises)))
    }
}

/// The page's views over the app's state.
fn layout(state: AppState, exercises: Exercises) -> impl IntoView {
    let catalogue = move || exercises.screen.get() == Screen::Catalogue;
    let asking = Memo::new(move |_| state.why.with(Option::is_some));
    let has_scene = Memo::new(move |_| state.project.with(|p| p.scene.is_some()));
    view! {
        <a class="skip-link" href="#simulation" on:click=skip_to_simulation>{t(K::app_skip_to_simulation)}</a>
        <Header/>
        <Banner/>
        <Show when=catalogue>
            {tour_panel()}
            {lazy_view(What::ExerciseCatalogue, lazy::catalogue_view)}
        </Show>
        // Kept while the catalogue is shown (hidden), so the editors keep their state.
        <main class="workspace" hidden=catalogue>
            // At the top of the simulation column: the editors never move for it.
            {tour_panel()}
            <section class="editor-pane" aria-label="Program">
                {move || exercises.open.with(Option::is_some).then(|| {
                    lazy_view(What::Exercise, lazy::exercise_panel_view)
                })}
                <PouPane/>
            </section>
            <section class="sim-pane" id="simulation" tabindex="-1" aria-label="Simulation">
                <Controls/>
                {move || asking.get().then(|| lazy_view(What::Explanation, lazy::explanation_view))}
                {move || has_scene.get().then(|| lazy_view(What::PlantScene, lazy::scene_view))}
                <IoPanel/>
                <Variables/>
                <Timeline/>
            </section>
        </main>
    }
}

/// The skip link's click: focus moves to the simulation column (Run, the inputs) without
/// a fragment in the address, which is the share link's place.
fn skip_to_simulation(ev: leptos::ev::MouseEvent) {
    ev.prevent_default();
    let pane = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id("simulation"))
        .and_then(|e| wasm_bindgen::JsCast::dyn_into::<web_sys::HtmlElement>(e).ok());
    if let Some(pane) = pane {
        let _ = pane.focus();
    }
}

/// The message banner (errors, faults with a link to their line, information).
#[component]
fn Banner() -> impl IntoView {
    let state = expect_context::<AppState>();
    move || {
        state.notice.get().map(|n| {
            let class = if n.error { "banner banner-error" } else { "banner banner-info" };
            let site = n.site.clone().filter(|s| *s != Site::Project);
            view! {
                <div class=class role="alert">
                    <span>{n.text.clone()}</span>
                    {n.actions.iter().cloned().map(|action| view! {
                        <button class="link" on:click=move |_| state.act(&action)>{action.label()}</button>
                    }).collect_view()}
                    {site.map(|site| {
                        let label = match &site {
                            Site::St { line, .. } => format!("Go to line {line}"),
                            _ => "Show".to_string(),
                        };
                        view! {
                            <button class="link" on:click=move |_| state.reveal(&site)>{label}</button>
                        }
                    })}
                    <button class="close" aria-label="Dismiss" on:click=move |_| state.notice.set(None)>"×"</button>
                </div>
            }
        })
    }
}
