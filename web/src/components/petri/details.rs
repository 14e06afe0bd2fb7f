//! The text behind the selected net element (a place's actions, a transition's guard, the
//! prologue …) with its problems, so a located problem shows the ST it is about.

use leptos::prelude::*;
use plc_core::build::Site;
use plc_core::petri::{NetElement, PetriPou};

use crate::components::editor::text::{highlight_html, offset_of, Mark};
use crate::i18n::{t, tf, K};
use crate::state::AppState;

/// The title and ST text of an element.
fn element_text(pou: &PetriPou, element: &NetElement) -> (String, String) {
    let net = &pou.net;
    match element {
        NetElement::Place(id) => match net.place(id) {
            Some(p) => (
                tf(K::petri_place_actions, &[("name", id), ("label", &p.label.to_string())]),
                p.actions.clone(),
            ),
            None => (tf(K::petri_place_name, &[("name", id)]), String::new()),
        },
        NetElement::Transition(id) => match net.transition(id) {
            Some(tr) => (
                tf(
                    K::petri_transition_guard,
                    &[("name", id), ("priority", &tr.priority.to_string())],
                ),
                tr.guard.clone(),
            ),
            None => (tf(K::petri_transition_name, &[("name", id)]), String::new()),
        },
        NetElement::Prologue => (t(K::petri_prologue).into(), pou.prologue.clone()),
        NetElement::Epilogue => (t(K::petri_epilogue).into(), pou.epilogue.clone()),
        NetElement::Declarations => (t(K::petri_declarations).into(), pou.declarations.clone()),
        NetElement::Emergency => match &net.emergency {
            Some(e) => {
                (tf(K::petri_emergency_condition, &[("place", &e.place)]), e.condition.clone())
            }
            None => (t(K::petri_emergency).into(), String::new()),
        },
        other => (other.to_string(), String::new()),
    }
}

/// The details of the element a clicked problem or a click on the net selected.
#[component]
pub fn ElementDetails(pou: Memo<Option<PetriPou>>, name: StoredValue<String>) -> impl IntoView {
    let state = expect_context::<AppState>();
    move || {
        let Some(Site::Petri { pou: p, element: Some(element), at }) = state.focus.get() else {
            return None;
        };
        if !name.with_value(|n| p.eq_ignore_ascii_case(n)) {
            return None;
        }
        let (title, text) = pou.with(|pou| pou.as_ref().map(|pou| element_text(pou, &element)))?;
        let marks: Vec<Mark> = at
            .map(|at| {
                let start = offset_of(&text, at.line, at.column);
                vec![Mark { start, end: start + 1, error: true }]
            })
            .unwrap_or_default();
        let problems: Vec<String> = state.diagnostics.with(|ds| {
            ds.iter()
                .filter(|d| matches!(&d.site, Site::Petri { pou: q, element: Some(e), .. } if q.eq_ignore_ascii_case(&p) && *e == element))
                .map(|d| format!("{}  {}", d.code, d.message()))
                .collect()
        });
        let shown =
            if text.trim().is_empty() { t(K::petri_empty).to_string() } else { text.clone() };
        Some(view! {
            <div class="pn-details" aria-label=t(K::petri_details)>
                <div class="panel-head">
                    <h3>{title}</h3>
                    <button class="close" aria-label=t(K::petri_close_details) on:click=move |_| state.focus.set(None)>"×"</button>
                </div>
                <pre class="code-view" tabindex="0"><code inner_html=highlight_html(&shown, &marks)></code></pre>
                {(!problems.is_empty()).then(|| view! {
                    <ul class="pn-details-problems">
                        {problems.into_iter().map(|m| view! { <li>{m}</li> }).collect_view()}
                    </ul>
                })}
            </div>
        })
    }
}
