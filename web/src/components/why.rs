//! The `Explanation` region (issue 36): why a variable has its value, or a Petri net place
//! holds a token, at the scan the page shows. It reads the core's answer
//! (`plc_core::why::explain`, `explain_place`): what wrote the value, with a link that
//! shows the statement, rung, element or transition; the operands that decided it, each
//! with its own `Why is …?` button (at the scan the writer read it, so the student follows
//! the cause backwards scan by scan); the power path of a rung; a block's history; and
//! `When did NAME change?`, which jumps to the previous or next change.
//!
//! Only `lazy::explanation_view` names this module: it is a chunk of its own, fetched the
//! first time a `Why?` button is pressed.

use leptos::prelude::*;
use plc_core::build::Site;
use plc_core::sim::Simulator;
use plc_core::why::{self, Context, Explanation, Kind};

use crate::state::{AppState, RunMode, WhyTarget};

/// The words the region shows (one place, for the translation catalogue to come).
mod words {
    pub const TITLE: &str = "Why?";
    pub const CLOSE: &str = "Close explanation";
    pub const NO_PROGRAM: &str = "No program runs: fix the errors first.";
    pub const DECIDED_BY: &str = "Decided by";
    pub const POWER: &str = "Power flow";
    pub const HISTORY: &str = "History";
    pub const NO_CHANGE: &str = "none recorded";
    pub fn nothing_at_start() -> String {
        "Run or step the program first: scan 0 is the initial state, before any scan.".into()
    }
    pub fn since(scan: u64) -> String {
        format!("(since scan {scan})")
    }
    pub fn go_to_scan(scan: u64) -> String {
        format!("Go to scan {scan}")
    }
}

/// An operand with the question that follows it.
#[derive(Debug, Clone, PartialEq)]
struct OperandLink {
    name: String,
    text: String,
    since: u64,
    /// `Why is NAME VALUE?` at `scan`, when the operand can be read there.
    label: Option<String>,
    /// The scan on which the operand got the value the writer read.
    scan: u64,
}

/// An explanation with its links, ready to show.
#[derive(Debug, Clone, PartialEq)]
struct Answer {
    ex: Explanation,
    operands: Vec<OperandLink>,
    /// The name `When did NAME change?` asks about (the variable, or a place's step
    /// variable).
    changes_of: String,
}

fn explain_now(state: AppState, target: &WhyTarget, scan: u64) -> Result<Answer, String> {
    if scan == 0 {
        return Err(words::nothing_at_start());
    }
    state.project.with_untracked(|project| {
        state.sim_build.with_value(|build| {
            state.sim.with_value(|sim| {
                let (Some(build), Some(sim)) = (build.as_ref(), sim.as_ref()) else {
                    return Err(words::NO_PROGRAM.to_string());
                };
                let ctx = Context::new(project, build);
                let ex = match target {
                    WhyTarget::Var(path) => why::explain(&ctx, sim, path, scan),
                    WhyTarget::Place(place) => why::explain_place(&ctx, sim, place, scan),
                }
                .map_err(|e| capitalised(&e.to_string()))?;
                let operands = operand_links(sim, &ex);
                let changes_of = match &ex.place {
                    Some(p) => p.step_variable.clone(),
                    None => ex.var.clone(),
                };
                Ok(Answer { ex, operands, changes_of })
            })
        })
    })
}

fn capitalised(text: &str) -> String {
    let mut c = text.chars();
    match c.next() {
        Some(first) => first.to_uppercase().chain(c).collect(),
        None => String::new(),
    }
}

/// Each operand with its `Why?`: asked at the scan on which the operand got the value the
/// writer read (its `since_scan`), so following operands walks the causes backwards.
fn operand_links(sim: &Simulator, ex: &Explanation) -> Vec<OperandLink> {
    let first = sim.recorded_range().map_or(1, |r| r.0.max(1));
    ex.operands
        .iter()
        .map(|o| {
            let at = o.since_scan.max(first);
            // The question is asked only where the operand has the value the writer read
            // (an initial value overwritten on the first scan has no scan to ask at).
            let value = sim
                .view_at(at)
                .ok()
                .and_then(|v| v.read(&o.name).ok())
                .filter(|v| plc_core::export::value_text(v) == o.text);
            OperandLink {
                name: o.name.clone(),
                text: o.text.clone(),
                since: o.since_scan,
                label: value.map(|v| why::why_label(&o.name, &v)),
                scan: at,
            }
        })
        .collect()
}

/// The sentence that says what wrote the value.
fn writer_sentence(ex: &Explanation) -> String {
    let w = &ex.written_by;
    match (w.kind, w.since_scan) {
        (Kind::None, Some(k)) => format!(
            "Nothing wrote it on this scan; it has had this value since scan {k}, when {} wrote it.",
            w.describe()
        ),
        (Kind::None, None) => "Nothing wrote it since the first scan recorded.".to_string(),
        (Kind::Initial, _) => {
            "Its initial value: nothing has written it since the start.".to_string()
        }
        (Kind::Input | Kind::Forced, _) => format!("{}.", capitalised(&w.describe())),
        _ => format!("Written by {}.", w.describe()),
    }
}

/// The site the writer's link shows, and the link's text.
fn writer_link(ex: &Explanation) -> Option<(Site, String)> {
    let w = &ex.written_by;
    let site = w.site.clone().or_else(|| w.then.as_ref().and_then(|t| t.site.clone()))?;
    let label = match &site {
        Site::Project => return None,
        Site::St { line, .. } => format!("Go to line {line}"),
        Site::Ladder { pou, cell: Some((r, ..)) } => format!("Show rung {} of {pou}", r + 1),
        Site::Ladder { pou, .. } | Site::Declarations { pou, .. } => format!("Show {pou}"),
        Site::Network { pou, .. } => format!("Show the element in {pou}"),
        Site::Petri { pou, .. } => match w
            .element
            .as_deref()
            .or_else(|| w.then.as_ref().and_then(|t| t.element.as_deref()))
        {
            Some(e) => format!("Show {e} in {pou}"),
            None => format!("Show {pou}"),
        },
    };
    Some((site, label))
}

fn headline(ex: &Explanation) -> String {
    match &ex.place {
        Some(p) if p.holds_token => format!(
            "{} holds a token at scan {} ({} = {})",
            p.id, ex.scan, p.step_variable, p.step_value
        ),
        Some(p) => format!("{} holds no token at scan {}", p.id, ex.scan),
        None => format!("{} is {} at scan {}", ex.var, ex.value_text, ex.scan),
    }
}

/// The `Explanation` region.
#[component]
pub fn Explanation() -> impl IntoView {
    let state = expect_context::<AppState>();
    let answer = Memo::new(move |_| {
        let q = state.why.get()?;
        // While running, the scan asked about; paused, the scan the page shows (so the
        // explanation follows Step back, Step and the slider).
        let scan =
            if state.run_mode.get() == RunMode::Running { q.scan } else { state.displayed_scan() };
        Some(untrack(|| explain_now(state, &q.target, scan)))
    });
    let when_open = RwSignal::new(false);
    let close = move |_| state.why.set(None);
    view! {
        <section class="panel explanation" role="region" aria-label="Explanation">
            <div class="panel-head">
                <h2>{words::TITLE}</h2>
                <button class="close" aria-label=words::CLOSE on:click=close>"×"</button>
            </div>
            {move || answer.get().map(|a| match a {
                Err(e) => view! { <p class="muted">{e}</p> }.into_any(),
                Ok(a) => answer_view(state, a, when_open).into_any(),
            })}
        </section>
    }
}

fn answer_view(state: AppState, a: Answer, when_open: RwSignal<bool>) -> impl IntoView {
    let ex = a.ex;
    let text = ex
        .written_by
        .text
        .clone()
        .or_else(|| ex.written_by.then.as_ref().and_then(|t| t.text.clone()));
    let link = writer_link(&ex).map(|(site, label)| {
        view! { <button class="link" on:click=move |_| state.reveal(&site)>{label}</button> }
    });
    let operands = (!a.operands.is_empty()).then(|| {
        view! {
            <h3>{words::DECIDED_BY}</h3>
            <ul class="why-operands">
                {a.operands.into_iter().map(|o| {
                    let follow = o.label.map(|label| {
                        let (name, at) = (o.name.clone(), o.scan);
                        view! {
                            <button class="small" on:click=move |_| {
                                if at != state.displayed_scan() {
                                    state.show_scan(at);
                                }
                                state.ask_why(&name);
                            }>{label}</button>
                        }
                    });
                    view! {
                        <li>
                            <code>{o.name.clone()}</code>" "{o.text.clone()}" "
                            <span class="muted">{words::since(o.since)}</span>" "
                            {follow}
                        </li>
                    }
                }).collect_view()}
            </ul>
        }
    });
    let power = (!ex.path.is_empty()).then(|| {
        view! {
            <h3>{words::POWER}</h3>
            <ul class="why-power">
                {ex.path.iter().map(|s| view! {
                    <li>{format!("{} (row {}, column {}): {}", s.element, s.row, s.column,
                        if s.powered { "power passes" } else { "no power" })}</li>
                }).collect_view()}
            </ul>
        }
    });
    let block = ex.block.clone().map(|b| {
        view! {
            <p>{format!("{} is a {}.", b.instance, b.fb)}</p>
            {(!b.history.is_empty()).then(|| view! {
                <h3>{words::HISTORY}</h3>
                <ul class="why-history">
                    {b.history.iter().map(|c| view! {
                        <li>{format!("scan {}: {} = {}", c.scan, c.name, json_text(&c.value))}</li>
                    }).collect_view()}
                </ul>
            })}
        }
    });
    let name = a.changes_of;
    let when_label = why::when_label(&name);
    let (previous, next) = (ex.previous_change, ex.next_change);
    let jump = move |k: Option<u64>| {
        match k {
        Some(k) => view! {
            <button class="link" on:click=move |_| state.show_scan(k)>{words::go_to_scan(k)}</button>
        }
        .into_any(),
        None => view! { <span class="muted">{words::NO_CHANGE}</span> }.into_any(),
    }
    };
    view! {
        <p class="why-head">{headline(&ex)}</p>
        <p class="why-writer">{writer_sentence(&ex)}" "{link}</p>
        {text.map(|t| view! { <p><code class="why-text">{t}</code></p> })}
        {operands}
        {power}
        {block}
        <p>
            <button class="small" aria-expanded=move || when_open.get().to_string()
                on:click=move |_| when_open.update(|o| *o = !*o)>{when_label}</button>
        </p>
        <Show when=move || when_open.get()>
            <p class="why-changes">
                "Previous change: "{jump(previous)}" · Next change: "{jump(next)}
            </p>
        </Show>
    }
}

/// A JSON value as IEC text writes it (`TRUE`, `3`, `T#2s`).
fn json_text(v: &serde_json::Value) -> String {
    match v {
        serde_json::Value::Bool(true) => "TRUE".to_string(),
        serde_json::Value::Bool(false) => "FALSE".to_string(),
        serde_json::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}
