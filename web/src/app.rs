//! The page layout: header with the project menu, the editor, and the simulation panels.

use leptos::prelude::*;

use crate::components::{
    controls::Controls, editor::Editor, header::Header, io::IoPanel, timeline::Timeline,
    variables::Variables,
};
use crate::state::AppState;

/// The whole app.
#[component]
pub fn App() -> impl IntoView {
    let state = AppState::new();
    provide_context(state);
    view! {
        <Header/>
        <Banner/>
        <main class="workspace">
            <section class="editor-pane" aria-label="Program">
                <Editor/>
            </section>
            <section class="sim-pane" aria-label="Simulation">
                <Controls/>
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
            let line = n.line;
            view! {
                <div class=class role="alert">
                    <span>{n.text.clone()}</span>
                    {line.map(|l| view! {
                        <button class="link" on:click=move |_| state.jump_to.set(Some((l, 1)))>
                            {format!("Go to line {l}")}
                        </button>
                    })}
                    <button class="close" aria-label="Dismiss" on:click=move |_| state.notice.set(None)>"×"</button>
                </div>
            }
        })
    }
}
