//! The I/O panel, generated from the main program's declarations: switches (or push
//! buttons) and sliders for inputs, lamps and bars for outputs.

use leptos::prelude::*;
use plc_core::export::value_number;
use plc_core::semantic::{Elem, Type};
use plc_core::vm::Value;

use crate::i18n::{t, tf, K};
use crate::state::AppState;

/// What kind of control an I/O variable gets.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    Bool,
    /// An integer (or bit string) with its type's limits.
    Int(f64, f64),
    Real,
}

/// One input or output of the main program.
#[derive(Debug, Clone, PartialEq)]
struct IoVar {
    name: String,
    kind: Kind,
    range: Option<(i64, i64)>,
    comment: Option<String>,
    /// The plant writes it on every scan (one of its sensors): shown, not set.
    from_plant: Option<String>,
}

fn kind_of(ty: Type) -> Option<Kind> {
    match ty {
        Type::Elem(Elem::Bool) => Some(Kind::Bool),
        Type::Elem(e) if e.is_integral() => {
            let (lo, hi) = e.int_range();
            Some(Kind::Int(lo as f64, hi as f64))
        }
        Type::Elem(e) if e.is_real() => Some(Kind::Real),
        _ => None,
    }
}

/// The inputs and outputs of the running program.
fn io_vars(state: AppState) -> (Vec<IoVar>, Vec<IoVar>) {
    state
        .with_sim(|s| {
            let mut inputs = Vec::new();
            let mut outputs = Vec::new();
            for (name, var) in s.listed_vars() {
                let Some(kind) = kind_of(var.ty) else { continue };
                let from_plant =
                    s.plant_drives(&name).then(|| s.plant_name().unwrap_or_default().to_string());
                let v = IoVar {
                    name,
                    kind,
                    range: var.range,
                    comment: var.comment.clone(),
                    from_plant,
                };
                if var.is_input() {
                    inputs.push(v);
                } else if var.is_output() {
                    outputs.push(v);
                }
            }
            (inputs, outputs)
        })
        .unwrap_or_default()
}

fn read_number(state: AppState, name: &str) -> f64 {
    state.read(name).as_ref().and_then(value_number).unwrap_or(0.0)
}

fn read_bool(state: AppState, name: &str) -> bool {
    matches!(state.read(name), Some(Value::Bool(true)))
}

fn number_text(x: f64, kind: Kind) -> String {
    match kind {
        Kind::Real => {
            let t = format!("{x}");
            t
        }
        _ => format!("{}", x.round() as i64),
    }
}

/// The literal written for a number typed or slid to (integers rounded, clamped to type).
fn literal(x: f64, kind: Kind) -> Option<String> {
    if !x.is_finite() {
        return None;
    }
    Some(match kind {
        Kind::Int(lo, hi) => format!("{}", x.round().clamp(lo, hi) as i128),
        Kind::Real => {
            let t = format!("{x}");
            if t.contains(['.', 'e', 'E']) {
                t
            } else {
                format!("{t}.0")
            }
        }
        Kind::Bool => if x != 0.0 { "TRUE" } else { "FALSE" }.to_string(),
    })
}

/// Inputs and outputs of the main program.
#[component]
pub fn IoPanel() -> impl IntoView {
    let state = expect_context::<AppState>();
    let vars = Memo::new(move |_| io_vars(state));
    view! {
        <section class="panel io-panel" aria-label=t(K::sim_inputs_and_outputs)>
            <h2>{t(K::sim_inputs_and_outputs)}</h2>
            <div class="io-columns">
                <div class="io-col">
                    <h3>{t(K::sim_inputs)}</h3>
                    {move || {
                        let switches = vars.with(|v| {
                            v.0.iter().any(|i| i.kind == Kind::Bool && i.from_plant.is_none())
                        });
                        switches.then(|| view! { <p class="io-legend muted small-text">{t(K::sim_hold_legend)}</p> })
                    }}
                    {move || {
                        let inputs = vars.with(|v| v.0.clone());
                        if !state.engine_ready.get() {
                            view! { <p class="muted">{t(K::lazy_loading_checker)}</p> }.into_any()
                        } else if inputs.is_empty() {
                            view! { <p class="muted">{t(K::sim_no_inputs)}</p> }.into_any()
                        } else {
                            inputs.into_iter().map(|v| match (v.kind, v.from_plant.is_some()) {
                                (Kind::Bool, false) => view! { <BoolInput var=v/> }.into_any(),
                                (_, false) => view! { <NumberInput var=v/> }.into_any(),
                                (Kind::Bool, true) => view! { <Lamp var=v/> }.into_any(),
                                (_, true) => view! { <Bar var=v/> }.into_any(),
                            }).collect_view().into_any()
                        }
                    }}
                </div>
                <div class="io-col">
                    <h3>{t(K::sim_outputs)}</h3>
                    {move || {
                        let outputs = vars.with(|v| v.1.clone());
                        if !state.engine_ready.get() {
                            view! { <p class="muted">{t(K::lazy_loading_checker)}</p> }.into_any()
                        } else if outputs.is_empty() {
                            view! { <p class="muted">{t(K::sim_no_outputs)}</p> }.into_any()
                        } else {
                            outputs.into_iter().map(|v| match v.kind {
                                Kind::Bool => view! { <Lamp var=v/> }.into_any(),
                                _ => view! { <Bar var=v/> }.into_any(),
                            }).collect_view().into_any()
                        }
                    }}
                </div>
            </div>
        </section>
    }
}

/// A BOOL input: a switch, or a push button (TRUE only while held).
#[component]
fn BoolInput(var: IoVar) -> impl IntoView {
    let state = expect_context::<AppState>();
    let push = RwSignal::new(false);
    let name = StoredValue::new(var.name.clone());
    let set = move |on: bool| {
        name.with_value(|n| state.hold_input(n, if on { "TRUE" } else { "FALSE" }));
    };
    let checked = move || name.with_value(|n| read_bool(state, n));
    let release = move || {
        if push.get_untracked() && checked() {
            set(false);
        }
    };
    view! {
        <div class="io-row" title=var.comment.clone().unwrap_or_default()>
            <label class="switch" class:push=move || push.get()>
                <input type="checkbox" prop:checked=checked
                    on:change=move |ev| {
                        if !push.get_untracked() {
                            set(event_target_checked(&ev));
                        }
                    }
                    on:click=move |ev| {
                        if push.get_untracked() {
                            ev.prevent_default();
                        }
                    }
                    on:pointerdown=move |_| {
                        if push.get_untracked() {
                            set(true);
                        }
                    }
                    on:pointerup=move |_| release()
                    on:pointerleave=move |_| release()
                    on:pointercancel=move |_| release()
                    on:keydown=move |ev| {
                        if push.get_untracked() && ev.key() == " " && !ev.repeat() {
                            ev.prevent_default();
                            set(true);
                        }
                    }
                    on:keyup=move |ev| {
                        if push.get_untracked() && ev.key() == " " {
                            ev.prevent_default();
                            release();
                        }
                    }
                    on:blur=move |_| release()/>
                <span class="io-name">{var.name.clone()}</span>
            </label>
            <label class="push-mode" title=t(K::sim_hold_title)>
                <input type="checkbox" aria-label=tf(K::sim_hold_name, &[("name", &var.name)])
                    prop:checked=move || push.get()
                    on:change=move |ev| {
                        push.set(event_target_checked(&ev));
                        if push.get_untracked() && checked() {
                            set(false);
                        }
                    }/>
                {t(K::sim_hold)}
            </label>
        </div>
    }
}

/// A numeric input: a slider and a number box.
#[component]
fn NumberInput(var: IoVar) -> impl IntoView {
    let state = expect_context::<AppState>();
    let kind = var.kind;
    let (lo0, hi0) = match var.range {
        Some((l, h)) => (l as f64, h as f64),
        None => (0.0, 100.0),
    };
    let lo = RwSignal::new(lo0);
    let hi = RwSignal::new(hi0);
    let fixed = var.range.is_some();
    let name = StoredValue::new(var.name.clone());
    // The text shown changes only when the value does: the boxes are not written again on
    // every scan of a run, which wiped out what a student was typing.
    let shown = Memo::new(move |_| number_text(name.with_value(|n| read_number(state, n)), kind));
    let write = move |text: String| {
        let Some(x) = crate::dom::number_of(&text) else {
            state.error(tf(K::sim_not_a_number, &[("text", text.trim())]));
            return;
        };
        if let Some(lit) = literal(x, kind) {
            name.with_value(|n| state.hold_input(n, &lit));
        }
    };
    let step = move || match kind {
        Kind::Real => format!("{}", ((hi.get() - lo.get()) / 1000.0).max(f64::MIN_POSITIVE)),
        _ => "1".to_string(),
    };
    let set_limit = move |sig: RwSignal<f64>, text: String| {
        if let Some(x) = crate::dom::number_of(&text) {
            if x.is_finite() {
                sig.set(x);
            }
        }
    };
    view! {
        <div class="io-row io-number" title=var.comment.clone().unwrap_or_default()>
            <label class="io-name" for=format!("io-{}", var.name)>{var.name.clone()}</label>
            <input type="range" id=format!("io-{}", var.name) aria-label=var.name.clone()
                prop:min=move || lo.get().to_string() prop:max=move || hi.get().to_string()
                prop:step=step
                prop:value=shown
                on:input=move |ev| write(event_target_value(&ev))/>
            <input type="number" class="num" aria-label=tf(K::sim_value_of, &[("name", &var.name)])
                prop:value=shown
                on:change=move |ev| write(event_target_value(&ev))/>
            {(!fixed).then(|| view! {
                <span class="limits">
                    <input type="number" class="num small" aria-label=tf(K::sim_minimum_of, &[("name", &var.name)])
                        prop:value=move || lo.get().to_string()
                        on:change=move |ev| set_limit(lo, event_target_value(&ev))/>
                    "…"
                    <input type="number" class="num small" aria-label=tf(K::sim_maximum_of, &[("name", &var.name)])
                        prop:value=move || hi.get().to_string()
                        on:change=move |ev| set_limit(hi, event_target_value(&ev))/>
                </span>
            })}
        </div>
    }
}

/// For a sensor the plant writes: which plant, in place of a control.
fn plant_note(var: &IoVar) -> Option<impl IntoView> {
    var.from_plant.as_ref().map(|plant| {
        view! { <span class="io-from-plant small-text muted">{tf(K::sim_from_plant, &[("plant", plant)])}</span> }
    })
}

/// A BOOL output (or a sensor the plant writes): a lamp.
#[component]
fn Lamp(var: IoVar) -> impl IntoView {
    let state = expect_context::<AppState>();
    let name = StoredValue::new(var.name.clone());
    let on = move || name.with_value(|n| read_bool(state, n));
    view! {
        <div class="io-row" title=var.comment.clone().unwrap_or_default()>
            <span class="lamp" class:on=on role="img"
                aria-label=move || format!("{}: {}", name.get_value(), t(if on() { K::sim_lamp_on } else { K::sim_lamp_off }))></span>
            <span class="io-name">{var.name.clone()}</span>
            {plant_note(&var)}
        </div>
    }
}

/// A numeric output (or a sensor the plant writes): a horizontal bar with its value.
#[component]
fn Bar(var: IoVar) -> impl IntoView {
    let state = expect_context::<AppState>();
    let kind = var.kind;
    let name = StoredValue::new(var.name.clone());
    let value = move || name.with_value(|n| read_number(state, n));
    // Without a subrange the scale grows to the largest magnitude seen (at least 100).
    let seen = StoredValue::new(100.0f64);
    let range = var.range;
    let fraction = move || {
        let v = value();
        let (lo, hi) = match range {
            Some((l, h)) => (l as f64, h as f64),
            None => {
                let m = seen.get_value().max(v.abs());
                seen.set_value(m);
                (if v < 0.0 { -m } else { 0.0 }, m)
            }
        };
        if hi > lo {
            ((v - lo) / (hi - lo)).clamp(0.0, 1.0)
        } else {
            0.0
        }
    };
    view! {
        <div class="io-row io-bar" title=var.comment.clone().unwrap_or_default()>
            <span class="io-name">{var.name.clone()}</span>
            <span class="bar" role="meter" aria-label=var.name.clone()
                aria-valuenow=move || number_text(value(), kind)>
                <span class="bar-fill" style=move || format!("width: {:.1}%", fraction() * 100.0)></span>
            </span>
            <output class="bar-value">{move || number_text(value(), kind)}</output>
            {plant_note(&var)}
        </div>
    }
}
