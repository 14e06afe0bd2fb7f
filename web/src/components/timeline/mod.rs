//! The timeline: chosen variables charted against virtual time (BOOL as digital lanes,
//! numbers as analog lanes) as plain SVG, with zoom, pan, follow mode, a read-out cursor
//! and CSV / VCD / SVG export.

mod chart;

use crate::download::download;

use leptos::prelude::*;
use plc_core::export::value_text;
use plc_core::semantic::Type;
use wasm_bindgen::JsCast;

use crate::i18n::{t, tf, K};
use crate::state::AppState;
use chart::{build, t_of, value_at, Chart, AXIS_H, LEFT, WIDTH};

/// Lane colours (also used in the exported SVG, so not in CSS; the page's dark theme
/// brightens them through the `tl-series` class).
const COLORS: [&str; 8] =
    ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2"];

/// The smallest and largest visible window (1 ms … 1 day).
const MIN_SPAN: i64 = 1_000_000;
const MAX_SPAN: i64 = 86_400_000_000_000;

/// The view's window over virtual time.
#[derive(Clone, Copy)]
struct View {
    follow: RwSignal<bool>,
    span: RwSignal<i64>,
    end: RwSignal<i64>,
    cursor: RwSignal<Option<i64>>,
}

impl View {
    fn window(&self, now: i64) -> (i64, i64) {
        let span = self.span.get();
        let end = if self.follow.get() { now.max(span) } else { self.end.get() };
        (end - span, end)
    }

    /// Zooms by `factor` (> 1 zooms out) keeping time `at` in place.
    fn zoom(&self, factor: f64, at: Option<i64>, now: i64) {
        let (start, end) = self.window(now);
        let old = (end - start).max(1);
        let new = ((old as f64 * factor) as i64).clamp(MIN_SPAN, MAX_SPAN);
        self.span.set(new);
        if !self.follow.get_untracked() {
            let at = at.unwrap_or(start + old / 2);
            let frac = (at - start) as f64 / old as f64;
            self.end.set(at + ((1.0 - frac) * new as f64) as i64);
        }
    }

    /// Pans by `dt` nanoseconds (leaves follow mode).
    fn pan(&self, dt: i64, now: i64) {
        let (_, end) = self.window(now);
        self.follow.set(false);
        self.end.set(end.saturating_add(dt));
    }
}

/// The variables one can chart: the main program's BOOL and numeric variables (each
/// program instance's, when a configuration runs).
fn candidates(state: AppState) -> Vec<String> {
    state
        .with_sim(|s| {
            s.listed_vars()
                .into_iter()
                .filter(|(name, _)| !plc_core::build::is_hidden_variable(name))
                .filter(|(_, var)| match var.ty {
                    Type::Elem(el) => {
                        el.is_integral()
                            || el.is_real()
                            || el == plc_core::semantic::Elem::Bool
                            || el == plc_core::semantic::Elem::Time
                    }
                    Type::Enum(_) => true,
                    _ => false,
                })
                .map(|(name, _)| name)
                .collect()
        })
        .unwrap_or_default()
}

/// SVG x of a pointer event over the chart.
fn pointer_x(ev: &web_sys::PointerEvent) -> Option<f64> {
    let el = ev.current_target()?.dyn_into::<web_sys::Element>().ok()?;
    let rect = el.get_bounding_client_rect();
    if rect.width() <= 0.0 {
        return None;
    }
    Some((f64::from(ev.client_x()) - rect.left()) / rect.width() * WIDTH)
}

/// The timeline panel.
#[component]
pub fn Timeline() -> impl IntoView {
    let state = expect_context::<AppState>();
    let view = View {
        follow: RwSignal::new(true),
        span: RwSignal::new(5_000_000_000),
        end: RwSignal::new(5_000_000_000),
        cursor: RwSignal::new(None),
    };
    let traced = Memo::new(move |_| state.project.with(|p| p.settings.traced.clone()));
    let names = Memo::new(move |_| candidates(state));
    let now = move || state.with_sim(|s| s.time_ns()).unwrap_or(0);
    let chart = Memo::new(move |_| {
        let window = view.window(now());
        state.with_sim(|s| build(s.trace(), window)).unwrap_or_default()
    });
    let toggle = move |name: String, on: bool| {
        let mut list = traced.get_untracked();
        list.retain(|p| !p.eq_ignore_ascii_case(&name));
        if on {
            list.push(name);
        }
        state.set_traced(list);
    };
    let path_text = RwSignal::new(String::new());
    let add_path = move || {
        let p = path_text.get_untracked().trim().to_string();
        if p.is_empty() {
            return;
        }
        if state.with_sim(|s| s.executable().locate(&p).is_some()) != Some(true) {
            state.error(tf(K::sim_no_variable, &[("path", &p)]));
            return;
        }
        toggle(p, true);
        path_text.set(String::new());
    };
    let export = move |kind: &'static str| {
        leptos::task::spawn_local(async move {
            let text = match kind {
                "svg" => svg_text(),
                // The writers are a chunk of the app, fetched on the first export.
                _ => match crate::lazy::timeline_file(state, kind == "csv").await {
                    Ok(text) => text,
                    Err(e) => {
                        state.error(tf(K::sim_export_failed, &[("error", &e.to_string())]));
                        return;
                    }
                },
            };
            let Some(text) = text else {
                state.error(t(K::sim_nothing_to_export));
                return;
            };
            let (name, mime) = match kind {
                "csv" => ("timeline.csv", "text/csv"),
                "vcd" => ("timeline.vcd", "text/plain"),
                _ => ("timeline.svg", "image/svg+xml"),
            };
            if let Err(e) = download(name, mime, &text) {
                state.error(e);
            }
        });
    };

    view! {
        <section class="panel timeline" aria-label=t(K::sim_timeline)>
            <div class="panel-head">
                <h2>{t(K::sim_timeline)}</h2>
                <div class="control-row">
                    <button on:click=move |_| export("csv")>{t(K::sim_export_csv)}</button>
                    <button on:click=move |_| export("vcd")>{t(K::sim_export_vcd)}</button>
                    <button on:click=move |_| export("svg")>{t(K::sim_export_svg)}</button>
                </div>
            </div>
            <fieldset class="trace-pick">
                <legend>{t(K::sim_timeline_variables)}</legend>
                {move || names.get().into_iter().map(|n| {
                    let on = {
                        let n = n.clone();
                        move || traced.with(|t| t.iter().any(|p| p.eq_ignore_ascii_case(&n)))
                    };
                    let name = n.clone();
                    let label = tf(K::sim_chart, &[("name", &n)]);
                    view! {
                        <label class="chip">
                            <input type="checkbox" aria-label=label prop:checked=on
                                on:change=move |ev| toggle(name.clone(), event_target_checked(&ev))/>
                            {n}
                        </label>
                    }
                }).collect_view()}
                <span class="add-path">
                    <input class="mono" aria-label=t(K::sim_variable_path) placeholder=t(K::sim_variable_path_placeholder)
                        prop:value=move || path_text.get()
                        on:input=move |ev| path_text.set(event_target_value(&ev))
                        on:keydown=move |ev| if ev.key() == "Enter" { add_path() }/>
                    <button on:click=move |_| add_path()>{t(K::sim_add_to_timeline)}</button>
                </span>
                {move || traced.get().into_iter()
                    .filter(|p| !names.with(|n| n.iter().any(|x| x.eq_ignore_ascii_case(p))))
                    .map(|p| {
                        let q = p.clone();
                        view! {
                            <span class="chip">
                                <code>{p.clone()}</code>
                                <button class="small" aria-label=tf(K::sim_remove_from_timeline, &[("path", &p)])
                                    on:click=move |_| toggle(q.clone(), false)>"×"</button>
                            </span>
                        }
                    }).collect_view()}
            </fieldset>
            <div class="control-row">
                <button aria-label=t(K::sim_zoom_in) title=t(K::sim_zoom_in) on:click=move |_| view.zoom(0.5, None, now())>"+"</button>
                <button aria-label=t(K::sim_zoom_out) title=t(K::sim_zoom_out) on:click=move |_| view.zoom(2.0, None, now())>"−"</button>
                <button aria-label=t(K::sim_pan_left) title=t(K::sim_earlier) on:click=move |_| {
                    let s = view.span.get_untracked();
                    view.pan(-s / 4, now())
                }>"◀"</button>
                <button aria-label=t(K::sim_pan_right) title=t(K::sim_later) on:click=move |_| {
                    let s = view.span.get_untracked();
                    view.pan(s / 4, now())
                }>"▶"</button>
                <button aria-pressed=move || if view.follow.get() { "true" } else { "false" }
                    class:active=move || view.follow.get()
                    on:click=move |_| view.follow.update(|f| *f = !*f)>{t(K::sim_follow)}</button>
                <span class="muted">{move || {
                    let (a, b) = chart.with(|c| c.window);
                    format!("{} – {}", chart::time_label(a, 1_000_000), chart::time_label(b, 1_000_000))
                }}</span>
            </div>
            <ChartSvg chart=chart view=view/>
            <Legend chart=chart view=view/>
        </section>
    }
}

/// The exported SVG: the drawn chart's markup.
fn svg_text() -> Option<String> {
    let doc = web_sys::window()?.document()?;
    let el = doc.query_selector("svg.timeline-chart").ok()??;
    Some(format!("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n{}", el.outer_html()))
}

/// The chart itself.
#[component]
fn ChartSvg(chart: Memo<Chart>, view: View) -> impl IntoView {
    let state = expect_context::<AppState>();
    let now = move || state.with_sim(|s| s.time_ns()).unwrap_or(0);
    // While dragging: (start x, window end at start, window span).
    let drag = StoredValue::new(None::<(f64, i64, i64)>);
    // The drawn width in CSS px: the chart's units per px (`k`) keep its text 11 px and
    // the chart at least 120 px tall at any width (issue 34).
    let svg_ref = NodeRef::<leptos::svg::Svg>::new();
    let px = RwSignal::new(0.0_f64);
    Effect::new(move |_| {
        let Some(el) = svg_ref.get() else { return };
        let el: web_sys::Element = el.into();
        let measured = el.clone();
        // The new width is taken in the next frame, and only when it changed: the chart's
        // height follows it, and a size changed inside the observer's own notification
        // is an error in WebKit ("ResizeObserver loop completed with undelivered
        // notifications").
        let on_resize = wasm_bindgen::closure::Closure::<dyn Fn()>::new(move || {
            let measured = measured.clone();
            request_animation_frame(move || {
                let width = measured.get_bounding_client_rect().width();
                if px.try_get_untracked().is_some_and(|old| (old - width).abs() > 0.5) {
                    px.set(width);
                }
            });
        });
        if let Ok(observer) = web_sys::ResizeObserver::new(on_resize.as_ref().unchecked_ref()) {
            observer.observe(&el);
        }
        on_resize.forget();
    });
    let k = move || {
        let w = px.get();
        if w > 0.0 {
            WIDTH / w
        } else {
            1.0
        }
    };
    // The lanes' bottom, the axis below them and the whole height, in the chart's units.
    let axis_y = move || {
        let k = k();
        chart.with(|c| (c.height - AXIS_H).max(120.0 * k - AXIS_H * k))
    };
    let height = move || axis_y() + AXIS_H * k();
    let on_move = move |ev: web_sys::PointerEvent| {
        let Some(x) = pointer_x(&ev) else { return };
        let window = chart.with_untracked(|c| c.window);
        if let Some((x0, end0, span)) = drag.get_value().filter(|d| (d.0 - x).abs() > 2.0) {
            let dt = ((x0 - x) / (WIDTH - LEFT) * span as f64) as i64;
            view.follow.set(false);
            view.end.set(end0.saturating_add(dt));
        }
        view.cursor.set((x >= LEFT).then(|| t_of(x, window)));
    };
    let on_down = move |ev: web_sys::PointerEvent| {
        let Some(x) = pointer_x(&ev) else { return };
        let (a, b) = chart.with_untracked(|c| c.window);
        drag.set_value(Some((x, b, b - a)));
        if let Some(el) = ev.current_target().and_then(|t| t.dyn_into::<web_sys::Element>().ok()) {
            let _ = el.set_pointer_capture(ev.pointer_id());
        }
    };
    let on_wheel = move |ev: web_sys::WheelEvent| {
        ev.prevent_default();
        let factor = if ev.delta_y() > 0.0 { 1.25 } else { 0.8 };
        view.zoom(factor, view.cursor.get_untracked(), now());
    };
    view! {
        <svg class="timeline-chart" role="img" aria-label=t(K::sim_timeline_chart) node_ref=svg_ref
            xmlns="http://www.w3.org/2000/svg"
            viewBox=move || format!("0 0 {WIDTH} {}", height())
            width="100%"
            font-family="sans-serif" font-size=move || format!("{:.2}", 11.0 * k())
            on:pointermove=on_move
            on:pointerdown=on_down
            on:pointerup=move |_| drag.set_value(None)
            on:pointercancel=move |_| drag.set_value(None)
            on:pointerleave=move |_| { drag.set_value(None); view.cursor.set(None); }
            on:wheel=on_wheel>
            <rect class="tl-bg" x="0" y="0" width=WIDTH height=height fill="#ffffff"/>
            {move || chart.with(|c| c.ticks.iter().map(|(x, label)| {
                let h = axis_y();
                view! {
                    <line class="tl-grid" x1=*x x2=*x y1="0" y2=h stroke="#e3e8ee" stroke-width="1"/>
                    <text class="tl-tick" x=*x y=h + 15.0 * k() text-anchor="middle" fill="#5b6b7c">{label.clone()}</text>
                }
            }).collect_view())}
            {move || chart.with(|c| c.lanes.iter().enumerate().map(|(i, lane)| {
                let color = COLORS[i % COLORS.len()];
                // A lane's own labels fit its height.
                let lane_font = format!("{:.2}", (11.0 * k()).min(lane.height * 0.6));
                view! {
                    <g>
                        <rect class="tl-lane-bg" x=LEFT y=lane.top width=WIDTH - LEFT height=lane.height fill="#f7f9fb"/>
                        <text class="tl-series" x="4" y=lane.top + 14.0 fill=color font-weight="bold" font-size=lane_font.clone()>{lane.path.clone()}</text>
                        {(!lane.digital).then(|| view! {
                            <text class="tl-tick" x="4" y=lane.top + 28.0 fill="#5b6b7c" font-size=lane_font.clone()>{tf(K::sim_lane_max, &[("value", &short(lane.range.1))])}</text>
                            <text class="tl-tick" x="4" y=lane.top + lane.height - 4.0 fill="#5b6b7c" font-size=lane_font.clone()>{tf(K::sim_lane_min, &[("value", &short(lane.range.0))])}</text>
                        })}
                        <polyline class="tl-series" points=lane.points.clone() fill="none" stroke=color stroke-width="1.5"/>
                    </g>
                }
            }).collect_view())}
            <line class="tl-axis-line" x1=LEFT x2=WIDTH y1=axis_y y2=axis_y stroke="#5b6b7c"/>
            // The recorded scan the page shows (issue 36).
            {move || state.with_shown_view(|v| v.time_ns()).map(|t| {
                let x = chart::x_of(t, chart.with(|c| c.window));
                view! { <line class="scan-cursor" x1=x x2=x y1="0" y2=axis_y() stroke="#b45309" stroke-width="2"/> }
            })}
            {move || view.cursor.get().map(|t| {
                let x = chart::x_of(t, chart.with(|c| c.window));
                view! { <line class="cursor" x1=x x2=x y1="0" y2=axis_y() stroke="#333" stroke-dasharray="3 3"/> }
            })}
        </svg>
    }
}

fn short(x: f64) -> String {
    if x.fract() == 0.0 && x.abs() < 1e15 {
        format!("{x}")
    } else {
        format!("{x:.3}")
    }
}

/// The legend: every lane's value at the cursor (or the latest value).
#[component]
fn Legend(chart: Memo<Chart>, view: View) -> impl IntoView {
    let state = expect_context::<AppState>();
    let rows = move || {
        let at = view.cursor.get().or_else(|| state.with_shown_view(|v| v.time_ns()));
        let t = at.unwrap_or(i64::MAX);
        state
            .with_sim(|s| {
                s.trace()
                    .paths()
                    .enumerate()
                    .map(|(i, p)| {
                        let v = value_at(s.trace(), i, t)
                            .map(|v| value_text(&v))
                            .unwrap_or_else(|| "–".into());
                        (p.to_string(), v)
                    })
                    .collect::<Vec<_>>()
            })
            .unwrap_or_default()
    };
    let _ = chart;
    view! {
        <div class="legend" aria-live="off">
            <span class="legend-time">{move || match view.cursor.get().or_else(|| state.with_shown_view(|v| v.time_ns())) {
                Some(at) => tf(K::sim_at_time, &[("time", &chart::time_label(at, 1))]),
                None => t(K::sim_latest).to_string(),
            }}</span>
            {move || rows().into_iter().enumerate().map(|(i, (p, v))| view! {
                <span class="legend-item">
                    <span class="swatch tl-series" style=format!("background: {}", COLORS[i % COLORS.len()])></span>
                    <span>{p}</span>
                    ": "
                    <output class="mono">{v}</output>
                </span>
            }).collect_view()}
        </div>
    }
}
