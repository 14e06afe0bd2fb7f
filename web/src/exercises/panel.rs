//! The exercise panel beside the editors: the statement, the interface, `Start in` (the
//! language of the attempt), `Program to check`, `Check`, `Reset to starter`, `Share
//! exercise`, and the last check's report.

use leptos::ev;
use leptos::prelude::*;
use plc_core::exercise::{graded_program, Direction, Language};
use plc_core::project::ProgramPou;
use wasm_bindgen::JsCast;

use super::report::ReportView;
use super::{language_name, Exercises, Screen};
use crate::components::share_box::{copy_to_clipboard, ShareBox};
use crate::state::AppState;

/// The words of the panel's own controls.
const START_IN: &str = "Start in";
const START_IN_TITLE: &str =
    "The language you write your answer in: choosing another starts again from its starter";
const PROGRAM_TO_CHECK: &str = "Program to check";
const PROGRAM_TO_CHECK_TITLE: &str = "The PROGRAM that Check grades (and the simulator runs)";
const SCENARIOS: &str =
    "Check runs these scenarios (the score adds up the points of those passed): ";

/// The open exercise (nothing when the open project is not an attempt).
#[component]
pub fn ExercisePanel() -> impl IntoView {
    let state = expect_context::<AppState>();
    let ex = expect_context::<Exercises>();
    let shown = expect_context::<crate::i18n::I18n>().shown;
    let share = move |_| {
        let Some(link) = ex.link() else { return };
        ex.share_link.set(Some(link.clone()));
        leptos::task::spawn_local(async move {
            if copy_to_clipboard(&link).await {
                state.info("Exercise link copied to the clipboard (it never holds hidden scenarios nor the reference).");
            }
        });
    };
    move || {
        ex.open.get().map(|open| {
            let v = open.opened.view.localised(shown.get());
            let langs = v.languages.iter().map(|l| language_name(l)).collect::<Vec<_>>().join(", ");
            let scenarios = v.scenarios.iter().map(|s| {
                let random = if s.random { ", random inputs" } else { "" };
                let points = if s.weight == 1 { "1 point".to_string() } else { format!("{} points", s.weight) };
                format!("{} ({points}{random})", s.name)
            }).collect::<Vec<_>>().join(" · ");
            let starters: Vec<(String, &'static str)> = open.opened.starters.iter().map(|s| {
                let name = Language::from_code(&s.language).map_or("", Language::name);
                (s.language.clone(), name)
            }).collect();
            let (preferred, plant) = (v.program.clone(), v.plant.clone());
            // The PROGRAMs the student may have checked and the one Check grades, re-read
            // when the project changes (the options are redrawn only when these do).
            let choice = Memo::new(move |_| state.project.with(|p| {
                let programs: Vec<ProgramPou> = p.programs().into_iter()
                    .filter(|q| plant.as_deref().is_none_or(|n| !q.name.eq_ignore_ascii_case(n)))
                    .collect();
                let checked = graded_program(p, preferred.as_deref(), plant.as_deref()).map(|q| q.name);
                (programs, checked.unwrap_or_default())
            }));
            let attempt_language = Memo::new(move |_| ex.attempt_language(state).unwrap_or_default());
            view! {
                <section class="exercise-panel" aria-label="Exercise">
                    <div class="exercise-head">
                        <h2 class="exercise-title">{v.title.clone()}</h2>
                        <span class="exercise-meta">{format!("Level {} · {langs}", v.level)}</span>
                        <div class="exercise-actions">
                            <button class="primary" on:click=move |_| ex.check(state)
                                disabled=move || ex.checking.get()>
                                {move || if ex.checking.get() { "Checking…" } else { "Check" }}
                            </button>
                            <button on:click=move |_| ex.reset_to_starter(state)>"Reset to starter"</button>
                            <button on:click=share title="Copy a link that carries this exercise">"Share exercise"</button>
                            <super::HandInActions/>
                            <button class="lms-hidden" on:click=move |_| ex.screen.set(Screen::Catalogue)>"All exercises"</button>
                        </div>
                    </div>
                    <div class="exercise-setup">
                        {(starters.len() > 1).then(|| view! {
                            <label class="field">
                                <span>{START_IN}</span>
                                <select aria-label=START_IN title=START_IN_TITLE
                                    prop:value=move || attempt_language.get()
                                    on:change=move |e: ev::Event| {
                                        let code = event_target_value(&e);
                                        if !ex.start_in(state, &code) {
                                            // Kept their work: the select shows the attempt's language again.
                                            if let Some(select) = e.target().and_then(|t| t.dyn_into::<web_sys::HtmlSelectElement>().ok()) {
                                                select.set_value(&attempt_language.get_untracked());
                                            }
                                        }
                                    }>
                                    {starters.iter().map(|(code, name)| {
                                        let code = code.clone();
                                        let selected = { let code = code.clone(); move || attempt_language.get() == code };
                                        view! { <option value=code selected=selected>{*name}</option> }
                                    }).collect_view()}
                                </select>
                            </label>
                        })}
                        {move || {
                            let (programs, checked) = choice.get();
                            view! {
                                <label class="field">
                                    <span>{PROGRAM_TO_CHECK}</span>
                                    <select aria-label=PROGRAM_TO_CHECK title=PROGRAM_TO_CHECK_TITLE
                                        on:change=move |e: ev::Event| state.set_program(&event_target_value(&e))>
                                        {programs.into_iter().map(|q| {
                                            let selected = q.name.eq_ignore_ascii_case(&checked);
                                            let label = format!("{} ({})", q.name, q.language.label());
                                            view! { <option value=q.name selected=selected>{label}</option> }
                                        }).collect_view()}
                                    </select>
                                </label>
                            }
                        }}
                    </div>
                    {move || ex.share_link.get().map(|link| view! {
                        <ShareBox link=link label="Exercise link" close_label="Close exercise link"
                            on_close=move || ex.share_link.set(None)/>
                    })}
                    <details class="exercise-task" open=true>
                        <summary>"Task"</summary>
                        <div class="statement" inner_html=v.statement_html.clone()></div>
                        <table class="exercise-interface" aria-label="Interface">
                            <thead><tr><th>"Variable"</th><th>"Type"</th><th>"Declared as"</th><th>"Meaning"</th></tr></thead>
                            <tbody>
                                {v.interface.iter().map(|i| {
                                    let kind = match i.direction {
                                        Direction::Input => "VAR_INPUT",
                                        Direction::Output => "VAR_OUTPUT",
                                    };
                                    view! {
                                        <tr><td><code>{i.name.clone()}</code></td><td>{i.ty.clone()}</td><td>{kind}</td><td>{i.meaning.clone()}</td></tr>
                                    }
                                }).collect_view()}
                            </tbody>
                        </table>
                        <p class="exercise-scenarios">{format!("{SCENARIOS}{scenarios}")}</p>
                    </details>
                    <ReportView/>
                </section>
            }
        })
    }
}
