//! The analysis summary of a net (guards ignored): safe, bounded, live, reversible, the
//! deadlocks with the firing sequence that reaches each, dead transitions and places no
//! state-machine component covers. Computed by the core when the panel is opened; a
//! deadlock is a button that plays its firing sequence on the net.

use leptos::prelude::*;
use plc_core::petri::{analyze, build, conflicts, panel_budget, NetAnalysis, PetriPou, PtNet};

use super::play::Play;

fn verdict(v: Option<bool>) -> (&'static str, &'static str) {
    match v {
        Some(true) => ("yes", "chip chip-yes"),
        Some(false) => ("no", "chip chip-no"),
        None => ("unknown", "chip"),
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
            format!(
                "{} and {} both take the token of {}: {} is tested first (priority {} against {})",
                net.transition_names[c.first],
                net.transition_names[c.second],
                net.place_names[c.place],
                net.transition_names[c.first],
                pou.net.transitions[c.first].priority,
                pou.net.transitions[c.second].priority,
            )
        })
        .collect();
    view! {
        <h3>"Conflicts"</h3>
        {if list.is_empty() {
            view! { <p class="small-text">"None: the generated code does not depend on priorities."</p> }.into_any()
        } else {
            view! {
                <ul class="pn-conflicts small-text" aria-label="Conflicts">
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
        ("Safe", a.safe),
        ("Bounded", a.bounded),
        ("Live", a.live),
        ("Reversible", a.reversible),
        ("Deadlock-free", deadlock_free),
    ];
    let t = |i: usize| net.transition_names[i].clone();
    let deadlocks = a
        .deadlocks
        .iter()
        .map(|d| {
            let path: Vec<String> = d.path.iter().map(|&i| t(i)).collect();
            let path =
                if path.is_empty() { "at the start".to_string() } else { path.join(" → ") };
            let steps = d.path.clone();
            view! {
                <li>
                    <button class="link" title="Play the firing sequence on the net, one transition per step"
                        on:click=move |_| play.set(Some(Play { path: steps.clone(), step: 0, game: false }))>
                        {format!("{} after {path}", marking_text(net, &d.marking))}
                    </button>
                </li>
            }
        })
        .collect_view();
    let dead = match &a.dead_transitions {
        Some(d) if d.is_empty() => "none".to_string(),
        Some(d) => d.iter().map(|&i| t(i)).collect::<Vec<_>>().join(", "),
        None => "unknown (the search was cut short)".to_string(),
    };
    let uncovered: Vec<String> = a.uncovered.iter().map(|&i| net.place_names[i].clone()).collect();
    let components = a.components.len();
    view! {
        <p class="muted small-text">
            {format!(
                "{} reachable markings{}. Guards are ignored: this describes what the net allows.",
                a.states,
                if a.complete { "" } else { " (incomplete: the search budget ran out)" }
            )}
        </p>
        <dl class="pn-verdicts">
            {rows.into_iter().map(|(name, v)| {
                let (text, class) = verdict(v);
                view! { <div><dt>{name}</dt><dd><span class=class>{text}</span></dd></div> }
            }).collect_view()}
        </dl>
        {(!a.deadlocks.is_empty()).then(|| view! {
            <h3>"Deadlocks"</h3>
            <ul class="pn-deadlocks">{deadlocks}</ul>
        })}
        <p class="small-text">{format!("Dead transitions: {dead}")}</p>
        <p class="small-text">{format!(
            "State-machine components: {components}{}",
            if uncovered.is_empty() { String::new() } else { format!("; not covered: {}", uncovered.join(", ")) }
        )}</p>
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
                view! { <p class="muted">"Fix the net's errors (see Problems) to analyse it."</p> }
                    .into_any()
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
            <summary>"Analysis (safe, live, reversible, deadlocks)"</summary>
            {body}
        </details>
    }
}
