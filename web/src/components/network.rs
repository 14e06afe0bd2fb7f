//! The view of a network POU (LD, FBD or SFC kept as the file drew it): every element at its own
//! position and size, its wires along the paths the file gives, and — while its PROGRAM
//! runs — the values on them: power in green, values beside the pins that carry them
//! (`plc_core::network::live`), active SFC steps lit. Problems are marked on their element.
//! The elements are read-only (networks are imported, not drawn here); the POU can be
//! renamed and deleted.

use std::collections::{HashMap, HashSet};

use leptos::prelude::*;
use plc_core::build::Site;
use plc_core::export::value_text;
use plc_core::ladder::ContactKind;
use plc_core::network::live::{output_values, wire_value};
use plc_core::network::{
    NetElement, NetKind, NetworkLanguage, NetworkPou, NetworkPouKind, Pin, PinModifier,
};
use plc_core::vm::Value;

use crate::components::ladder::geometry::clip;
use crate::components::pou_actions::{DiagramKind, PouActions};
use crate::i18n::{t, tf, K};
use crate::state::AppState;

/// Values on the network's outputs: (`localId`, pin) → value.
type Values = HashMap<(String, String), Value>;

/// Where a pin is on the drawing.
fn pin_at(e: &NetElement, p: &Pin) -> (f64, f64) {
    (e.x + p.dx, e.y + p.dy)
}

/// The output pin of `e` a wire names (`param`), or its only one.
fn output_pin<'a>(e: &'a NetElement, param: Option<&str>) -> Option<&'a Pin> {
    match param {
        Some(p) => e.outputs.iter().find(|o| o.name.eq_ignore_ascii_case(p)).or(e.outputs.first()),
        None => e.outputs.first(),
    }
}

fn is_on(v: Option<&Value>) -> bool {
    matches!(v, Some(Value::Bool(true)))
}

/// The wires into every input of every element.
fn wires(net: &NetworkPou, values: &Values) -> impl IntoView {
    let by_id: HashMap<&str, &NetElement> =
        net.elements.iter().map(|e| (e.id.as_str(), e)).collect();
    let mut paths = Vec::new();
    for e in &net.elements {
        for p in &e.inputs {
            let (tx, ty) = pin_at(e, p);
            for w in &p.wires {
                let on = is_on(wire_value(values, w));
                let points: Vec<(f64, f64)> = if w.points.len() >= 2 {
                    w.points.clone()
                } else {
                    let Some(src) = by_id.get(w.from.as_str()) else { continue };
                    let Some(out) = output_pin(src, w.param.as_deref()) else { continue };
                    let (sx, sy) = pin_at(src, out);
                    let mid = (sx + tx) / 2.0;
                    vec![(tx, ty), (mid, ty), (mid, sy), (sx, sy)]
                };
                let d = points
                    .iter()
                    .enumerate()
                    .map(|(k, (x, y))| format!("{}{x} {y}", if k == 0 { "M" } else { " L" }))
                    .collect::<String>();
                paths.push(view! { <path class="nw-wire" class:powered=on d=d/> });
            }
        }
    }
    paths.collect_view()
}

/// The text of a value for a label beside a pin.
fn shown(v: Option<&Value>) -> Option<String> {
    v.map(|v| clip(&value_text(v), 14))
}

/// One element: its symbol, names and, while running, its values.
fn element(e: &NetElement, values: &Values, faulty: bool) -> impl IntoView {
    let (x, y, w, h) = (e.x, e.y, e.width.max(1.0), e.height.max(1.0));
    let out = |pin: &str| values.get(&(e.id.clone(), pin.to_string()));
    let id = e.id.clone();
    let (label, body) = match &e.kind {
        NetKind::LeftRail | NetKind::RightRail => {
            let on = e.kind == NetKind::LeftRail;
            (
                if on { t(K::network_left_rail) } else { t(K::network_right_rail) }.to_string(),
                view! { <rect class="nw-rail" class:powered=on x=x y=y width=w.max(3.0) height=h/> }
                    .into_any(),
            )
        }
        NetKind::Contact { operand, contact } => {
            let on = is_on(out(""));
            let state = out("")
                .map(|_| if on { t(K::network_passes_power) } else { t(K::network_open) })
                .unwrap_or("");
            let (mid, cy) = (x + w / 2.0, y + h / 2.0);
            let mark = match contact {
                ContactKind::NormallyOpen => "",
                ContactKind::NormallyClosed => "/",
                ContactKind::Rising => "P",
                ContactKind::Falling => "N",
            };
            let kind = match contact {
                ContactKind::NormallyOpen => K::network_contact,
                ContactKind::NormallyClosed => K::network_contact_nc,
                ContactKind::Rising => K::network_contact_rising,
                ContactKind::Falling => K::network_contact_falling,
            };
            (
                tf(kind, &[("operand", operand), ("state", state)]),
                view! {
                    <g class="nw-sym" class:powered=on>
                        <line x1=x y1=cy x2=mid - 5.0 y2=cy/>
                        <line x1=mid - 5.0 y1=y x2=mid - 5.0 y2=y + h/>
                        <line x1=mid + 5.0 y1=y x2=mid + 5.0 y2=y + h/>
                        <line x1=mid + 5.0 y1=cy x2=x + w y2=cy/>
                    </g>
                    <text class="nw-mark" x=mid y=cy + 4.0>{mark}</text>
                    <text class="nw-name" x=mid y=y - 4.0>{clip(operand, 16)}</text>
                }
                .into_any(),
            )
        }
        NetKind::Coil { operand, coil } => {
            let on = is_on(out(""));
            let state = out("")
                .map(|_| if on { t(K::network_on) } else { t(K::network_off) })
                .unwrap_or("");
            let (mid, cy) = (x + w / 2.0, y + h / 2.0);
            let r = (h / 2.0).max(6.0);
            let mark = crate::components::ladder::coil_letter(*coil);
            (
                tf(K::network_coil, &[("operand", operand), ("state", state)]),
                view! {
                    <g class="nw-sym" class:powered=on>
                        <line x1=x y1=cy x2=mid - 7.0 y2=cy/>
                        <path d=format!("M{} {} A{r} {r} 0 0 0 {} {}", mid - 4.0, cy - r + 2.0, mid - 4.0, cy + r - 2.0)/>
                        <path d=format!("M{} {} A{r} {r} 0 0 1 {} {}", mid + 4.0, cy - r + 2.0, mid + 4.0, cy + r - 2.0)/>
                        <line x1=mid + 7.0 y1=cy x2=x + w y2=cy/>
                    </g>
                    <text class="nw-mark" x=mid y=cy + 4.0>{mark}</text>
                    <text class="nw-name" x=mid y=y - 4.0>{clip(operand, 16)}</text>
                }
                .into_any(),
            )
        }
        NetKind::Block { type_name, instance } => {
            let outputs: Vec<String> = e
                .outputs
                .iter()
                .filter_map(|p| shown(out(&p.name)).map(|v| format!("{} = {v}", p.name)))
                .collect();
            let label = tf(
                K::network_block,
                &[
                    ("type", type_name),
                    ("instance", &instance.as_ref().map(|i| format!(" {i}")).unwrap_or_default()),
                    (
                        "outputs",
                        &if outputs.is_empty() {
                            String::new()
                        } else {
                            format!(": {}", outputs.join(", "))
                        },
                    ),
                ],
            );
            let pins_in = e
                .inputs
                .iter()
                .map(|p| {
                    let (px, py) = pin_at(e, p);
                    let negated = p.modifier == Some(PinModifier::Negated);
                    let edge = matches!(p.modifier, Some(PinModifier::Rising | PinModifier::Falling));
                    view! {
                        <text class="nw-pin" x=x + 4.0 y=py + 4.0>{clip(&p.name, 8)}</text>
                        {negated.then(|| view! { <circle class="nw-neg" cx=px + 3.0 cy=py r="3"/> })}
                        {edge.then(|| view! { <path class="nw-edge" d=format!("M{x} {} L{} {py} L{x} {}", py - 4.0, x + 5.0, py + 4.0)/> })}
                    }
                })
                .collect_view();
            let pins_out = e
                .outputs
                .iter()
                .map(|p| {
                    let (px, py) = pin_at(e, p);
                    let value = shown(out(&p.name));
                    let on = is_on(out(&p.name));
                    view! {
                        <text class="nw-pin nw-pin-out" x=x + w - 4.0 y=py + 4.0>{clip(&p.name, 8)}</text>
                        {value.map(|v| view! {
                            <text class="nw-value" class:on=on x=px + 4.0 y=py - 3.0>{v}</text>
                        })}
                    }
                })
                .collect_view();
            (
                label,
                view! {
                    <rect class="nw-box" x=x y=y width=w height=h rx="2"/>
                    <text class="nw-type" x=x + w / 2.0 y=y + 13.0>{clip(type_name, 14)}</text>
                    {instance.clone().map(|i| view! {
                        <text class="nw-name" x=x + w / 2.0 y=y - 4.0>{clip(&i, 18)}</text>
                    })}
                    {pins_in}
                    {pins_out}
                }
                .into_any(),
            )
        }
        NetKind::InVar { expr } | NetKind::OutVar { expr } | NetKind::InOutVar { expr } => {
            let value = out("");
            let text = shown(value);
            let on = is_on(value);
            (
                tf(
                    K::network_variable,
                    &[
                        ("expr", expr),
                        ("value", &text.as_ref().map(|v| format!(" = {v}")).unwrap_or_default()),
                    ],
                ),
                view! {
                    <rect class="nw-var" class:on=on x=x y=y width=w height=h rx=h / 2.0/>
                    <text class="nw-expr" x=x + w / 2.0 y=y + h / 2.0 + 4.0>{clip(expr, 20)}</text>
                    {text.map(|v| view! {
                        <text class="nw-value" class:on=on x=x + w / 2.0 y=y - 3.0>{v}</text>
                    })}
                }
                .into_any(),
            )
        }
        NetKind::Comment { text } => {
            let lines: Vec<String> = text
                .lines()
                .take(((h / 14.0) as usize).max(1))
                .map(|l| clip(l, ((w / 7.0) as usize).max(4)))
                .collect();
            (
                tf(K::network_comment, &[("text", &clip(text, 60))]),
                view! {
                    <rect class="nw-comment" x=x y=y width=w height=h/>
                    {lines.into_iter().enumerate().map(|(k, l)| view! {
                        <text class="nw-comment-text" x=x + 6.0 y=y + 15.0 + 14.0 * k as f64>{l}</text>
                    }).collect_view()}
                }
                .into_any(),
            )
        }
        NetKind::Label { label } | NetKind::Jump { label } => {
            let jump = matches!(e.kind, NetKind::Jump { .. });
            (
                tf(
                    if jump { K::network_jump } else { K::network_label },
                    &[("label", label)],
                ),
                view! {
                    <rect class="nw-var" x=x y=y width=w height=h/>
                    <text class="nw-expr" x=x + w / 2.0 y=y + h / 2.0 + 4.0>{format!("{}{}", if jump { "▶ " } else { "" }, clip(label, 14))}</text>
                }
                .into_any(),
            )
        }
        NetKind::Return => (
            t(K::network_return).to_string(),
            view! {
                <rect class="nw-var" x=x y=y width=w height=h/>
                <text class="nw-expr" x=x + w / 2.0 y=y + h / 2.0 + 4.0>"RETURN"</text>
            }
            .into_any(),
        ),
        NetKind::Step { .. }
        | NetKind::Transition { .. }
        | NetKind::SelectionDivergence
        | NetKind::SelectionConvergence
        | NetKind::SimultaneousDivergence
        | NetKind::SimultaneousConvergence
        | NetKind::JumpStep { .. }
        | NetKind::ActionBlock { .. } => chart_element(e, is_on(out(""))),
        NetKind::Connector { name } | NetKind::Continuation { name } => {
            let connector = matches!(e.kind, NetKind::Connector { .. });
            (
                tf(
                    if connector { K::network_connector } else { K::network_continuation },
                    &[("name", name)],
                ),
                view! {
                    <path class="nw-var" d=format!("M{x} {y} L{} {y} L{} {} L{} {} L{x} {} Z", x + w - h / 2.0, x + w, y + h / 2.0, x + w - h / 2.0, y + h, y + h)/>
                    <text class="nw-expr" x=x + w / 2.0 y=y + h / 2.0 + 4.0>{clip(name, 14)}</text>
                }
                .into_any(),
            )
        }
    };
    view! {
        <g class="nw-el" class:faulty=faulty role="img" aria-label=label data-local-id=id>
            {body}
        </g>
    }
}

/// An element of an SFC chart: its accessible name and its drawing (`active`: a step
/// whose flag is set).
fn chart_element(e: &NetElement, active: bool) -> (String, AnyView) {
    let (x, y, w, h) = (e.x, e.y, e.width.max(1.0), e.height.max(1.0));
    match &e.kind {
        NetKind::Step { name, initial } => (
            tf(
                if *initial { K::network_initial_step } else { K::network_step },
                &[("name", name), ("active", if active { t(K::network_active) } else { "" })],
            ),
            view! {
                <rect class="nw-step" class:active=active x=x y=y width=w height=h/>
                {initial.then(|| view! {
                    <rect class="nw-step-inner" x=x + 3.0 y=y + 3.0 width=(w - 6.0).max(1.0) height=(h - 6.0).max(1.0)/>
                })}
                <text class="nw-expr" x=x + w / 2.0 y=y + h / 2.0 + 4.0>{clip(name, 14)}</text>
            }
            .into_any(),
        ),
        NetKind::Transition { condition, negated, .. } => {
            let text = match condition {
                plc_core::network::SfcCondition::Inline { st } => st.clone(),
                plc_core::network::SfcCondition::Reference { name } => name.clone(),
                plc_core::network::SfcCondition::Wired => String::new(),
            };
            let text = if *negated { format!("NOT {text}") } else { text };
            let cy = y + h / 2.0;
            (
                if text.is_empty() {
                    t(K::network_transition).to_string()
                } else {
                    tf(K::network_transition_condition, &[("condition", &clip(&text, 60))])
                },
                view! {
                    <line class="nw-chart" x1=x + w / 2.0 y1=y x2=x + w / 2.0 y2=y + h/>
                    <rect class="nw-bar" x=x y=cy - 2.0 width=w height="4"/>
                    <text class="nw-cond" x=x + w + 6.0 y=cy + 4.0>{clip(&text, 30)}</text>
                }
                .into_any(),
            )
        }
        NetKind::JumpStep { target } => (
            tf(K::network_jump_step, &[("target", target)]),
            view! {
                <path class="nw-jump" d=format!("M{x} {y} L{} {y} L{} {} Z", x + w, x + w / 2.0, y + h)/>
                <text class="nw-cond" x=x + w + 4.0 y=y + h / 2.0 + 4.0>{clip(target, 14)}</text>
            }
            .into_any(),
        ),
        NetKind::ActionBlock { actions } => {
            let rows = actions.len().max(1) as f64;
            let row_h = h / rows;
            let q_w = 30.0_f64.min(w / 3.0);
            let names: Vec<String> = actions
                .iter()
                .map(|a| match &a.action {
                    plc_core::network::SfcActionBody::Reference { name } => name.clone(),
                    plc_core::network::SfcActionBody::Inline { st } => st.trim().to_string(),
                })
                .collect();
            let label = actions
                .iter()
                .zip(&names)
                .map(|(a, n)| format!("{} {}", a.qualifier, clip(n, 30)))
                .collect::<Vec<_>>()
                .join(", ");
            (
                tf(K::network_actions, &[("actions", &label)]),
                view! {
                    <rect class="nw-box" x=x y=y width=w height=h/>
                    <line class="nw-chart" x1=x + q_w y1=y x2=x + q_w y2=y + h/>
                    {actions.iter().zip(names).enumerate().map(|(k, (a, n))| {
                        let ry = y + row_h * k as f64;
                        view! {
                            {(k > 0).then(|| view! { <line class="nw-chart" x1=x y1=ry x2=x + w y2=ry/> })}
                            <text class="nw-pin" x=x + 4.0 y=ry + row_h / 2.0 + 4.0>{clip(&a.qualifier, 3)}</text>
                            <text class="nw-pin" x=x + q_w + 4.0 y=ry + row_h / 2.0 + 4.0>{clip(&n, ((w - q_w) / 7.0).max(4.0) as usize)}</text>
                        }
                    }).collect_view()}
                }
                .into_any(),
            )
        }
        kind => {
            let simultaneous = matches!(
                kind,
                NetKind::SimultaneousDivergence | NetKind::SimultaneousConvergence
            );
            let name = t(match kind {
                NetKind::SelectionDivergence => K::network_selection_divergence,
                NetKind::SelectionConvergence => K::network_selection_convergence,
                NetKind::SimultaneousDivergence => K::network_simultaneous_divergence,
                _ => K::network_simultaneous_convergence,
            });
            (
                name.to_string(),
                view! {
                    <line class="nw-chart" x1=x y1=y x2=x + w y2=y/>
                    {simultaneous.then(|| view! { <line class="nw-chart" x1=x y1=y + 3.0 x2=x + w y2=y + 3.0/> })}
                }
                .into_any(),
            )
        }
    }
}

/// The drawing of a network.
fn network_svg(net: &NetworkPou, values: &Values, faulty: &HashSet<String>) -> AnyView {
    let xs = net.elements.iter().flat_map(|e| [e.x, e.x + e.width]);
    let ys = net.elements.iter().flat_map(|e| [e.y, e.y + e.height]);
    let (x0, x1) = xs.fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
    let (y0, y1) = ys.fold((f64::MAX, f64::MIN), |(a, b), y| (a.min(y), b.max(y)));
    if !x0.is_finite() || !y0.is_finite() {
        return view! { <p class="muted">{t(K::network_no_elements)}</p> }.into_any();
    }
    let (vx, vy) = (x0 - 40.0, y0 - 30.0);
    let (vw, vh) = (x1 - x0 + 100.0, y1 - y0 + 60.0);
    let language = net.language.name();
    view! {
        <svg class="nw-svg" viewBox=format!("{vx} {vy} {vw} {vh}") width=vw height=vh
            role="group" aria-label=tf(K::network_label_aria, &[("language", language), ("name", &net.name)])>
            {wires(net, values)}
            {net.elements.iter().map(|e| element(e, values, faulty.contains(&e.id))).collect_view()}
        </svg>
    }
    .into_any()
}

/// The view of the network POU `name`.
#[component]
pub fn NetworkView(name: String) -> impl IntoView {
    let state = expect_context::<AppState>();
    let key = name.clone();
    let net = Memo::new(move |_| {
        state
            .project
            .with(|p| p.networks.iter().find(|n| n.name.eq_ignore_ascii_case(&key)).cloned())
    });
    let key = name.clone();
    let runs =
        Memo::new(move |_| state.running.get().is_some_and(|r| r.eq_ignore_ascii_case(&key)));
    // A function block's network shows one of its instances in the running PROGRAM.
    let key = name.clone();
    let is_fb = Memo::new(move |_| {
        net.with(|n| n.as_ref().is_some_and(|n| n.kind == NetworkPouKind::FunctionBlock))
    });
    let instances = Memo::new(move |_| {
        state.running.track();
        if !is_fb.get() {
            return Vec::new();
        }
        state.sim.with_value(|s| s.as_ref().map(|s| s.instances_of(&key))).unwrap_or_default()
    });
    let picked = RwSignal::new(None::<String>);
    let instance = Memo::new(move |_| {
        let list = instances.get();
        picked.get().filter(|i| list.contains(i)).or_else(|| list.first().cloned())
    });
    let values = Memo::new(move |_| {
        let prefix = match (runs.get(), instance.get()) {
            (true, _) => String::new(),
            (false, Some(inst)) => format!("{inst}."),
            (false, None) => return Values::new(),
        };
        net.with(|n| {
            let Some(n) = n.as_ref() else { return Values::new() };
            // A recorded scan shown: its values and watches, else the present.
            let past = state.with_shown_view(|s| {
                output_values(n, &|path: &str| {
                    if prefix.is_empty() {
                        s.read(path).ok().or_else(|| s.watch(path).cloned())
                    } else {
                        s.read(&format!("{prefix}{path}")).ok()
                    }
                })
            });
            if let Some(past) = past {
                return past;
            }
            state
                .with_sim(|s| {
                    output_values(n, &|path: &str| {
                        if prefix.is_empty() {
                            s.read(path).ok().or_else(|| s.watch(path).cloned())
                        } else {
                            s.read(&format!("{prefix}{path}")).ok()
                        }
                    })
                })
                .unwrap_or_default()
        })
    });
    let key = name.clone();
    let faulty = Memo::new(move |_| {
        state.diagnostics.with(|ds| {
            ds.iter()
                .filter(|d| d.error)
                .filter_map(|d| match &d.site {
                    Site::Network { pou, element: Some(id) } if pou.eq_ignore_ascii_case(&key) => {
                        Some(id.clone())
                    }
                    _ => None,
                })
                .collect::<HashSet<String>>()
        })
    });
    let key = name.clone();
    let focused = Memo::new(move |_| match state.focus.get() {
        Some(Site::Network { pou, element: Some(id) }) if pou.eq_ignore_ascii_case(&key) => {
            Some(id)
        }
        _ => None,
    });
    let title = name.clone();
    let shown_name = name.clone();
    let actions_name = name.clone();
    let status = move || {
        if runs.get() || instance.get().is_some() {
            return None;
        }
        let kind = net.with(|n| n.as_ref().map_or(NetworkPouKind::Program, |n| n.kind));
        Some(match (kind, state.running.get()) {
            (NetworkPouKind::Function, _) => t(K::network_status_function).to_string(),
            (NetworkPouKind::FunctionBlock, Some(r)) => {
                tf(K::network_status_no_instance, &[("program", &r), ("name", &name)])
            }
            (NetworkPouKind::Program, Some(r)) => {
                tf(K::network_status_other, &[("program", &r), ("name", &name)])
            }
            (_, None) => t(K::network_status_idle).to_string(),
        })
    };
    let instance_picker = move || {
        let list = instances.get();
        (!list.is_empty()).then(|| {
            let current = instance.get().unwrap_or_default();
            view! {
                <label class="nw-instance">{t(K::network_instance)}" "
                    <select aria-label=t(K::network_instance) on:change=move |ev| picked.set(Some(event_target_value(&ev)))>
                        {list.into_iter().map(|i| {
                            let selected = i == current;
                            view! { <option value=i.clone() selected=selected>{i.clone()}</option> }
                        }).collect_view()}
                    </select>
                </label>
            }
        })
    };
    let language =
        move || net.with(|n| n.as_ref().map_or(NetworkLanguage::Ld, |n| n.language).name());
    view! {
        <section class="panel network-view" aria-label=move || tf(K::network_label_aria, &[("language", language()), ("name", &title)])>
            <div class="ed-toolbar">
                <h2>{language}</h2>
                <span class="pou-title">{shown_name}</span>
                <span class="ed-spacer"></span>
                {instance_picker}
                <span class="view-note-inline">{t(K::network_as_drawn)}</span>
                <PouActions kind=DiagramKind::Network name=actions_name/>
            </div>
            {move || status().map(|s| view! { <p class="view-note">{s}</p> })}
            {move || focused.get().map(|id| view! {
                <p class="view-note" role="status">{tf(K::network_marked, &[("id", &id)])}</p>
            })}
            <div class="nw-wrap" tabindex="0">
                {move || match net.get() {
                    Some(n) => {
                        let mut marked = faulty.get();
                        if let Some(id) = focused.get() {
                            marked.insert(id);
                        }
                        values.with(|v| network_svg(&n, v, &marked))
                    }
                    None => view! { <p class="muted">{t(K::network_gone)}</p> }.into_any(),
                }}
            </div>
        </section>
    }
}
