//! The chart of a POU whose body is a textual SFC, drawn top-down from the core's outline
//! (`plc_core::sfc::outline`): steps (the initial one framed twice, its action associations
//! beside it), transitions as bars with their conditions, AND divergences and convergences
//! as double lines, links back up routed on the right. Read-only: the chart is edited as
//! text in the ST editor. While its PROGRAM runs, the active steps (`Step.X`) are lit.

use leptos::prelude::*;
use plc_core::sfc::outline::{outlines, ChartLayout, Outline};
use plc_core::vm::Value;

use crate::components::ladder::geometry::clip;
use crate::i18n::{t, tf, K};
use crate::state::{AppState, PouView};

/// Half the width and height of a step box.
const STEP_HW: f64 = 44.0;
const STEP_HH: f64 = 17.0;
/// Half the width of a transition bar.
const BAR_HW: f64 = 22.0;

/// The links of one transition: from each step it leaves to its bar, from its bar to each
/// step it activates (down, or routed on the right up to a step above), and the double
/// lines of AND convergences and divergences.
fn links(chart: &Outline, lay: &ChartLayout, t: usize, lane: f64) -> impl IntoView {
    let tr = &chart.transitions[t];
    let (tx, ty) = lay.transitions[t];
    let mut paths: Vec<String> = Vec::new();
    let above = ty - 14.0;
    let below = ty + 14.0;
    for &s in &tr.from {
        let (sx, sy) = lay.steps[s];
        let join = if tr.from.len() > 1 { above - 4.0 } else { ty };
        paths.push(format!(
            "M{sx} {} L{sx} {} L{tx} {} L{tx} {ty}",
            sy + STEP_HH,
            (sy + STEP_HH + join) / 2.0,
            (sy + STEP_HH + join) / 2.0
        ));
    }
    for &s in &tr.to {
        let (sx, sy) = lay.steps[s];
        let top = sy - STEP_HH;
        let start = if tr.to.len() > 1 { below + 4.0 } else { ty };
        if top > ty {
            let mid = (start + top) / 2.0;
            paths.push(format!("M{tx} {start} L{tx} {mid} L{sx} {mid} L{sx} {top}"));
        } else {
            // Back up: down a little, out to the lane on the right, up, and in from above.
            let over = top - 18.0;
            paths.push(format!(
                "M{tx} {start} L{tx} {} L{lane} {} L{lane} {over} L{sx} {over} L{sx} {top}",
                ty + 22.0,
                ty + 22.0
            ));
        }
    }
    let span = |xs: Vec<f64>| {
        let lo = xs.iter().copied().fold(f64::MAX, f64::min).min(tx);
        let hi = xs.iter().copied().fold(f64::MIN, f64::max).max(tx);
        (lo - 10.0, hi + 10.0)
    };
    let doubles = [
        (tr.from.len() > 1)
            .then(|| (span(tr.from.iter().map(|&s| lay.steps[s].0).collect()), above)),
        (tr.to.len() > 1).then(|| (span(tr.to.iter().map(|&s| lay.steps[s].0).collect()), below)),
    ];
    view! {
        {paths.into_iter().map(|d| view! { <path class="sfc-link" d=d marker-end="url(#sfc-arrow)"/> }).collect_view()}
        {doubles.into_iter().flatten().map(|((x0, x1), y)| view! {
            <line class="sfc-double" x1=x0 y1=y - 2.0 x2=x1 y2=y - 2.0/>
            <line class="sfc-double" x1=x0 y1=y + 2.0 x2=x1 y2=y + 2.0/>
        }).collect_view()}
    }
}

/// The drawing of a chart; `active` gives each step's state while it runs.
fn chart_svg(chart: &Outline, active: Memo<Vec<bool>>) -> impl IntoView {
    let lay = chart.layout();
    let xs = lay.steps.iter().chain(&lay.transitions).map(|p| p.0);
    let ys = lay.steps.iter().chain(&lay.transitions).map(|p| p.1);
    let (x0, x1) = xs.fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
    let (y0, y1) = ys.fold((f64::MAX, f64::MIN), |(a, b), y| (a.min(y), b.max(y)));
    if !x0.is_finite() {
        return view! { <p class="muted">{t(K::sfc_no_steps)}</p> }.into_any();
    }
    let lane = x1 + STEP_HW + 150.0;
    let (vx, vy) = (x0 - STEP_HW - 150.0, y0 - STEP_HH - 40.0);
    let (vw, vh) = (lane + 40.0 - vx, y1 + STEP_HH + 40.0 - vy);
    let links = (0..chart.transitions.len()).map(|t| links(chart, &lay, t, lane)).collect_view();
    let bars = chart
        .transitions
        .iter()
        .enumerate()
        .map(|(t, tr)| {
            let (x, y) = lay.transitions[t];
            let name = tr.name.clone().unwrap_or_default();
            let label = tf(
                K::sfc_transition,
                &[
                    ("name", &if name.is_empty() { String::new() } else { format!("{name} ") }),
                    ("condition", &tr.condition),
                ],
            );
            view! {
                <g class="sfc-transition" role="img" aria-label=label>
                    <title>{tr.condition.clone()}</title>
                    <rect class="sfc-bar" x=x - BAR_HW y=y - 2.5 width=2.0 * BAR_HW height="5"/>
                    <text class="sfc-tname" x=x - BAR_HW - 6.0 y=y + 4.0>{clip(&name, 12)}</text>
                    <text class="sfc-cond" x=x + BAR_HW + 6.0 y=y + 4.0>{clip(&tr.condition, 24)}</text>
                </g>
            }
        })
        .collect_view();
    let steps = chart
        .steps
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let (x, y) = lay.steps[i];
            let is_active = move || active.with(|a| a.get(i).copied().unwrap_or(false));
            let name = s.name.clone();
            let actions = s.actions.join(", ");
            let initial = s.initial;
            view! {
                <g class="sfc-step" class:active=is_active role="img" data-step=name.clone()
                    aria-label=move || tf(
                        if initial { K::sfc_initial_step } else { K::sfc_step },
                        &[("name", &name), ("active", if is_active() { t(K::sfc_active) } else { "" })],
                    )>
                    <rect x=x - STEP_HW y=y - STEP_HH width=2.0 * STEP_HW height=2.0 * STEP_HH rx="2"/>
                    {initial.then(|| view! {
                        <rect class="sfc-inner" x=x - STEP_HW + 4.0 y=y - STEP_HH + 4.0
                            width=2.0 * STEP_HW - 8.0 height=2.0 * STEP_HH - 8.0/>
                    })}
                    <text class="sfc-step-name" x=x y=y + 4.0>{clip(&s.name, 10)}</text>
                    {(!actions.is_empty()).then(|| view! {
                        <text class="sfc-actions" x=x + STEP_HW + 8.0 y=y - 6.0>{clip(&actions, 36)}</text>
                    })}
                </g>
            }
        })
        .collect_view();
    view! {
        <svg class="sfc-svg" viewBox=format!("{vx} {vy} {vw} {vh}") width=vw height=vh
            role="group" aria-label=tf(K::sfc_chart, &[("name", &chart.pou)])>
            <defs>
                <marker id="sfc-arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6"
                    markerHeight="6" orient="auto-start-reverse">
                    <path d="M0 0 L10 5 L0 10 z" class="pn-arrowhead"/>
                </marker>
            </defs>
            {links}
            {bars}
            {steps}
        </svg>
    }
    .into_any()
}

/// The chart view of the SFC POU `name`.
#[component]
pub fn SfcView(name: String) -> impl IntoView {
    let state = expect_context::<AppState>();
    let key = name.clone();
    let chart = Memo::new(move |_| {
        state
            .project
            .with(|p| outlines(&p.source).into_iter().find(|o| o.pou.eq_ignore_ascii_case(&key)))
    });
    let key = name.clone();
    let runs =
        Memo::new(move |_| state.running.get().is_some_and(|r| r.eq_ignore_ascii_case(&key)));
    let active = Memo::new(move |_| {
        if !runs.get() {
            return Vec::new();
        }
        chart.with(|c| {
            let Some(c) = c.as_ref() else { return Vec::new() };
            state
                .with_readout(|s| {
                    c.steps
                        .iter()
                        .map(|st| {
                            matches!(s.read(&format!("{}.X", st.name)), Ok(Value::Bool(true)))
                        })
                        .collect()
                })
                .unwrap_or_default()
        })
    });
    let title = name.clone();
    let status = move || {
        if runs.get() {
            return None;
        }
        let program = chart.with(|c| c.as_ref().is_some_and(|c| c.program));
        Some(match (program, state.running.get()) {
            (false, _) => t(K::sfc_status_fb).to_string(),
            (true, Some(r)) => tf(K::sfc_status_other, &[("program", &r), ("name", &name)]),
            (true, None) => t(K::sfc_status_idle).to_string(),
        })
    };
    view! {
        <section class="panel sfc-view" aria-label=tf(K::sfc_chart, &[("name", &title)])>
            <div class="ed-toolbar">
                <h2>"SFC"</h2>
                <span class="pou-title">{title.clone()}</span>
                <span class="ed-spacer"></span>
                <button title=t(K::sfc_edit_as_text_title)
                    on:click=move |_| state.view.set(PouView::St)>{t(K::sfc_edit_as_text)}</button>
            </div>
            {move || status().map(|s| view! { <p class="view-note">{s}</p> })}
            <div class="sfc-wrap" tabindex="0">
                {move || match chart.get() {
                    Some(c) => chart_svg(&c, active).into_any(),
                    None => view! { <p class="muted">{t(K::sfc_gone)}</p> }.into_any(),
                }}
            </div>
        </section>
    }
}
