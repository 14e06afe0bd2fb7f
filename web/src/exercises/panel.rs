//! The exercise panel beside the editors: the statement, the interface, `Check`,
//! `Reset to starter`, `Share exercise`, and the last check's report.

use leptos::prelude::*;
use plc_core::exercise::Direction;

use super::report::ReportView;
use super::{language_name, Exercises, Screen};
use crate::components::share_box::{copy_to_clipboard, ShareBox};
use crate::state::AppState;

/// The open exercise (nothing when the open project is not an attempt).
#[component]
pub fn ExercisePanel() -> impl IntoView {
    let state = expect_context::<AppState>();
    let ex = expect_context::<Exercises>();
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
            let v = open.opened.view;
            let langs = v.languages.iter().map(|l| language_name(l)).collect::<Vec<_>>().join(", ");
            let scenarios = v.scenarios.iter().map(|s| {
                let random = if s.random { " (random inputs)" } else { "" };
                format!("{}{random}", s.name)
            }).collect::<Vec<_>>().join(" · ");
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
                        <p class="exercise-scenarios">{format!("Checked by {} scenario(s): {scenarios}", v.scenarios.len())}</p>
                    </details>
                    <ReportView/>
                </section>
            }
        })
    }
}
