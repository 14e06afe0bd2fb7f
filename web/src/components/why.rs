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
use plc_core::why::{self, Context, Explanation, Kind, WrittenBy};

use crate::components::variables::why_label;
use crate::i18n::{t, tf, K};
use crate::state::{AppState, RunMode, WhyTarget};

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
        return Err(t(K::why_nothing_at_start).to_string());
    }
    state.project.with_untracked(|project| {
        state.sim_build.with_value(|build| {
            state.sim.with_value(|sim| {
                let (Some(build), Some(sim)) = (build.as_ref(), sim.as_ref()) else {
                    return Err(t(K::why_no_program).to_string());
                };
                let ctx = Context::new(project, build);
                let ex = match target {
                    WhyTarget::Var(path) => why::explain(&ctx, sim, path, scan),
                    WhyTarget::Place(place) => why::explain_place(&ctx, sim, place, scan),
                }
                .map_err(|e| why_error(&e))?;
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

/// Why the explanation cannot be given, as a sentence.
fn why_error(e: &why::WhyError) -> String {
    use plc_core::sim::RecordError;
    let n = |x: u64| x.to_string();
    match e {
        why::WhyError::Unknown(name) => tf(K::why_unknown, &[("name", name)]),
        why::WhyError::Record(RecordError::NotRecording) => t(K::why_not_recording).to_string(),
        why::WhyError::Record(RecordError::OutOfRange { scan, first, last }) => tf(
            K::why_not_recorded,
            &[("scan", &n(*scan)), ("first", &n(*first)), ("last", &n(*last))],
        ),
        why::WhyError::Record(RecordError::TooLarge { bytes }) => {
            tf(K::why_too_large, &[("kb", &(bytes / 1024).to_string())])
        }
        why::WhyError::Record(RecordError::Replay(m)) => tf(K::why_not_replayed, &[("reason", m)]),
        other => capitalised(&other.to_string()),
    }
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
                label: value.map(|v| why_label(&o.name, &v)),
                scan: at,
            }
        })
        .collect()
}

/// The sentence that says what wrote the value.
fn writer_sentence(ex: &Explanation) -> String {
    let w = &ex.written_by;
    match (w.kind, w.since_scan) {
        (Kind::None, Some(k)) => {
            tf(K::why_unchanged_since, &[("scan", &k.to_string()), ("writer", &describe(w))])
        }
        (Kind::None, None) => t(K::why_unchanged_since_first).to_string(),
        (Kind::Initial, _) => t(K::why_initial_sentence).to_string(),
        (Kind::Input | Kind::Forced, _) => format!("{}.", capitalised(&describe(w))),
        _ => tf(K::why_written_by, &[("writer", &describe(w))]),
    }
}

/// The writer in words (as `WrittenBy::describe` says it in English): `Main line 9:
/// Motor := …`, `Latch rung 1 (coil Motor): …`, `a value from outside`.
fn describe(w: &WrittenBy) -> String {
    let pou = w.pou.as_deref().unwrap_or_else(|| t(K::why_the_program));
    let text = w.text.as_deref().unwrap_or_default();
    let element = w.element.as_deref().unwrap_or_default();
    let with_text = |head: String| if text.is_empty() { head } else { format!("{head}: {text}") };
    let line = |key: K| w.line.map(|l| tf(key, &[("line", &l.to_string())])).unwrap_or_default();
    match w.kind {
        Kind::Statement => match (w.line, &w.element) {
            (Some(l), _) => {
                with_text(tf(K::why_writer_line, &[("pou", pou), ("line", &l.to_string())]))
            }
            (None, Some(e)) => with_text(format!("{pou} {e}")),
            (None, None) => with_text(pou.to_string()),
        },
        Kind::Rung => {
            let rung = w.rung.unwrap_or(0).to_string();
            let head = tf(K::why_writer_rung, &[("pou", pou), ("rung", &rung)]);
            let element = w.element.as_deref().map(|e| format!(" ({e})")).unwrap_or_default();
            with_text(format!("{head}{element}"))
        }
        Kind::Element => {
            with_text(tf(K::why_writer_element, &[("pou", pou), ("element", element)]))
        }
        Kind::Transition => {
            let head = tf(K::why_writer_transition, &[("pou", pou), ("transition", element)]);
            let line = line(K::why_writer_at_line);
            match text.is_empty() {
                true => format!("{head}{line}"),
                false => {
                    let condition = tf(K::why_writer_condition, &[("condition", text)]);
                    format!("{head}{line}{condition}")
                }
            }
        }
        Kind::StepAction => {
            let head = if element.starts_with("action ") {
                format!("{pou} {element}")
            } else {
                tf(K::why_writer_action, &[("pou", pou), ("step", element)])
            };
            with_text(format!("{head}{}", line(K::why_writer_in_line)))
        }
        Kind::Input if text.is_empty() => t(K::why_writer_input).to_string(),
        Kind::Forced if text.is_empty() => t(K::why_writer_forcing).to_string(),
        Kind::Input | Kind::Forced => text.to_string(),
        Kind::Initial => t(K::why_writer_initial).to_string(),
        Kind::None => match &w.then {
            Some(then) => describe(then),
            None => t(K::why_writer_nothing).to_string(),
        },
    }
}

/// The site the writer's link shows, and the link's text.
fn writer_link(ex: &Explanation) -> Option<(Site, String)> {
    let w = &ex.written_by;
    let site = w.site.clone().or_else(|| w.then.as_ref().and_then(|t| t.site.clone()))?;
    let label = match &site {
        Site::Project => return None,
        Site::St { line, .. } => tf(K::why_go_to_line, &[("line", &line.to_string())]),
        Site::Ladder { pou, cell: Some((r, ..)) } => {
            tf(K::why_show_rung, &[("rung", &(r + 1).to_string()), ("pou", pou)])
        }
        Site::Ladder { pou, .. } | Site::Declarations { pou, .. } => {
            tf(K::why_show_pou, &[("pou", pou)])
        }
        Site::Network { pou, .. } => tf(K::why_show_element_in, &[("pou", pou)]),
        Site::Petri { pou, .. } => match w
            .element
            .as_deref()
            .or_else(|| w.then.as_ref().and_then(|t| t.element.as_deref()))
        {
            Some(e) => tf(K::why_show_named_in, &[("element", e), ("pou", pou)]),
            None => tf(K::why_show_pou, &[("pou", pou)]),
        },
    };
    Some((site, label))
}

fn headline(ex: &Explanation) -> String {
    match &ex.place {
        Some(p) if p.holds_token => tf(
            K::why_holds_token,
            &[
                ("place", &p.id),
                ("scan", &ex.scan.to_string()),
                ("variable", &p.step_variable),
                ("value", &p.step_value.to_string()),
            ],
        ),
        Some(p) => tf(K::why_holds_no_token, &[("place", &p.id), ("scan", &ex.scan.to_string())]),
        None => tf(
            K::why_value_at_scan,
            &[("name", &ex.var), ("value", &ex.value_text), ("scan", &ex.scan.to_string())],
        ),
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
        <section class="panel explanation" role="region" aria-label=t(K::why_region)>
            <div class="panel-head">
                <h2>{t(K::why_title)}</h2>
                <button class="close" aria-label=t(K::why_close) on:click=close>"×"</button>
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
            <h3>{t(K::why_decided_by)}</h3>
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
                            <span class="muted">{tf(K::why_since, &[("scan", &o.since.to_string())])}</span>" "
                            {follow}
                        </li>
                    }
                }).collect_view()}
            </ul>
        }
    });
    let power = (!ex.path.is_empty()).then(|| {
        view! {
            <h3>{t(K::why_power)}</h3>
            <ul class="why-power">
                {ex.path.iter().map(|s| view! {
                    <li>{tf(if s.powered { K::why_power_passes } else { K::why_no_power }, &[
                        ("element", &s.element),
                        ("row", &s.row.to_string()),
                        ("column", &s.column.to_string()),
                    ])}</li>
                }).collect_view()}
            </ul>
        }
    });
    let block = ex.block.clone().map(|b| {
        view! {
            <p>{tf(K::why_instance_of, &[("instance", &b.instance), ("block", &b.fb)])}</p>
            {(!b.history.is_empty()).then(|| view! {
                <h3>{t(K::why_history)}</h3>
                <ul class="why-history">
                    {b.history.iter().map(|c| view! {
                        <li>{tf(K::why_history_item, &[("scan", &c.scan.to_string()), ("name", &c.name), ("value", &json_text(&c.value))])}</li>
                    }).collect_view()}
                </ul>
            })}
        }
    });
    let name = a.changes_of;
    let when_label = tf(K::why_when_changed, &[("name", &name)]);
    let (previous, next) = (ex.previous_change, ex.next_change);
    let jump = move |k: Option<u64>| {
        match k {
        Some(k) => view! {
            <button class="link" on:click=move |_| state.show_scan(k)>{tf(K::why_go_to_scan, &[("scan", &k.to_string())])}</button>
        }
        .into_any(),
        None => view! { <span class="muted">{t(K::why_none_recorded)}</span> }.into_any(),
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
                {t(K::why_previous_change)}{jump(previous)}{t(K::why_next_change)}{jump(next)}
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
