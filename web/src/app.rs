//! The page layout: header with the project menu, the `Start here` strip of a first
//! visit, the editor pane (POU navigator, the
//! selected POU's view, the problem list) and the simulation panels. On a small screen
//! (≤ 700 px wide, issue 34) a tab bar shows one of them at a time: `Program`,
//! `Simulation`, and `Exercise` while one is open.

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
use crate::i18n::{t, tf, K};
use crate::lazy::{self, lazy_view, What};
use crate::state::AppState;
use plc_core::build::Site;

/// The whole app.
#[component]
pub fn App() -> impl IntoView {
    // First: the state, the exercises and the tour make words in the language shown.
    let i18n = crate::i18n::I18n::start();
    provide_context(i18n);
    let state = AppState::new();
    provide_context(state);
    let exercises = Exercises::new(state);
    provide_context(exercises);
    let tour = Tour::new();
    provide_context(tour);
    tour.watch(state, exercises);
    let pane = RwSignal::new(Pane::Program);
    provide_context(pane);
    // On a phone an exercise opened shows its task; closed, the program.
    let has_exercise = Memo::new(move |_| exercises.open.with(Option::is_some));
    Effect::new(move |before: Option<bool>| {
        let open = has_exercise.get();
        if before.is_some_and(|b| b != open) {
            pane.set(if open { Pane::Exercise } else { Pane::Program });
        }
        open
    });
    // Drawn again when the language shown changes: the views hold plain texts, the state
    // stays where it is.
    move || {
        i18n.shown.track();
        untrack(move || layout(state, exercises))
    }
}

/// The page's views over the app's state.
fn layout(state: AppState, exercises: Exercises) -> impl IntoView {
    let catalogue = move || exercises.screen.get() == Screen::Catalogue;
    let asking = Memo::new(move |_| state.why.with(Option::is_some));
    let has_scene = Memo::new(move |_| state.project.with(|p| p.scene.is_some()));
    let pane = expect_context::<RwSignal<Pane>>();
    let has_exercise = Memo::new(move |_| exercises.open.with(Option::is_some));
    // The pane shown on a small screen (the exercise's only while one is open).
    let shown = Memo::new(move |_| match pane.get() {
        Pane::Exercise if !has_exercise.get() => Pane::Program,
        p => p,
    });
    view! {
        <a class="skip-link" href="#simulation" on:click=move |ev| skip_to_simulation(ev, pane)>{t(K::app_skip_to_simulation)}</a>
        <Header/>
        <Banner/>
        <Show when=catalogue>
            {tour_panel()}
            {lazy_view(What::ExerciseCatalogue, lazy::catalogue_view)}
        </Show>
        // Kept while the catalogue is shown (hidden), so the editors keep their state.
        <main class="workspace" hidden=catalogue data-pane=move || shown.get().id()>
            {pane_tabs(pane, shown, has_exercise)}
            // At the top of the simulation column: the editors never move for it.
            {tour_panel()}
            <section class="editor-pane" id="program" aria-label=t(K::app_program)>
                <div class="exercise-slot" id="exercise">
                    {move || has_exercise.get().then(|| {
                        lazy_view(What::Exercise, lazy::exercise_panel_view)
                    })}
                </div>
                <div class="program-slot">
                    <PouPane/>
                </div>
            </section>
            <section class="sim-pane" id="simulation" tabindex="-1" aria-label=t(K::app_simulation)>
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

/// The panes a small screen shows one at a time (the `Program` / `Simulation` /
/// `Exercise` tabs); a wide screen shows them side by side.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Pane {
    Program,
    Simulation,
    Exercise,
}

impl Pane {
    /// The id of the pane's element (the tab's `aria-controls`).
    fn id(self) -> &'static str {
        match self {
            Pane::Program => "program",
            Pane::Simulation => "simulation",
            Pane::Exercise => "exercise",
        }
    }
}

/// The tab bar of a small screen (hidden on a wide one): a tab per pane, the arrow keys,
/// Home and End move among them as in every tab bar.
fn pane_tabs(pane: RwSignal<Pane>, shown: Memo<Pane>, has_exercise: Memo<bool>) -> impl IntoView {
    let tab = move |p: Pane, label: &'static str| {
        view! {
            <button class="pane-tab" role="tab" id=format!("tab-{}", p.id()) aria-controls=p.id()
                aria-selected=move || (shown.get() == p).to_string()
                tabindex=move || if shown.get() == p { "0" } else { "-1" }
                on:click=move |_| pane.set(p)>{label}</button>
        }
    };
    let on_key = move |ev: leptos::ev::KeyboardEvent| {
        let mut all = vec![Pane::Program, Pane::Simulation];
        if has_exercise.get_untracked() {
            all.push(Pane::Exercise);
        }
        let at = all.iter().position(|p| *p == shown.get_untracked()).unwrap_or(0);
        let next = match ev.key().as_str() {
            "ArrowRight" => (at + 1) % all.len(),
            "ArrowLeft" => (at + all.len() - 1) % all.len(),
            "Home" => 0,
            "End" => all.len() - 1,
            _ => return,
        };
        ev.prevent_default();
        pane.set(all[next]);
        if let Some(tab) =
            crate::dom::by_id::<web_sys::HtmlElement>(&format!("tab-{}", all[next].id()))
        {
            let _ = tab.focus();
        }
    };
    view! {
        <div class="pane-tabs" role="tablist" aria-label=t(K::phone_views) on:keydown=on_key>
            {tab(Pane::Program, t(K::phone_program))}
            {tab(Pane::Simulation, t(K::phone_simulation))}
            {move || has_exercise.get().then(|| tab(Pane::Exercise, t(K::phone_exercise)))}
        </div>
    }
}

/// The skip link's click: focus moves to the simulation column (Run, the inputs) without
/// a fragment in the address, which is the share link's place; a small screen shows its
/// tab first.
fn skip_to_simulation(ev: leptos::ev::MouseEvent, pane: RwSignal<Pane>) {
    ev.prevent_default();
    pane.set(Pane::Simulation);
    let focus = || {
        let pane = crate::dom::by_id::<web_sys::HtmlElement>("simulation")?;
        let _ = pane.focus();
        let active = web_sys::window()?.document()?.active_element()?;
        Some(active == *pane.as_ref())
    };
    // Shown already (a wide screen): at once; else once its tab has shown it.
    if focus() != Some(true) {
        request_animation_frame(move || {
            focus();
        });
    }
}

/// The message banner (errors, faults with a link to their line, information).
#[component]
fn Banner() -> impl IntoView {
    let state = expect_context::<AppState>();
    let pane = expect_context::<RwSignal<Pane>>();
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
                            Site::St { line, .. } => tf(K::app_go_to_line, &[("line", &line.to_string())]),
                            _ => t(K::app_show).to_string(),
                        };
                        view! {
                            <button class="link" on:click=move |_| {
                                pane.set(Pane::Program);
                                state.reveal(&site);
                            }>{label}</button>
                        }
                    })}
                    <button class="close" aria-label=t(K::app_dismiss) on:click=move |_| state.notice.set(None)>"×"</button>
                </div>
            }
        })
    }
}
