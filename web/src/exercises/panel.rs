//! The exercise panel beside the editors: the statement, the interface, `Start in` (the
//! language of the attempt), `Program to check`, `Check`, `Reset to starter`, `Share
//! exercise`, and the last check's report.

use leptos::ev;
use leptos::prelude::*;
use plc_core::exercise::{graded_program, Direction};
use plc_core::project::ProgramPou;
use wasm_bindgen::JsCast;

use super::{language_name, starter_language_name, Exercises, Screen};
use crate::components::share_box::{copy_to_clipboard, ShareBox};
use crate::i18n::{t, tf, K};
use crate::lazy::{lazy_view, What};
use crate::state::{plural, AppState};

/// The open exercise (nothing when the open project is not an attempt).
#[component]
pub fn ExercisePanel() -> impl IntoView {
    let state = expect_context::<AppState>();
    let ex = expect_context::<Exercises>();
    let shown = expect_context::<crate::i18n::I18n>().shown;
    // The report's view is a chunk of its own, fetched at the first check.
    let has_report = Memo::new(move |_| ex.report.with(Option::is_some));
    let share = move |_| {
        leptos::task::spawn_local(async move {
            let link = match ex.link().await {
                Some(Ok(link)) => link,
                Some(Err(e)) => return state.error(e.to_string()),
                None => return,
            };
            ex.share_link.set(Some(link.clone()));
            if copy_to_clipboard(&link).await {
                state.info(t(K::exercise_link_copied));
            }
        });
    };
    move || {
        ex.open.get().map(|open| {
            let v = open.opened.view.localised(shown.get());
            let langs = v.languages.iter().map(|l| language_name(l)).collect::<Vec<_>>().join(", ");
            let scenarios = v.scenarios.iter().map(|s| {
                let n = u64::from(s.weight);
                let points = tf(plural(n, K::exercise_points_one, K::exercise_points_few, K::exercise_points_many), &[("n", &n.to_string())]);
                let line = if s.random { K::exercise_scenario_random } else { K::exercise_scenario };
                tf(line, &[("name", &s.name), ("points", &points)])
            }).collect::<Vec<_>>().join(" · ");
            let starters: Vec<(String, &'static str)> = open.opened.starters.iter().map(|s| {
                (s.language.clone(), starter_language_name(&s.language))

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
                <section class="exercise-panel" aria-label=t(K::exercise_exercise)>
                    <div class="exercise-head">
                        <h2 class="exercise-title">{v.title.clone()}</h2>
                        <span class="exercise-meta">{tf(K::exercise_level_meta, &[("level", &v.level.to_string()), ("languages", &langs)])}</span>
                        <div class="exercise-actions">
                            <button class="primary" on:click=move |_| ex.check(state)
                                disabled=move || ex.checking.get()>
                                {move || if ex.checking.get() { t(K::exercise_checking) } else { t(K::exercise_check) }}
                            </button>
                            <button on:click=move |_| ex.reset_to_starter(state)>{t(K::exercise_reset_to_starter)}</button>
                            <button on:click=share title=t(K::exercise_share_title)>{t(K::exercise_share)}</button>
                            <super::HandInActions/>
                            <button class="lms-hidden" on:click=move |_| ex.screen.set(Screen::Catalogue)>{t(K::exercise_all_exercises)}</button>
                        </div>
                    </div>
                    <div class="exercise-setup">
                        {(starters.len() > 1).then(|| view! {
                            <label class="field">
                                <span>{t(K::exercise_start_in)}</span>
                                <select aria-label=t(K::exercise_start_in) title=t(K::exercise_start_in_title)
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
                                    <span>{t(K::exercise_program_to_check)}</span>
                                    <select aria-label=t(K::exercise_program_to_check) title=t(K::exercise_program_to_check_title)
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
                        <ShareBox link=link label=t(K::exercise_link) close_label=t(K::exercise_close_link)
                            on_close=move || ex.share_link.set(None)/>
                    })}
                    <details class="exercise-task" open=task_open()>
                        <summary>{t(K::exercise_task)}</summary>
                        <div class="statement" inner_html=v.statement_html.clone()></div>
                        <table class="exercise-interface" aria-label=t(K::exercise_interface)>
                            <thead><tr><th>{t(K::exercise_variable)}</th><th>{t(K::exercise_type)}</th><th>{t(K::exercise_declared_as)}</th><th>{t(K::exercise_meaning)}</th></tr></thead>
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
                        <p class="exercise-scenarios">{tf(K::exercise_scenarios, &[("scenarios", &scenarios)])}</p>

                    </details>
                    {move || has_report.get().then(|| lazy_view(What::Report, crate::lazy::report_view))}
                </section>
            }
        })
    }
}

/// Whether the task starts unfolded: on a screen tall enough for it and the editor (at
/// 1280 × 800 it folds to its summary line so the editor is on the first screen, issue
/// 34), and on a phone, where the task has its own `Exercise` tab.
fn task_open() -> bool {
    let size = |f: fn(&web_sys::Window) -> Result<wasm_bindgen::JsValue, wasm_bindgen::JsValue>| {
        web_sys::window().and_then(|w| f(&w).ok()).and_then(|v| v.as_f64()).unwrap_or(0.0)
    };
    size(web_sys::Window::inner_height) >= 900.0 || size(web_sys::Window::inner_width) <= 700.0
}
