//! The report of a check: the score, each scenario passed or failed, and for a failure
//! what was expected, what happened (the first wrong output, its time and scan), the hint,
//! and a timeline of the scans around it — the failing condition as it should have been
//! drawn against what it was, the interface's values, and the cursor on the first wrong
//! scan.

use leptos::prelude::*;
use plc_core::exercise::{time_text, Failure, Sample};

use super::Exercises;
use crate::i18n::{message_text, sentence_text, t, tf, K};

/// Width of the labels on the left of the timeline.
const LABEL_W: f64 = 170.0;
/// Width of the plot.
const PLOT_W: f64 = 560.0;
/// Height of one row.
const ROW_H: f64 = 26.0;
/// Space above the rows (the cursor's label).
const TOP: f64 = 18.0;

/// The report of the last check.
#[component]
pub fn ReportView() -> impl IntoView {
    let ex = expect_context::<Exercises>();
    let shown = expect_context::<crate::i18n::I18n>().shown;
    move || {
        ex.report.get().map(|r| {
            let lang = shown.get();
            let r = ex.open.with(|o| o.as_ref().map(|o| o.opened.view.localised_report(lang, r.clone()))).unwrap_or(r);
            let all = r.error.is_none() && r.score == r.total;
            let summary = match &r.error {
                Some(e) => tf(K::exercise_not_graded, &[("error", &sentence_text(r.error_msg.as_ref(), e))]),
                None if all => tf(K::exercise_all_pass, &[("score", &r.score.to_string()), ("total", &r.total.to_string())]),
                None => {
                    let said = r.score_said();
                    message_text(&said.message, None, &said.english)
                }
            };
            view! {
                <section class="exercise-report" aria-label=t(K::exercise_report) aria-live="polite">
                    {r.checked().map(|s| view! { <p class="report-program">{message_text(&s.message, None, &s.english)}</p> })}
                    <p class="report-score" class:report-pass=all class:report-fail=!all>{summary}</p>
                    <ul class="report-scenarios">
                        {r.scenarios.into_iter().map(|s| {
                            let passed = s.failure.is_none();
                            let name = s.name.clone();
                            view! {
                                <li class="report-scenario" class:passed=passed class:failed=!passed data-passed=passed.to_string()>
                                    <span class="report-mark" aria-hidden="true">{if passed { "✓" } else { "✗" }}</span>
                                    <span class="report-name">{s.name.clone()}</span>
                                    <span class="report-verdict">" "{if passed { t(K::exercise_scenario_passed) } else { t(K::exercise_scenario_failed) }}</span>
                                    {s.failure.map(|f| view! {
                                        <div class="report-failure">
                                            <p><strong>{t(K::exercise_expected)}" "</strong>{sentence_text(f.expected_msg.as_ref(), &f.expected)}</p>
                                            <p class="report-actual"><strong>{t(K::exercise_actual)}" "</strong>{sentence_text(f.actual_msg.as_ref(), &f.actual)}</p>
                                            {s.hint.clone().map(|h| view! { <p class="report-hint"><strong>{t(K::exercise_hint)}" "</strong>{h}</p> })}
                                            <FailureTimeline scenario=name.clone() failure=f/>
                                        </div>
                                    })}
                                </li>
                            }
                        }).collect_view()}
                    </ul>
                </section>
            }
        })
    }
}

/// One row of the timeline: a label and a value per sample.
struct Row {
    label: String,
    class: &'static str,
    values: Vec<Cell>,
}

/// A sample's value in a row.
#[derive(Clone, PartialEq)]
enum Cell {
    Bool(bool),
    Number(f64),
    Text(String),
    /// Any value is right (the expected row outside its window).
    Any,
}

fn cell_of(text: &str) -> Cell {
    match text {
        "TRUE" => Cell::Bool(true),
        "FALSE" => Cell::Bool(false),
        t => t.parse::<f64>().map_or_else(|_| Cell::Text(t.to_string()), Cell::Number),
    }
}

/// The rows: the failing condition expected and actual, then every interface variable.
fn rows(failure: &Failure) -> Vec<Row> {
    let w = &failure.window;
    let mut rows = Vec::new();
    if let Some(condition) = &failure.condition {
        let opt = |v: Option<bool>| v.map_or(Cell::Any, Cell::Bool);
        rows.push(Row {
            label: tf(K::exercise_row_expected, &[("condition", condition)]),
            class: "row-expected",
            values: w.iter().map(|s| opt(s.expected)).collect(),
        });
        rows.push(Row {
            label: tf(K::exercise_row_actual, &[("condition", condition)]),
            class: "row-actual",
            values: w.iter().map(|s| opt(s.actual)).collect(),
        });
    }
    let names: Vec<String> =
        w.first().map(|s| s.values.iter().map(|(n, _)| n.clone()).collect()).unwrap_or_default();
    for (k, name) in names.into_iter().enumerate() {
        let values = w
            .iter()
            .map(|s: &Sample| s.values.get(k).map_or(Cell::Any, |(_, v)| cell_of(v)))
            .collect();
        rows.push(Row { label: name, class: "row-var", values });
    }
    rows
}

/// An SVG path drawing a BOOL row as a step line (cells of width `dx` from `x0`).
fn bool_path(values: &[Cell], x0: f64, dx: f64, hi: f64, lo: f64) -> String {
    let mut d = String::new();
    let mut prev: Option<bool> = None;
    for (i, c) in values.iter().enumerate() {
        let x = x0 + i as f64 * dx;
        match c {
            Cell::Bool(v) => {
                let y = if *v { hi } else { lo };
                match prev {
                    None => d.push_str(&format!("M{x:.1} {y:.1}")),
                    Some(p) if p != *v => d.push_str(&format!("V{y:.1}")),
                    Some(_) => {}
                }
                d.push_str(&format!("H{:.1}", x + dx));
                prev = Some(*v);
            }
            _ => prev = None,
        }
    }
    d
}

/// The timeline of a failure's window, with the cursor on the first wrong scan.
#[component]
fn FailureTimeline(scenario: String, failure: Failure) -> impl IntoView {
    let w = failure.window.clone();
    if w.is_empty() {
        return None;
    }
    let rows = rows(&failure);
    let n = w.len();
    let dx = PLOT_W / n as f64;
    let height = TOP + rows.len() as f64 * ROW_H + 20.0;
    let at = w.iter().position(|s| s.scan == failure.scan).unwrap_or(n.saturating_sub(1));
    let cursor_x = LABEL_W + (at as f64 + 0.5) * dx;
    let cursor_text = tf(
        K::exercise_cursor,
        &[("time", &time_text(failure.time_ns)), ("scan", &failure.scan.to_string())],
    );
    let (first, last) = (&w[0], &w[n - 1]);
    let summary = tf(
        K::exercise_timeline_summary,
        &[
            ("scenario", &scenario),
            ("from", &time_text(first.time_ns)),
            ("to", &time_text(last.time_ns)),
            ("actual", &failure.actual),
            ("cursor", &cursor_text),
        ],
    );
    let drawn = rows.iter().enumerate().map(|(r, row)| {
        let top = TOP + r as f64 * ROW_H;
        let (hi, lo) = (top + 5.0, top + ROW_H - 5.0);
        let label = view! { <text class="tl-label" x="4" y=format!("{:.1}", top + ROW_H / 2.0 + 4.0)>{row.label.clone()}</text> };
        let any = row.values.iter().enumerate().filter(|(_, c)| **c == Cell::Any).map(|(i, _)| view! {
            <rect class="tl-any" x=format!("{:.1}", LABEL_W + i as f64 * dx) y=format!("{hi:.1}") width=format!("{dx:.2}") height=format!("{:.1}", lo - hi)/>
        }).collect_view();
        let line = if row.values.iter().any(|c| matches!(c, Cell::Bool(_))) {
            let d = bool_path(&row.values, LABEL_W, dx, hi, lo);
            view! { <path class=format!("tl-trace {}", row.class) d=d/> }.into_any()
        } else if row.values.iter().any(|c| matches!(c, Cell::Number(_))) {
            let nums: Vec<f64> = row.values.iter().filter_map(|c| if let Cell::Number(v) = c { Some(*v) } else { None }).collect();
            let (min, max) = nums.iter().fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
            let span = if max > min { max - min } else { 1.0 };
            let points = row.values.iter().enumerate().filter_map(|(i, c)| match c {
                Cell::Number(v) => Some(format!("{:.1},{:.1}", LABEL_W + (i as f64 + 0.5) * dx, lo - (v - min) / span * (lo - hi))),
                _ => None,
            }).collect::<Vec<_>>().join(" ");
            let range = format!("{} … {}", trim(min), trim(max));
            view! {
                <polyline class=format!("tl-trace tl-number {}", row.class) points=points/>
                <text class="tl-range" x=format!("{:.1}", LABEL_W + PLOT_W + 4.0) y=format!("{:.1}", top + ROW_H / 2.0 + 4.0)>{range}</text>
            }.into_any()
        } else {
            let text = row.values.get(at).map(|c| if let Cell::Text(t) = c { t.clone() } else { String::new() }).unwrap_or_default();
            view! { <text class="tl-value" x=format!("{:.1}", cursor_x + 4.0) y=format!("{:.1}", top + ROW_H / 2.0 + 4.0)>{text}</text> }.into_any()
        };
        // Where the condition was not what it should have been.
        let wrong = if row.class == "row-actual" {
            let expected = rows.first().map(|e| e.values.clone()).unwrap_or_default();
            row.values.iter().enumerate().filter(|(i, c)| {
                matches!((expected.get(*i), c), (Some(Cell::Bool(e)), Cell::Bool(a)) if e != a)
            }).map(|(i, _)| view! {
                <rect class="tl-wrong" x=format!("{:.1}", LABEL_W + i as f64 * dx) y=format!("{:.1}", top + 2.0) width=format!("{dx:.2}") height=format!("{:.1}", ROW_H - 4.0)/>
            }).collect_view().into_any()
        } else {
            ().into_any()
        };
        view! { <g class="tl-row">{label}{any}{wrong}{line}</g> }
    }).collect_view();
    let axis_y = TOP + rows.len() as f64 * ROW_H + 14.0;
    Some(view! {
        <figure class="report-timeline">
            <svg role="img" aria-label=summary.clone() viewBox=format!("0 0 {} {height:.0}", LABEL_W + PLOT_W + 70.0)
                data-cursor-scan=failure.scan.to_string() data-cursor-time=time_text(failure.time_ns)>
                {drawn}
                <line class="tl-cursor" x1=format!("{cursor_x:.1}") x2=format!("{cursor_x:.1}") y1="12" y2=format!("{:.1}", axis_y - 10.0)/>
                <text class="tl-cursor-label" x=format!("{:.1}", (cursor_x + 4.0).min(LABEL_W + PLOT_W - 60.0)) y="11">{cursor_text.clone()}</text>
                <text class="tl-axis" x=format!("{LABEL_W:.0}") y=format!("{axis_y:.1}")>{time_text(first.time_ns)}</text>
                <text class="tl-axis tl-axis-end" x=format!("{:.0}", LABEL_W + PLOT_W) y=format!("{axis_y:.1}")>{time_text(last.time_ns)}</text>
            </svg>
            <figcaption>{tf(K::exercise_timeline_caption, &[("cursor", &cursor_text)])}</figcaption>

        </figure>
    })
}

/// A number without a useless fraction.
fn trim(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e15 {
        format!("{}", v as i64)
    } else {
        format!("{v:.3}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bool_row_is_one_step_line_broken_where_any_value_is_right() {
        let v =
            [Cell::Bool(false), Cell::Bool(true), Cell::Bool(true), Cell::Any, Cell::Bool(false)];
        assert_eq!(
            bool_path(&v, 0.0, 10.0, 0.0, 20.0),
            "M0.0 20.0H10.0V0.0H20.0H30.0M40.0 20.0H50.0"
        );
    }

    #[test]
    fn values_read_as_bools_numbers_or_text() {
        assert!(cell_of("TRUE") == Cell::Bool(true));
        assert!(cell_of("42") == Cell::Number(42.0));
        assert!(cell_of("T#1s") == Cell::Text("T#1s".into()));
        assert_eq!(trim(3.0), "3");
    }
}
