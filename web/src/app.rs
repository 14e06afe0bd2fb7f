//! The page layout: header with the project menu, the editor pane (POU navigator, the
//! selected POU's view, the problem list) and the simulation panels.

use leptos::prelude::*;

use crate::components::{
    controls::Controls, header::Header, io::IoPanel, pou_pane::PouPane, timeline::Timeline,
    variables::Variables,
};
use crate::exercises::{Exercises, Screen};
use crate::lazy::{self, lazy_view};
use crate::state::AppState;
use plc_core::build::Site;

/// The whole app.
#[component]
pub fn App() -> impl IntoView {
    let state = AppState::new();
    provide_context(state);
    let exercises = Exercises::new(state);
    provide_context(exercises);
    let catalogue = move || exercises.screen.get() == Screen::Catalogue;
    let asking = Memo::new(move |_| state.why.with(Option::is_some));
    let has_scene = Memo::new(move |_| state.project.with(|p| p.scene.is_some()));
    view! {
        <Header/>
        <Banner/>
        <Show when=catalogue>
            {lazy_view("the exercise catalogue", lazy::catalogue_view)}
        </Show>
        // Kept while the catalogue is shown (hidden), so the editors keep their state.
        <main class="workspace" hidden=catalogue>
            <section class="editor-pane" aria-label="Program">
                {move || exercises.open.with(Option::is_some).then(|| {
                    lazy_view("the exercise", lazy::exercise_panel_view)
                })}
                <PouPane/>
            </section>
            <section class="sim-pane" aria-label="Simulation">
                <Controls/>
                {move || asking.get().then(|| lazy_view("the explanation", lazy::explanation_view))}
                {move || has_scene.get().then(|| lazy_view("the plant scene", lazy::scene_view))}
                <IoPanel/>
                <Variables/>
                <Timeline/>
            </section>
        </main>
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
