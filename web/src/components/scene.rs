//! The plant's scene (`docs/plants.md`, "Scenes"): the project's widgets drawn on an SVG
//! canvas from the values of each scan — tanks filled to their level, valves and motors
//! green while on, lamps lit, a scale's readout — and its buttons and switches, which
//! write the controller's inputs as the I/O panel does. Every widget has an accessible
//! name with its state (`Tank T1: 43 %`, `Start button`).

use leptos::prelude::*;
use plc_core::export::value_text;
use plc_core::project::{Widget, WidgetKind};
use plc_core::vm::Value;

use crate::state::AppState;

/// A value as a number (BOOL as 0 or 1).
fn number(v: &Value) -> Option<f64> {
    match v {
        Value::Bool(b) => Some(f64::from(u8::from(*b))),
        Value::Int(i, _) => Some(*i as f64),
        Value::Real(r, _) => Some(*r),
        _ => None,
    }
}

/// The value of `path` in the running simulator.
fn read(state: AppState, path: &str) -> Option<Value> {
    state.with_sim(|s| s.read(path).ok()).flatten()
}

/// A readout: the value divided by the widget's `scale`, with its unit.
fn readout(w: &Widget, v: Option<&Value>) -> String {
    let Some(v) = v else { return "–".to_string() };
    let unit = w.unit.as_deref().map(|u| format!(" {u}")).unwrap_or_default();
    match (w.scale, number(v)) {
        (Some(k), Some(x)) if k != 0.0 => format!("{}{unit}", (x / k * 10.0).round() / 10.0),
        _ => format!("{}{unit}", value_text(v)),
    }
}

/// An attribute or text value, escaped.
fn esc(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    crate::components::editor::text::escape(&mut out, text);
    out
}

/// The SVG markup of one widget that only shows its variable (written as text: one
/// formatter for every kind keeps the page's code small; every name is escaped).
fn shown(w: &Widget, v: Option<Value>) -> String {
    let (x, y, wd, h) = (w.x, w.y, w.width, w.height);
    let on = matches!(v, Some(Value::Bool(true)));
    let label = esc(&w.label);
    let (cx, cy) = (x + wd / 2.0, y + h / 2.0);
    let caption = format!(r#"<text class="sc-label" x="{cx}" y="{}">{label}</text>"#, y - 6.0);
    let lit = if on { " on" } else { "" };
    let (name, class, body) = match w.kind {
        WidgetKind::Tank => {
            let max = w.max.unwrap_or(100.0).max(f64::MIN_POSITIVE);
            let share = v.as_ref().and_then(number).map(|x| (x / max).clamp(0.0, 1.0));
            let pct = share.map(|s| (s * 100.0).round() as i64);
            let fill = share.unwrap_or(0.0) * h;
            let text = pct.map(|p| format!("{p} %")).unwrap_or_default();
            (
                pct.map_or(format!("{label}: no value"), |p| format!("{label}: {p} %")),
                "",
                format!(
                    r#"<rect class="sc-liquid" x="{x}" y="{}" width="{wd}" height="{fill}"/><rect class="sc-vessel" x="{x}" y="{y}" width="{wd}" height="{h}" rx="4"/><text class="sc-value" x="{cx}" y="{cy}">{text}</text>"#,
                    y + h - fill
                ),
            )
        }
        WidgetKind::Valve => (
            format!("{label}: {}", if on { "open" } else { "closed" }),
            "sc-valve",
            format!(
                r#"<path d="M{x} {y} L{cx} {cy} L{x} {} Z M{} {y} L{cx} {cy} L{} {} Z"/>"#,
                y + h,
                x + wd,
                x + wd,
                y + h
            ),
        ),
        WidgetKind::Motor | WidgetKind::Lamp => {
            let motor = w.kind == WidgetKind::Motor;
            let word = match (motor, on) {
                (true, true) => "running",
                (true, false) => "stopped",
                (false, true) => "on",
                (false, false) => "off",
            };
            let mark = if motor {
                format!(r#"<text class="sc-mark" x="{cx}" y="{}">M</text>"#, cy + 5.0)
            } else {
                String::new()
            };
            (
                format!("{label}: {word}"),
                if motor { "sc-motor" } else { "sc-lamp" },
                format!(r#"<circle cx="{cx}" cy="{cy}" r="{}"/>{mark}"#, wd.min(h) / 2.0),
            )
        }
        _ => {
            let text = esc(&readout(w, v.as_ref()));
            let scale = w.kind == WidgetKind::Scale;
            let dh = if scale { h - 14.0 } else { h };
            let platform = if scale {
                format!(
                    r#"<rect class="sc-platform" x="{x}" y="{}" width="{wd}" height="8"/>"#,
                    y + h - 8.0
                )
            } else {
                String::new()
            };
            (
                format!("{label}: {text}"),
                "",
                format!(
                    r#"{platform}<rect class="sc-display" x="{x}" y="{y}" width="{wd}" height="{dh}" rx="3"/><text class="sc-digits" x="{cx}" y="{}">{text}</text>"#,
                    y + dh / 2.0 + 5.0
                ),
            )
        }
    };
    format!(
        r#"<g class="sc-widget {class}{lit}" role="img" aria-label="{name}">{body}{caption}</g>"#
    )
}

/// A push button (momentary) or a selector switch writing its BOOL input. A press is held
/// at least until a scan has seen it, so a click while the PLC is paused reaches the next
/// step.
#[component]
fn Control(widget: Widget) -> impl IntoView {
    let state = expect_context::<AppState>();
    let var = StoredValue::new(widget.var.clone());
    let on =
        Memo::new(move |_| var.with_value(|v| matches!(read(state, v), Some(Value::Bool(true)))));
    let set = move |value: bool| {
        var.with_value(|v| state.hold_input(v, if value { "TRUE" } else { "FALSE" }));
    };
    let scans = move || state.with_sim(|s| s.scan_count()).unwrap_or(0);
    // A release waiting for a scan after the press: the scan count at the press.
    let pending = RwSignal::new(None::<u64>);
    let pressed_at = StoredValue::new(0u64);
    Effect::new(move |_| {
        if let Some(at) = pending.get() {
            if scans() > at {
                pending.set(None);
                set(false);
            }
        }
    });
    let press = move || {
        pressed_at.set_value(scans());
        pending.set(None);
        set(true);
    };
    let release = move || {
        if !on.get_untracked() {
            return;
        }
        if scans() > pressed_at.get_value() {
            set(false);
        } else {
            pending.set(Some(pressed_at.get_value()));
        }
    };
    let (x, y, w, h) = (widget.x, widget.y, widget.width, widget.height);
    let label = widget.label.clone();
    if widget.kind == WidgetKind::Switch {
        let name = label.clone();
        return view! {
            <g class="sc-widget sc-switch" class:on=move || on.get() role="switch" tabindex="0"
                aria-label=format!("{name} switch") aria-checked=move || if on.get() { "true" } else { "false" }
                on:click=move |_| set(!on.get_untracked())
                on:keydown=move |ev| if ev.key() == " " || ev.key() == "Enter" {
                    ev.prevent_default();
                    set(!on.get_untracked());
                }>
                <rect x=x y=y width=w height=h rx=h / 2.0/>
                <circle cx=move || if on.get() { x + w - h / 2.0 } else { x + h / 2.0 } cy=y + h / 2.0 r=h / 2.0 - 3.0/>
                <text class="sc-label" x=x + w / 2.0 y=y - 6.0>{label}</text>
            </g>
        }
        .into_any();
    }
    view! {
        <g class="sc-widget sc-button" class:on=move || on.get() role="button" tabindex="0"
            aria-label=format!("{label} button") aria-pressed=move || if on.get() { "true" } else { "false" }
            on:pointerdown=move |_| press()
            on:pointerup=move |_| release()
            on:pointerleave=move |_| release()
            on:pointercancel=move |_| release()
            on:keydown=move |ev| if (ev.key() == " " || ev.key() == "Enter") && !ev.repeat() {
                ev.prevent_default();
                press();
            }
            on:keyup=move |ev| if ev.key() == " " || ev.key() == "Enter" {
                ev.prevent_default();
                release();
            }>
            <rect x=x y=y width=w height=h rx="6"/>
            <text class="sc-button-text" x=x + w / 2.0 y=y + h / 2.0 + 5.0>{label.clone()}</text>
        </g>
    }
    .into_any()
}

/// The scene of the project's plant, when it has one.
#[component]
pub fn ScenePanel() -> impl IntoView {
    let state = expect_context::<AppState>();
    let scene = Memo::new(move |_| state.project.with(|p| p.scene.clone()));
    move || {
        scene.get().map(|scene| {
            let (controls, shown_widgets): (Vec<Widget>, Vec<Widget>) =
                scene.widgets.iter().cloned().partition(|w| w.kind.writes());
            let drawn = move || {
                shown_widgets.iter().map(|w| shown(w, read(state, &w.var))).collect::<String>()
            };
            view! {
                <section class="panel scene-panel" aria-label="Plant">
                    <h2>"Plant"</h2>
                    <svg class="sc-svg" viewBox=format!("0 0 {} {}", scene.width, scene.height)
                        role="group" aria-label="Plant scene">
                        <g inner_html=drawn></g>
                        {controls.into_iter().map(|w| view! { <Control widget=w/> }).collect_view()}
                    </svg>
                </section>
            }
        })
    }
}
