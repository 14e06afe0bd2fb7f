//! The analysis summary of a net (guards ignored): safe, bounded, live, reversible, the
//! deadlocks with the firing sequence that reaches each, dead transitions and places no
//! state-machine component covers. Computed by the core when the panel is opened; a
//! deadlock is a button that plays its firing sequence on the net.

use leptos::prelude::*;
use plc_core::petri::{analyze, build, conflicts, panel_budget, NetAnalysis, PetriPou, PtNet};

use super::play::Play;
use crate::i18n::{t, tf, K};

fn verdict(v: Option<bool>) -> (&'static str, &'static str) {
    match v {
        Some(true) => (t(K::petri_yes), "chip chip-yes"),
        Some(false) => (t(K::petri_no), "chip chip-no"),
        None => (t(K::petri_unknown), "chip"),
    }
}

fn marking_text(net: &PtNet, marking: &[u32]) -> String {
    let names: Vec<String> = marking
        .iter()
        .enumerate()
        .filter(|(_, &k)| k > 0)
        .map(|(i, &k)| {
            let n = &net.place_names[i];
            if k == 1 {
                n.clone()
            } else {
                format!("{k}·{n}")
            }
        })
        .collect();
    format!("{{{}}}", names.join(", "))
}

/// The conflicts that make the generated code depend on priorities: two transitions that
/// take the token of one place, and guards that are not provably exclusive.
fn conflict_list(pou: &PetriPou, net: &PtNet) -> impl IntoView {
    let list: Vec<String> = conflicts(pou, net)
        .into_iter()
        .filter(|c| !c.exclusive)
        .map(|c| {
            tf(
                K::petri_conflict,
                &[
                    ("first", &net.transition_names[c.first]),
                    ("second", &net.transition_names[c.second]),
                    ("place", &net.place_names[c.place]),
                    ("first_priority", &pou.net.transitions[c.first].priority.to_string()),
                    ("second_priority", &pou.net.transitions[c.second].priority.to_string()),
                ],
            )
        })
        .collect();
    view! {
        <h3>{t(K::petri_conflicts)}</h3>
        {if list.is_empty() {
            view! { <p class="small-text">{t(K::petri_conflicts_none)}</p> }.into_any()
        } else {
            view! {
                <ul class="pn-conflicts small-text" aria-label=t(K::petri_conflicts)>
                    {list.into_iter().map(|c| view! { <li>{c}</li> }).collect_view()}
                </ul>
            }.into_any()
        }}
    }
}

fn summary(net: &PtNet, a: &NetAnalysis, play: RwSignal<Option<Play>>) -> impl IntoView {
    let deadlock_free = if !a.deadlocks.is_empty() {
        Some(false)
    } else if a.complete && a.bounded == Some(true) {
        Some(true)
    } else {
        None
    };
    let rows = [
        (t(K::petri_safe), a.safe),
        (t(K::petri_bounded), a.bounded),
        (t(K::petri_live), a.live),
        (t(K::petri_reversible), a.reversible),
        (t(K::petri_deadlock_free), deadlock_free),
    ];
    let name_of = |i: usize| net.transition_names[i].clone();
    let deadlocks = a
        .deadlocks
        .iter()
        .map(|d| {
            let path: Vec<String> = d.path.iter().map(|&i| name_of(i)).collect();
            let path =
                if path.is_empty() { t(K::petri_at_the_start).to_string() } else { path.join(" → ") };
            let steps = d.path.clone();
            view! {
                <li>
                    <button class="link" title=t(K::petri_deadlock_play_title)
                        on:click=move |_| play.set(Some(Play { path: steps.clone(), step: 0, game: false }))>
                        {tf(K::petri_deadlock_after, &[("marking", &marking_text(net, &d.marking)), ("path", &path)])}
                    </button>
                </li>
            }
        })
        .collect_view();
    let dead = match &a.dead_transitions {
        Some(d) if d.is_empty() => t(K::petri_dead_none).to_string(),
        Some(d) => d.iter().map(|&i| name_of(i)).collect::<Vec<_>>().join(", "),
        None => t(K::petri_dead_unknown).to_string(),
    };
    let uncovered: Vec<String> = a.uncovered.iter().map(|&i| net.place_names[i].clone()).collect();
    let components = a.components.len();
    let uncovered = if uncovered.is_empty() {
        String::new()
    } else {
        tf(K::petri_uncovered, &[("places", &uncovered.join(", "))])
    };
    let markings = tf(
        super::plural(
            a.states as u64,
            [K::petri_markings_one, K::petri_markings_few, K::petri_markings_many],
        ),
        &[("n", &a.states.to_string())],
    );
    let incomplete = if a.complete { "" } else { t(K::petri_analysis_incomplete) };
    view! {
        <p class="muted small-text">
            {tf(K::petri_analysis_note, &[("markings", &markings), ("incomplete", incomplete)])}
        </p>
        <dl class="pn-verdicts">
            {rows.into_iter().map(|(name, v)| {
                let (text, class) = verdict(v);
                view! { <div><dt>{name}</dt><dd><span class=class>{text}</span></dd></div> }
            }).collect_view()}
        </dl>
        {(!a.deadlocks.is_empty()).then(|| view! {
            <h3>{t(K::petri_deadlocks)}</h3>
            <ul class="pn-deadlocks">{deadlocks}</ul>
        })}
        <p class="small-text">{tf(K::petri_dead_transitions, &[("dead", &dead)])}</p>
        <p class="small-text">{tf(K::petri_state_machine_components, &[("count", &components.to_string()), ("uncovered", &uncovered)])}</p>
    }
}

/// The collapsible analysis panel of a net.
#[component]
pub fn AnalysisPanel(pou: Memo<Option<PetriPou>>, play: RwSignal<Option<Play>>) -> impl IntoView {
    let open = RwSignal::new(false);
    let body = move || {
        if !open.get() {
            return ().into_any();
        }
        pou.with(|p| match p.as_ref().map(|p| build(&p.net)) {
            Some(Ok(net)) => {
                let a = analyze(&net, panel_budget(net.places()));
                let pou = p.as_ref().map(|p| conflict_list(p, &net));
                view! { {summary(&net, &a, play)} {pou} }.into_any()
            }
            Some(Err(_)) => {
                view! { <p class="muted">{t(K::petri_analysis_fix_errors)}</p> }.into_any()
            }
            None => ().into_any(),
        })
    };
    view! {
        <details class="pn-analysis" on:toggle=move |ev| {
            use wasm_bindgen::JsCast;
            let el = ev.target().and_then(|t| t.dyn_into::<web_sys::HtmlDetailsElement>().ok());
            open.set(el.is_some_and(|d| d.open()));
        }>
            <summary>{t(K::petri_analysis)}</summary>
            {body}
        </details>
    }
}
