//! The plant's scene (`docs/plants.md`, "Scenes"): the project's widgets drawn on an SVG
//! canvas from the values of each scan — tanks filled to their level, valves and motors
//! green while on, lamps lit, a scale's readout — and its buttons and switches, which
//! write the controller's inputs as the I/O panel does. Every widget has an accessible
//! name with its state (`Tank T1: 43 %`, `Start button`).

use leptos::prelude::*;
use plc_core::export::value_text;
use plc_core::project::{Widget, WidgetKind};
use plc_core::vm::Value;

use crate::i18n::{t, tf, K};
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

/// The value of `path` at the scan the page shows.
fn read(state: AppState, path: &str) -> Option<Value> {
    state.read(path)
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

/// Whether the BOOL at `path` (when the widget names one) is TRUE.
fn lit(state: AppState, path: Option<&String>) -> bool {
    path.is_some_and(|p| matches!(read(state, p), Some(Value::Bool(true))))
}

/// The SVG markup of one widget that only shows its variables (written as text: one
/// formatter for every kind keeps the page's code small; every name is escaped).
fn shown(state: AppState, w: &Widget) -> String {
    let v = read(state, &w.var);
    let (x, y, wd, h) = (w.x, w.y, w.width, w.height);
    let on = matches!(v, Some(Value::Bool(true)));
    let label = esc(&w.label);
    let (cx, cy) = (x + wd / 2.0, y + h / 2.0);
    // A conveyor's items ride above the belt: its caption goes under it.
    let caption_y = if w.kind == WidgetKind::Conveyor { y + 28.0 } else { y - 6.0 };
    let caption = format!(r#"<text class="sc-label" x="{cx}" y="{caption_y}">{label}</text>"#);
    let mut lit_class = if on { " on" } else { "" };
    let max = w.max.unwrap_or(100.0).max(f64::MIN_POSITIVE);
    let share = v.as_ref().and_then(number).map(|x| (x / max).clamp(0.0, 1.0));
    let words = |yes: K, no: K| tf(if on { yes } else { no }, &[("label", &label)]);
    let (name, class, body) = match w.kind {
        WidgetKind::Tank => {
            let pct = share.map(|s| (s * 100.0).round() as i64);
            let fill = share.unwrap_or(0.0) * h;
            let text = pct.map(|p| format!("{p} %")).unwrap_or_default();
            let overflow = lit(state, w.alarm.as_ref());
            let spill = if overflow {
                lit_class = " alarm";
                format!(
                    r#"<path class="sc-spill" d="M{} {y} q10 0 12 {} l-4 0 q-2 -{} -8 -{} Z"/>"#,
                    x + wd,
                    h,
                    h - 6.0,
                    h - 6.0
                )
            } else {
                String::new()
            };
            (
                if overflow {
                    tf(K::sim_scene_overflow, &[("label", &label)])
                } else {
                    pct.map_or_else(
                        || tf(K::sim_scene_no_value, &[("label", &label)]),
                        |p| format!("{label}: {p} %"),
                    )
                },
                "",
                format!(
                    r#"<rect class="sc-liquid" x="{x}" y="{}" width="{wd}" height="{fill}"/><rect class="sc-vessel" x="{x}" y="{y}" width="{wd}" height="{h}" rx="4"/>{spill}<text class="sc-value" x="{cx}" y="{cy}">{text}</text>"#,
                    y + h - fill
                ),
            )
        }
        WidgetKind::Valve => (
            words(K::sim_scene_valve_open, K::sim_scene_valve_closed),
            "sc-valve",
            format!(
                r#"<path d="M{x} {y} L{cx} {cy} L{x} {} Z M{} {y} L{cx} {cy} L{} {} Z"/>"#,
                y + h,
                x + wd,
                x + wd,
                y + h
            ),
        ),
        WidgetKind::Motor | WidgetKind::Pump => {
            let r = wd.min(h) / 2.0;
            let mark = if w.kind == WidgetKind::Motor {
                format!(r#"<text class="sc-mark" x="{cx}" y="{}">M</text>"#, cy + 5.0)
            } else {
                format!(
                    r#"<path class="sc-mark-shape" d="M{} {} L{} {cy} L{} {} Z"/>"#,
                    cx - r * 0.5,
                    cy - r * 0.6,
                    cx + r * 0.6,
                    cx - r * 0.5,
                    cy + r * 0.6
                )
            };
            (
                words(K::sim_scene_running, K::sim_scene_stopped),
                "sc-motor",
                format!(r#"<circle cx="{cx}" cy="{cy}" r="{r}"/>{mark}"#),
            )
        }
        WidgetKind::Lamp => (
            words(K::sim_scene_lamp_on, K::sim_scene_lamp_off),
            "sc-lamp",
            format!(r#"<circle cx="{cx}" cy="{cy}" r="{}"/>"#, wd.min(h) / 2.0),
        ),
        WidgetKind::Conveyor => {
            let item = w.at.as_ref().and_then(|p| read(state, p)).as_ref().and_then(number);
            let item = item.filter(|p| *p >= 0.0).map(|p| (p / max).clamp(0.0, 1.0));
            let size = (h - 10.0).max(6.0);
            let (box_svg, at) = match item {
                Some(s) => (
                    format!(
                        r#"<rect class="sc-item" x="{}" y="{}" width="{size}" height="{size}"/>"#,
                        x + s * (wd - size),
                        y - size + 2.0
                    ),
                    tf(
                        K::sim_scene_item_at,
                        &[("percent", &((s * 100.0).round() as i64).to_string())],
                    ),
                ),
                None => (String::new(), String::new()),
            };
            let r = 5.0;
            (
                format!("{}{at}", words(K::sim_scene_running, K::sim_scene_stopped)),
                "sc-conveyor",
                format!(
                    r#"{box_svg}<rect class="sc-belt" x="{x}" y="{}" width="{wd}" height="{}" rx="{r}"/><line class="sc-belt-run" x1="{}" y1="{}" x2="{}" y2="{}"/><circle class="sc-roller" cx="{}" cy="{}" r="{}"/><circle class="sc-roller" cx="{}" cy="{}" r="{}"/>"#,
                    y + 2.0,
                    2.0 * r,
                    x + r,
                    y + 2.0,
                    x + wd - r,
                    y + 2.0,
                    x + r,
                    y + 2.0 + r,
                    r - 1.5,
                    x + wd - r,
                    y + 2.0 + r,
                    r - 1.5
                ),
            )
        }
        WidgetKind::PhotoEye => (
            words(K::sim_scene_eye_blocked, K::sim_scene_eye_clear),
            "sc-eye",
            format!(
                r#"<rect x="{x}" y="{y}" width="10" height="{h}"/><line class="sc-beam" x1="{}" y1="{cy}" x2="{}" y2="{cy}"/><rect x="{}" y="{y}" width="10" height="{h}"/>"#,
                x + 10.0,
                x + wd - 10.0,
                x + wd - 10.0
            ),
        ),
        WidgetKind::LimitSwitch => (
            words(K::sim_scene_limit_pressed, K::sim_scene_limit_released),
            "sc-limit",
            format!(
                r#"<rect x="{x}" y="{}" width="{wd}" height="{}" rx="2"/><line class="sc-lever" x1="{cx}" y1="{}" x2="{}" y2="{y}"/><circle cx="{}" cy="{y}" r="3"/>"#,
                cy,
                h / 2.0,
                cy,
                if on { cx } else { x + wd },
                if on { cx } else { x + wd }
            ),
        ),
        WidgetKind::TrafficLight => {
            let lamps = [
                ("red", K::sim_scene_red, Some(&w.var)),
                ("yellow", K::sim_scene_yellow, w.yellow.as_ref()),
                ("green", K::sim_scene_green, w.green.as_ref()),
            ];
            let lamps: Vec<(&str, K, bool)> = lamps
                .into_iter()
                .filter_map(|(colour, word, var)| var.map(|v| (colour, word, lit(state, Some(v)))))
                .collect();
            let step = h / lamps.len().max(1) as f64;
            let r = (wd.min(step) / 2.0 - 3.0).max(2.0);
            let circles: String = lamps
                .iter()
                .enumerate()
                .map(|(i, (colour, _, on))| {
                    format!(
                        r#"<circle class="sc-tl-{colour}{}" cx="{cx}" cy="{}" r="{r}"/>"#,
                        if *on { " on" } else { "" },
                        y + step * (i as f64 + 0.5)
                    )
                })
                .collect();
            let showing =
                lamps.iter().filter(|l| l.2).map(|l| t(l.1).to_string()).reduce(|first, next| {
                    tf(K::sim_scene_and, &[("first", &first), ("next", &next)])
                });
            lit_class = "";
            (
                match showing {
                    Some(lights) => format!("{label}: {lights}"),
                    None => tf(K::sim_scene_dark, &[("label", &label)]),
                },
                "sc-traffic",
                format!(
                    r#"<rect class="sc-housing" x="{x}" y="{y}" width="{wd}" height="{h}" rx="6"/>{circles}"#
                ),
            )
        }
        WidgetKind::Gauge => {
            let text = esc(&readout(w, v.as_ref()));
            let r = (wd / 2.0).min(h - 12.0).max(4.0);
            let base = y + r + 2.0;
            let angle = std::f64::consts::PI * (1.0 - share.unwrap_or(0.0));
            let (nx, ny) = (cx + r * 0.85 * angle.cos(), base - r * 0.85 * angle.sin());
            (
                format!("{label}: {text}"),
                "sc-gauge",
                format!(
                    r#"<path class="sc-dial" d="M{} {base} A{r} {r} 0 0 1 {} {base}"/><line class="sc-needle" x1="{cx}" y1="{base}" x2="{nx:.1}" y2="{ny:.1}"/><text class="sc-value" x="{cx}" y="{}">{text}</text>"#,
                    cx - r,
                    cx + r,
                    base + 12.0
                ),
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
        r#"<g class="sc-widget {class}{lit_class}" role="img" aria-label="{name}">{body}{caption}</g>"#
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
    if widget.kind != WidgetKind::Button {
        let fault = widget.kind == WidgetKind::Fault;
        let name =
            tf(if fault { K::sim_scene_fault } else { K::sim_scene_switch }, &[("label", &label)]);
        return view! {
            <g class="sc-widget sc-switch" class:sc-fault=fault class:on=move || on.get() role="switch" tabindex="0"
                aria-label=name aria-checked=move || if on.get() { "true" } else { "false" }
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
            aria-label=tf(K::sim_scene_button, &[("label", &label)]) aria-pressed=move || if on.get() { "true" } else { "false" }
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
            let drawn = move || shown_widgets.iter().map(|w| shown(state, w)).collect::<String>();
            view! {
                <section class="panel scene-panel" aria-label=t(K::sim_plant)>
                    <h2>{t(K::sim_plant)}</h2>
                    <svg class="sc-svg" viewBox=format!("0 0 {} {}", scene.width, scene.height)
                        role="group" aria-label=t(K::sim_plant_scene)>
                        <g inner_html=drawn></g>
                        {controls.into_iter().map(|w| view! { <Control widget=w/> }).collect_view()}
                    </svg>
                </section>
            }
        })
    }
}
