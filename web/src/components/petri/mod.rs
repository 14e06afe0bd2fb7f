//! The Petri net view and editor: a net POU drawn in SVG by hand at its stored positions
//! (or laid out automatically until the first edit), edited with the canvas tools, keys and
//! the properties panel (`editor.rs` maps them to the core's net edits); while its PROGRAM
//! runs, tokens come from the step variables through the place map and the transitions that
//! fired on the last scan (and the enabled ones) are lit. Beside it the generated CASE OF
//! code with the active branches lit; below, the analysis summary.

mod analysis;
mod code;
mod details;
mod editor;
pub mod geometry;
pub mod layout;
pub mod live;
mod play;
mod props;

use leptos::prelude::*;
use plc_core::build::Site;
use plc_core::export::value_number;
use plc_core::petri::{build, compile, Compiled, NetElement, PetriPou, PtNet};

use crate::components::ladder::{geometry::clip, scroll_to};
use crate::components::pou_actions::{DiagramKind, PouActions};
use crate::i18n::{t, tf, K};
use crate::state::{marking_of, AppState, RunMode};
use analysis::AnalysisPanel;
use code::CodePanel;
use details::ElementDetails;
use editor::{NetEditor, NetTool, Selection};
use geometry::{
    arc_line, bar_of, canvas_box, label_box, label_on_left, macro_box, view_box, Bar, PLACE_R,
};
use layout::{layout, NetLayout, Point};
use play::{Play, PlayControls};
use props::Properties;

/// How long a firing's tokens travel (into the bar, then out), in milliseconds.
const FLY_MS: u64 = 260;

/// Characters of a guard shown beside its transition.
const GUARD_CHARS: usize = 26;

/// The form of a count's noun (`one`, `few` or `many` of `forms`) in the language shown.
pub(super) fn plural(n: u64, [one, few, many]: [K; 3]) -> K {
    crate::i18n::plural(n, one, few, many)
}

/// Everything the drawing's reactive parts share.
#[derive(Clone, Copy)]
struct NetCtx {
    state: AppState,
    name: StoredValue<String>,
    /// Tokens per place: live, or the initial marking when not running.
    tokens: Memo<Vec<u32>>,
    fired: Memo<Vec<bool>>,
    enabled: Memo<Vec<bool>>,
    /// Whether the simulator runs this net (transitions then say enabled / fired).
    runs: Memo<bool>,
    editor: NetEditor,
    /// The token game or a deadlock's path being played.
    play: RwSignal<Option<Play>>,
    /// The net as a place/transition net (for the token game).
    pt: Memo<Option<PtNet>>,
    /// Tokens travelling along the arcs of the transitions that just fired (an animation
    /// number, so each firing starts its own, and which transitions).
    flying: RwSignal<Option<(u64, Vec<bool>)>>,
}

impl NetCtx {
    /// Whether `site` is element `element` of this POU.
    fn is(&self, site: Option<Site>, element: &NetElement) -> bool {
        match site {
            Some(Site::Petri { pou, element: Some(e), .. }) => {
                self.name.with_value(|n| pou.eq_ignore_ascii_case(n)) && e == *element
            }
            _ => false,
        }
    }

    /// The worst diagnostic on an element: Some(true) error, Some(false) warning.
    fn problem(&self, element: &NetElement) -> Option<bool> {
        self.state.diagnostics.with(|ds| {
            ds.iter()
                .filter(|d| self.is(Some(d.site.clone()), element))
                .map(|d| d.error)
                .reduce(|a, b| a || b)
        })
    }

    fn is_selected(&self, id: &str) -> bool {
        self.editor.selected.with(|s| matches!(s, Some(Selection::Element(e)) if e == id))
    }

    /// The handlers every place and transition has: pressed, focused, keys. In the token
    /// game a press on a transition fires it.
    fn press(&self, id: &str, c: Point, ev: &web_sys::PointerEvent) {
        ev.stop_propagation();
        if self.play.with_untracked(|p| p.as_ref().is_some_and(|p| p.game)) {
            let fired = self.pt.with_untracked(|net| {
                let net = net.as_ref()?;
                let t = net.transition_names.iter().position(|n| n == id)?;
                let mut fired = false;
                self.play.update(|p| {
                    if let Some(p) = p {
                        fired = p.fire(net, t);
                    }
                });
                Some(fired)
            });
            if fired.is_some() {
                return;
            }
        }
        self.editor.press(Some(id.to_string()), Some(c), ev);
    }

    fn focus(&self, id: &str) {
        let now = Some(Selection::Element(id.to_string()));
        if self.editor.selected.get_untracked() != now {
            self.editor.selected.set(now);
        }
    }

    fn key(&self, id: &str, c: Point, ev: &web_sys::KeyboardEvent) {
        let (dx, dy) = match ev.key().as_str() {
            "ArrowLeft" => (-1.0, 0.0),
            "ArrowRight" => (1.0, 0.0),
            "ArrowUp" => (0.0, -1.0),
            "ArrowDown" => (0.0, 1.0),
            "Enter" => {
                ev.prevent_default();
                self.focus(id);
                props::focus_first_field();
                return;
            }
            key => {
                if self.editor.key(key, ev.ctrl_key() || ev.meta_key(), ev.shift_key()) {
                    ev.prevent_default();
                }
                return;
            }
        };
        ev.prevent_default();
        self.focus(id);
        self.editor.nudge(id, c, dx, dy);
    }
}

fn token_dots(n: u32, c: Point) -> AnyView {
    let offsets: &[(f64, f64)] = match n {
        0 => &[],
        1 => &[(0.0, 0.0)],
        2 => &[(-5.5, 0.0), (5.5, 0.0)],
        3 => &[(-5.5, 4.0), (5.5, 4.0), (0.0, -5.5)],
        4 => &[(-5.0, -5.0), (5.0, -5.0), (-5.0, 5.0), (5.0, 5.0)],
        _ => &[], // written as a number beside the place (`place_labels`)
    };
    let r = if n == 1 { 6.0 } else { 4.0 };
    offsets
        .iter()
        .map(|(dx, dy)| view! { <circle class="pn-token" cx=c.x + dx cy=c.y + dy r=r/> })
        .collect_view()
        .into_any()
}

fn place_view(
    ctx: NetCtx,
    pou: &PetriPou,
    compiled: Option<&Compiled>,
    i: usize,
    c: Point,
) -> AnyView {
    let place = &pou.net.places[i];
    let element = NetElement::Place(place.id.clone());
    let shown = if place.name.trim().is_empty() { place.id.clone() } else { place.name.clone() };
    let case = match compiled.and_then(|c| c.generated.place_map.places.get(i)) {
        Some(e) => format!("{} = {}", e.step_variable, e.value),
        None => place.label.to_string(),
    };
    let id = place.id.clone();
    let tokens = move || ctx.tokens.with(|t| t.get(i).copied().unwrap_or(0));
    let el = StoredValue::new(element);
    let title = format!(
        "{}{}",
        tf(K::petri_place_title, &[("name", &shown), ("label", &place.label.to_string())]),
        if place.actions.trim().is_empty() {
            String::new()
        } else {
            format!("\n{}", place.actions.trim())
        }
    );
    let (pid, kid, sid) = (id.clone(), id.clone(), id.clone());
    let place_id = id.clone();
    let why_id = place.id.clone();
    let label_name = shown.clone();
    view! {
        <g class="pn-place" class:marked=move || { tokens() > 0 }
            class:has-err=move || el.with_value(|e| ctx.problem(e)) == Some(true)
            class:has-warn=move || el.with_value(|e| ctx.problem(e)) == Some(false)
            class:focused=move || el.with_value(|e| ctx.is(ctx.state.focus.get(), e))
            class:faulted=move || el.with_value(|e| ctx.is(ctx.state.fault_site.get(), e))
            class:selected=move || ctx.is_selected(&sid)
            class:arc-from=move || ctx.editor.arc_from.with(|a| a.as_deref() == Some(id.as_str()))
            id=ctx.editor.element_dom_id(&place.id) data-id=place.id.clone() role="button" tabindex="0"
            data-tokens=move || tokens().to_string()
            aria-label=move || {
                let n = tokens();
                let key = plural(
                    n.into(),
                    [K::petri_place_tokens_one, K::petri_place_tokens_few, K::petri_place_tokens_many],
                );
                tf(key, &[("name", &label_name), ("n", &n.to_string())])
            }
            on:pointerdown=move |ev: leptos::ev::PointerEvent| ctx.press(&pid, c, &ev)
            on:focus=move |_| ctx.focus(&place_id)
            on:keydown=move |ev: leptos::ev::KeyboardEvent| ctx.key(&kid, c, &ev)>
            <title>{title}</title>
            <circle class="pn-circle" cx=c.x cy=c.y r=PLACE_R/>
            {move || token_dots(tokens(), c)}
            <text class="pn-name" x=c.x y=c.y - PLACE_R - 6.0>{clip(&shown, 16)}</text>
        </g>
        // Outside the place's button, whose visible text must be its name alone (the
        // accessible name holds the count; the CASE label is in the tooltip).
        <g class="pn-labels" aria-hidden="true">
            {move || (tokens() > 4).then(|| view! { <text class="pn-token-count" x=c.x y=c.y + 5.0>{tokens()}</text> })}
            <text class="pn-case" x=c.x y=c.y + PLACE_R + 14.0>{case}</text>
        </g>
        {move || ctx.runs.get().then(|| why_place(ctx.state, &why_id, c))}
    }
    .into_any()
}

/// `Why does P3 hold a token?` beside a place of the running net (issue 36).
fn why_place(state: AppState, id: &str, c: Point) -> impl IntoView {
    let label = tf(K::petri_why_place, &[("place", id)]);
    let id = StoredValue::new(id.to_string());
    let ask = move || id.with_value(|p| state.ask_why_place(p));
    let (x, y) = (c.x + PLACE_R + 4.0, c.y - PLACE_R - 4.0);
    view! {
        <g class="pn-why" role="button" tabindex="0" aria-label=label
            on:pointerdown=move |ev: leptos::ev::PointerEvent| ev.stop_propagation()
            on:click=move |ev: leptos::ev::MouseEvent| {
                ev.stop_propagation();
                ask();
            }
            on:keydown=move |ev: leptos::ev::KeyboardEvent| {
                ev.stop_propagation();
                if ev.key() == "Enter" || ev.key() == " " {
                    ev.prevent_default();
                    ask();
                }
            }>
            <title>{t(K::petri_why)}</title>
            <circle cx=x cy=y r="7"/>
            <text x=x y=y + 4.0 text-anchor="middle">"?"</text>
        </g>
    }
}

fn transition_view(
    ctx: NetCtx,
    pou: &PetriPou,
    j: usize,
    c: Point,
    bar: Bar,
    label_left: bool,
) -> AnyView {
    let tr = &pou.net.transitions[j];
    let element = NetElement::Transition(tr.id.clone());
    let shown = if tr.name.trim().is_empty() { tr.id.clone() } else { tr.name.clone() };
    let guard =
        if tr.guard.trim().is_empty() { "TRUE".to_string() } else { tr.guard.trim().to_string() };
    let (hw, hh) = bar.half();
    let el = StoredValue::new(element);
    let fired = move || ctx.fired.with(|f| f.get(j).copied().unwrap_or(false));
    let enabled = move || ctx.enabled.with(|f| f.get(j).copied().unwrap_or(false));
    let title = tf(
        K::petri_transition_title,
        &[("name", &shown), ("guard", &guard), ("priority", &tr.priority.to_string())],
    );
    let (label_x, anchor) =
        if label_left { (c.x - hw - 6.0, "end") } else { (c.x + hw + 6.0, "start") };
    let id = tr.id.clone();
    let (pid, kid, sid, fid) = (id.clone(), id.clone(), id.clone(), id.clone());
    let label_name = shown.clone();
    view! {
        <g class="pn-transition" class:fired=fired class:enabled=enabled
            class:has-err=move || el.with_value(|e| ctx.problem(e)) == Some(true)
            class:has-warn=move || el.with_value(|e| ctx.problem(e)) == Some(false)
            class:focused=move || el.with_value(|e| ctx.is(ctx.state.focus.get(), e))
            class:faulted=move || el.with_value(|e| ctx.is(ctx.state.fault_site.get(), e))
            class:selected=move || ctx.is_selected(&sid)
            class:arc-from=move || ctx.editor.arc_from.with(|a| a.as_deref() == Some(id.as_str()))
            id=ctx.editor.element_dom_id(&tr.id) data-id=tr.id.clone() role="button" tabindex="0"
            aria-label=move || {
                let mut label = tf(K::petri_transition_name, &[("name", &label_name)]);
                if ctx.runs.get() {
                    if enabled() {
                        label.push_str(t(K::petri_state_enabled));
                    }
                    if fired() {
                        label.push_str(t(K::petri_state_fired));
                    }
                }
                label
            }
            on:pointerdown=move |ev: leptos::ev::PointerEvent| ctx.press(&pid, c, &ev)
            on:focus=move |_| ctx.focus(&fid)
            on:keydown=move |ev: leptos::ev::KeyboardEvent| ctx.key(&kid, c, &ev)>
            <title>{title}</title>
            <rect class="pn-hit" x=c.x - hw - 4.0 y=c.y - hh - 4.0 width=2.0 * hw + 8.0 height=2.0 * hh + 8.0/>
            <rect class="pn-bar" x=c.x - hw y=c.y - hh width=2.0 * hw height=2.0 * hh rx="1.5"/>
            <text class="pn-tname" x=label_x y=c.y - 2.0 text-anchor=anchor>{clip(&shown, 18)}</text>
        </g>
        // Outside the transition's button, whose visible text must be its name alone (the
        // guard is in the tooltip and the details).
        <g class="pn-labels" aria-hidden="true">
            <text class="pn-guard" x=label_x y=c.y + 11.0 text-anchor=anchor>{clip(&guard, GUARD_CHARS)}</text>
        </g>
    }
    .into_any()
}

/// The SVG of the net.
fn net_svg(
    ctx: NetCtx,
    pou: &PetriPou,
    compiled: Option<&Compiled>,
    lay: &NetLayout,
) -> impl IntoView {
    let net = &pou.net;
    let place_at = |id: &str| net.places.iter().position(|p| p.id == id);
    let trans_at = |id: &str| net.transitions.iter().position(|t| t.id == id);
    // Bars across the flow.
    let bars: Vec<Bar> = (0..net.transitions.len())
        .map(|j| {
            let tid = &net.transitions[j].id;
            let ins: Vec<Point> = net
                .arcs
                .iter()
                .filter(|a| &a.to == tid)
                .filter_map(|a| place_at(&a.from).map(|i| lay.places[i]))
                .collect();
            let outs: Vec<Point> = net
                .arcs
                .iter()
                .filter(|a| &a.from == tid)
                .filter_map(|a| place_at(&a.to).map(|i| lay.places[i]))
                .collect();
            bar_of(lay.transitions[j], &ins, &outs)
        })
        .collect();
    let arcs = net
        .arcs
        .iter()
        .filter_map(|a| {
            let (p, t, place_first) = match (place_at(&a.from), trans_at(&a.to)) {
                (Some(p), Some(t)) => (p, t, true),
                _ => (place_at(&a.to)?, trans_at(&a.from)?, false),
            };
            let twin = net.arcs.iter().any(|b| b.from == a.to && b.to == a.from);
            let (s, e) = arc_line(lay.places[p], lay.transitions[t], bars[t], place_first, twin);
            let weight = (a.weight != 1).then(|| {
                let (mx, my) = ((s.x + e.x) / 2.0, (s.y + e.y) / 2.0);
                view! { <text class="pn-weight" x=mx + 5.0 y=my - 4.0>{a.weight}</text> }
            });
            // A firing sends a token from each input place into the bar, then from the
            // bar to each output place (half the animation each).
            let (start, end) = if place_first {
                (lay.places[p], lay.transitions[t])
            } else {
                (lay.transitions[t], lay.places[p])
            };
            let delay = if place_first { 0 } else { FLY_MS / 2 };
            let fly = move || {
                ctx.flying.with(|f| {
                    let (run, fired) = f.as_ref()?;
                    fired.get(t).copied().unwrap_or(false).then(|| view! {
                        <circle class="pn-flying" r="5" cx=start.x cy=start.y data-run=*run
                            style=format!(
                                "--dx:{:.1}px;--dy:{:.1}px;animation-delay:{delay}ms;animation-duration:{}ms",
                                end.x - start.x, end.y - start.y, FLY_MS / 2
                            )/>
                    })
                })
            };
            let this = Selection::Arc(a.from.clone(), a.to.clone());
            let pressed = this.clone();
            let selected = move || ctx.editor.selected.with(|s| s.as_ref() == Some(&this));
            Some(view! {
                <line class="pn-arc" class:selected=selected x1=s.x y1=s.y x2=e.x y2=e.y marker-end="url(#pn-arrow)"/>
                <line class="pn-arc-hit" x1=s.x y1=s.y x2=e.x y2=e.y data-arc="1"
                    role="button" aria-label=tf(K::petri_arc_label, &[("from", &a.from), ("to", &a.to)])
                    on:pointerdown=move |ev: leptos::ev::PointerEvent| {
                        ev.stop_propagation();
                        if ctx.editor.tool.get_untracked() == NetTool::Select {
                            ctx.editor.selected.set(Some(pressed.clone()));
                        }
                    }/>
                {weight}
                {fly}
            })
        })
        .collect_view();
    let boxes: Vec<(usize, (f64, f64, f64, f64))> = net
        .macro_places
        .iter()
        .enumerate()
        .filter_map(|(k, m)| {
            let pts: Vec<Point> =
                m.places.iter().filter_map(|id| place_at(id)).map(|i| lay.places[i]).collect();
            macro_box(&pts).map(|b| (k, b))
        })
        .collect();
    let macros = boxes
        .iter()
        .map(|&(k, (x, y, w, h))| {
            let m = &net.macro_places[k];
            let members: Vec<usize> = m.places.iter().filter_map(|id| place_at(id)).collect();
            let marked = move || {
                ctx.tokens.with(|t| members.iter().any(|&i| t.get(i).copied().unwrap_or(0) > 0))
            };
            let label = if m.name.trim().is_empty() { m.id.clone() } else { m.name.clone() };
            let label = if m.comment.trim().is_empty() {
                label
            } else {
                format!("{label}: {}", m.comment.trim())
            };
            view! {
                <g class="pn-macro" class:marked=marked data-id=m.id.clone()>
                    <rect x=x y=y width=w height=h rx="10"/>
                    <text class="pn-macro-name" x=x + 4.0 y=y - 5.0>{clip(&label, 40)}</text>
                </g>
            }
        })
        .collect_view();
    let left: Vec<bool> = (0..net.transitions.len())
        .map(|j| label_on_left(lay.transitions[j], bars[j].half().0, &lay.places))
        .collect();
    // Places and transitions in reading order (top to bottom, left to right): the order
    // Tab visits them in.
    let mut order: Vec<(Point, bool, usize)> = (0..net.places.len())
        .map(|i| (lay.places[i], true, i))
        .chain((0..net.transitions.len()).map(|j| (lay.transitions[j], false, j)))
        .collect();
    plc_core::order::sort_by(&mut order, |a, b| {
        a.0.y.total_cmp(&b.0.y).then(a.0.x.total_cmp(&b.0.x))
    });
    let elements = order
        .into_iter()
        .map(|(c, is_place, k)| {
            if is_place {
                place_view(ctx, pou, compiled, k, c)
            } else {
                transition_view(ctx, pou, k, c, bars[k], left[k])
            }
        })
        .collect_view();
    let points: Vec<Point> = lay.places.iter().chain(&lay.transitions).copied().collect();
    let mut extra: Vec<(f64, f64, f64, f64)> = boxes.iter().map(|&(_, b)| b).collect();
    extra.extend(
        (0..net.transitions.len())
            .filter(|&j| left[j])
            .map(|j| label_box(lay.transitions[j], bars[j].half().0, true)),
    );
    let (vx, vy, vw, vh) = canvas_box(view_box(&points, &extra));
    let zoom = ctx.editor.zoom;
    let editor = ctx.editor;
    view! {
        <svg class="pn-svg" viewBox=format!("{vx} {vy} {vw} {vh}")
            width=move || vw * zoom.get() height=move || vh * zoom.get()
            id=ctx.editor.canvas_id() role="group" aria-label=t(K::petri_net_canvas)
            class:tool-add=move || matches!(editor.tool.get(), NetTool::Place | NetTool::Transition)
            class:tool-arc=move || editor.tool.get() == NetTool::Arc
            on:pointerdown=move |ev: leptos::ev::PointerEvent| {
                // Presses on elements and arcs are theirs.
                use wasm_bindgen::JsCast;
                let on_element = ev.target()
                    .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
                    .and_then(|e| e.closest("[data-id], [data-arc]").ok().flatten())
                    .is_some();
                if !on_element {
                    editor.press(None, None, &ev);
                }
            }>
            <defs>
                <marker id="pn-arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7"
                    markerHeight="7" orient="auto-start-reverse">
                    <path d="M0 0 L10 5 L0 10 z" class="pn-arrowhead"/>
                </marker>
            </defs>
            {macros}
            {arcs}
            {elements}
        </svg>
    }
}

/// The view of Petri net POU `name`.
#[component]
pub fn PetriView(name: String) -> impl IntoView {
    let state = expect_context::<AppState>();
    let key = name.clone();
    let pou =
        Memo::new(move |_| state.project.with(|p| p.petri.iter().find(|n| n.name == key).cloned()));
    let compiled = Memo::new(move |_| pou.with(|p| p.as_ref().and_then(|p| compile(p).ok())));
    let key = name.clone();
    let runs =
        Memo::new(move |_| state.running.get().is_some_and(|r| r.eq_ignore_ascii_case(&key)));
    let live_marking = Memo::new(move |_| {
        if !runs.get() {
            return None;
        }
        compiled.with(|c| {
            let map = &c.as_ref()?.generated.place_map;
            state.with_readout(|s| marking_of(s, map))
        })
    });
    let play: RwSignal<Option<Play>> = RwSignal::new(None);
    let pt = Memo::new(move |_| pou.with(|p| p.as_ref().and_then(|p| build(&p.net).ok())));
    let played =
        Memo::new(move |_| play.with(|g| pt.with(|n| Some(g.as_ref()?.marking(n.as_ref()?)))));
    let tokens =
        Memo::new(move |_| match played.get().map(|(m, _)| m).or_else(|| live_marking.get()) {
            Some(m) => m,
            None => pou.with(|p| {
                p.as_ref()
                    .map(|p| p.net.places.iter().map(|q| q.tokens).collect())
                    .unwrap_or_default()
            }),
        });
    // Enabled by the marking (guards aside), capacities included.
    let enabled = Memo::new(move |_| {
        pt.with(|n| {
            let Some(n) = n.as_ref() else { return Vec::new() };
            tokens.with(|m| {
                if m.len() != n.places() {
                    return vec![false; n.transitions()];
                }
                (0..n.transitions()).map(|t| n.enabled(m, t)).collect()
            })
        })
    });
    // While running, a firing stays lit until the marking changes again (a scan lasts a
    // few milliseconds); when stepping, exactly the last scan's firings are lit.
    let held_fired: StoredValue<Option<(Vec<u32>, Vec<bool>)>> = StoredValue::new(None);
    let fired = Memo::new(move |_| {
        if let Some((_, last)) = played.get() {
            let n = pt.with(|n| n.as_ref().map_or(0, PtNet::transitions));
            return (0..n).map(|t| Some(t) == last).collect();
        }
        let Some(now) = live_marking.get() else { return Vec::new() };
        // A recorded scan shows the firings of that scan: the marking at the end of the
        // scan before, against its own.
        let past = state
            .with_shown_view(|v| {
                compiled.with(|c| {
                    let c = c.as_ref()?;
                    let before = c.generated.place_map.marking(|var| {
                        v.read_previous(var).as_ref().and_then(value_number).map(|x| x as i64)
                    });
                    Some(live::fired(&c.net.pre, &c.net.post, &before, &now))
                })
            })
            .flatten();
        if let Some(past) = past {
            return past;
        }
        let scans = state.with_sim(|s| s.scan_count()).unwrap_or(0);
        let before = state.marking_before_last.get_value();
        let last = compiled.with(|c| match (c, before) {
            (Some(c), Some((at, before))) if at + 1 == scans => {
                live::fired(&c.net.pre, &c.net.post, &before, &now)
            }
            _ => Vec::new(),
        });
        if last.iter().any(|&f| f) {
            held_fired.set_value(Some((now, last.clone())));
            return last;
        }
        let running = state.run_mode.get() == RunMode::Running;
        match held_fired.get_value() {
            Some((at, f)) if running && at == now => f,
            _ => last,
        }
    });
    let editor = NetEditor::new(state, &name);
    let ctx = NetCtx {
        state,
        name: StoredValue::new(name.clone()),
        tokens,
        fired,
        enabled,
        runs,
        editor,
        play,
        pt,
        flying: RwSignal::new(None),
    };
    // Each firing animates its tokens; a firing that comes while the last animation still
    // runs (the simulator is faster than the eye) is shown without one.
    let flying = ctx.flying;
    let last_run = StoredValue::new((0u64, f64::NEG_INFINITY));
    Effect::new(move |_| {
        let now_fired = fired.get();
        if !now_fired.iter().any(|&f| f) {
            return;
        }
        let (run, started) = last_run.get_value();
        let now = js_sys::Date::now();
        if now - started < FLY_MS as f64 {
            return;
        }
        let run = run + 1;
        last_run.set_value((run, now));
        flying.set(Some((run, now_fired)));
        set_timeout(
            move || {
                if flying.with_untracked(|f| f.as_ref().is_some_and(|(r, _)| *r == run)) {
                    flying.set(None);
                }
            },
            std::time::Duration::from_millis(FLY_MS + 60),
        );
    });
    // An edit ends what was being played (its path may no longer exist).
    Effect::new(move |previous: Option<u64>| {
        let now = editor.version.get();
        if previous.is_some_and(|p| p != now) {
            play.set(None);
        }
        now
    });
    // Where each element is drawn: its position, or where a drag holds it now.
    let moving = Memo::new(move |_| editor.moving());
    let net_layout = Memo::new(move |_| {
        let mut lay = pou.with(|p| p.as_ref().map(|p| layout(&p.net)).unwrap_or_default());
        if let Some((id, at)) = moving.get() {
            pou.with(|p| {
                let Some(p) = p.as_ref() else { return };
                if let Some(i) = p.net.places.iter().position(|q| q.id == id) {
                    lay.places[i] = at;
                } else if let Some(j) = p.net.transitions.iter().position(|t| t.id == id) {
                    lay.transitions[j] = at;
                }
            });
        }
        lay
    });
    // Drags follow the pointer anywhere in the window.
    let moves = window_event_listener(leptos::ev::pointermove, move |ev| {
        if let Some(zoom) = editor.pinch.moved(&ev, editor.zoom.get_untracked()) {
            editor.set_zoom(zoom);
        } else if editor.drag.with_untracked(Option::is_some) {
            editor.pointer_move(f64::from(ev.client_x()), f64::from(ev.client_y()));
        }
    });
    let ups = window_event_listener(leptos::ev::pointerup, move |ev| {
        editor.pinch.up(&ev);
        editor.release(f64::from(ev.client_x()), f64::from(ev.client_y()));
    });
    let cancels = window_event_listener(leptos::ev::pointercancel, move |ev| {
        editor.pinch.up(&ev);
        editor.drag.set(None)
    });
    on_cleanup(move || {
        moves.remove();
        ups.remove();
        cancels.remove();
    });

    // A clicked problem or a fault: bring the element into view.
    let this = name.clone();
    Effect::new(move |_| {
        for site in [state.focus.get(), state.fault_site.get()].into_iter().flatten() {
            if let Site::Petri { pou, element: Some(e), .. } = site {
                if pou.eq_ignore_ascii_case(&this) {
                    match e {
                        NetElement::Place(id) | NetElement::Transition(id) => {
                            scroll_to(&editor.element_dom_id(&id))
                        }
                        _ => {}
                    }
                }
            }
        }
    });

    let drawing = move || {
        state.diagnostics.track();
        let Some(p) = pou.get() else {
            return view! { <p class="muted">{t(K::petri_net_gone)}</p> }.into_any();
        };
        compiled.with(|c| net_layout.with(|l| net_svg(ctx, &p, c.as_ref(), l).into_any()))
    };
    let status = move || {
        if play.with(Option::is_some) {
            return None;
        }
        if runs.get() {
            return None;
        }
        Some(match (state.running.get(), compiled.with(Option::is_some)) {
            (_, false) => t(K::petri_status_errors).to_string(),
            (Some(r), true) => {
                tf(K::petri_status_other, &[("program", &r), ("name", &ctx.name.get_value())])
            }
            (None, true) => t(K::petri_status_idle).to_string(),
        })
    };
    let layout_note = move || {
        net_layout.with(|l| l.automatic).then(|| view! {
        <span class="muted small-text" title=t(K::petri_laid_out_title)>{t(K::petri_laid_out)}</span>
    })
    };
    // Why no code can be generated, naming the element (the net's errors).
    let no_code = Memo::new(move |_| {
        if compiled.with(Option::is_some) {
            return None;
        }
        pou.with(|p| {
            let p = p.as_ref()?;
            let errors = compile(p).err()?;
            let reasons: Vec<String> = errors
                .iter()
                .filter(|d| d.is_error())
                .map(|d| {
                    let place = plc_core::petri::describe(&p.name, &d.element, d.at.as_ref());
                    format!(
                        "{}: {} [{}]",
                        place.strip_prefix("POU ").unwrap_or(&place),
                        crate::i18n::message_text(&d.msg, None, &d.message),
                        d.code
                    )
                })
                .collect();
            (!reasons.is_empty()).then_some(reasons)
        })
    });
    let code = Signal::derive(move || {
        compiled.with(|c| c.as_ref().map(|c| c.generated.st.clone()).unwrap_or_default())
    });
    let key = name.clone();
    let active = Signal::derive(move || {
        state.active_generated.with(|l| {
            l.iter().filter(|(p, _)| p.eq_ignore_ascii_case(&key)).map(|(_, line)| *line).collect()
        })
    });
    // The selected element's lines in the code (a place: its whole CASE branch; a
    // transition: its guard test), and a click on a line selects the element behind it.
    let marked = Signal::derive(move || {
        let Some(Selection::Element(id)) = editor.selected.get() else { return Vec::new() };
        compiled.with(|c| {
            let Some(c) = c.as_ref() else { return Vec::new() };
            let is_it = |e: &NetElement| match e {
                NetElement::Place(p) | NetElement::Transition(p) => *p == id,
                _ => false,
            };
            let lines: Vec<u32> = c
                .generated
                .lines
                .iter()
                .enumerate()
                .filter(|(_, src)| src.as_ref().is_some_and(|s| is_it(&s.element)))
                .map(|(i, _)| i as u32 + 1)
                .collect();
            let mut ranges: Vec<(u32, u32)> = Vec::new();
            for l in lines {
                match ranges.last_mut() {
                    Some(r) if r.1 + 1 == l => r.1 = l,
                    _ => ranges.push((l, l)),
                }
            }
            let is_place = c.generated.place_map.places.iter().any(|p| p.id == id);
            if let (true, Some(&(first, _))) = (is_place, ranges.first()) {
                let branch = code::branch_lines(&c.generated.st, first);
                ranges.retain(|r| r.1 < branch.0 || r.0 > branch.1);
                ranges.push(branch);
            }
            ranges
        })
    });
    let on_line = Callback::new(move |line: u32| {
        let element = compiled.with_untracked(|c| {
            c.as_ref()?.generated.lines.get(line as usize - 1)?.as_ref().map(|s| s.element.clone())
        });
        if let Some(NetElement::Place(id) | NetElement::Transition(id)) = element {
            editor.selected.set(Some(Selection::Element(id)));
            editor.focus_selected();
        }
    });
    view! {
        <section class="panel petri-view" aria-label=tf(K::petri_net_label, &[("name", &name)])>
            <div class="ed-toolbar">
                <h2>{t(K::petri_net)}</h2>
                <span class="pou-title">{name.clone()}</span>
                {layout_note}
                <span class="ed-spacer"></span>
                <PouActions kind=DiagramKind::Petri name=name.clone()/>
            </div>
            <NetToolbar editor=editor pou=pou/>
            <PlayControls play=play net=pt/>
            <props::NetDeclarations editor=editor pou=pou/>
            <div class="ed-toolbar">
                <span class="ed-spacer"></span>
                <span class="pn-legend small-text" aria-hidden="true">
                    <span class="lg lg-token"></span>{t(K::petri_legend_token)}" "
                    <span class="lg lg-fired"></span>{t(K::petri_legend_fired)}" "
                    <span class="lg lg-enabled"></span>{t(K::petri_legend_enabled)}
                </span>
            </div>
            {move || status().map(|s| view! { <p class="view-note">{s}</p> })}
            <div class="pn-body">
                <div class="pn-net" tabindex="-1"
                    on:wheel=move |ev: leptos::ev::WheelEvent| {
                        ev.prevent_default();
                        let f = if ev.delta_y() > 0.0 { 0.8 } else { 1.25 };
                        editor.set_zoom(editor.zoom.get_untracked() * f);
                    }
                    on:keydown=move |ev: leptos::ev::KeyboardEvent| {
                    // Keys the elements did not take (Escape, undo) on the canvas.
                    if !ev.default_prevented() && editor.key(&ev.key(), ev.ctrl_key() || ev.meta_key(), ev.shift_key()) {
                        ev.prevent_default();
                    }
                }>{drawing}</div>
                <div class="pn-code">
                    <h3>{t(K::petri_generated_code)}</h3>
                    {move || no_code.get().map(|reasons| view! {
                        <div class="pn-no-code" role="status">
                            <p>{t(K::petri_no_code)}</p>
                            <ul>{reasons.into_iter().map(|r| view! { <li>{r}</li> }).collect_view()}</ul>
                        </div>
                    })}
                    <CodePanel code=code active=active marked=marked on_line=on_line/>
                </div>
            </div>
            <Properties editor=editor pou=pou/>
            <ElementDetails pou=pou name=ctx.name/>
            <AnalysisPanel pou=pou play=play/>
        </section>
    }
}

/// The canvas toolbar: the tools (toggle buttons), undo and redo, zoom.
#[component]
fn NetToolbar(editor: NetEditor, pou: Memo<Option<PetriPou>>) -> impl IntoView {
    let state = expect_context::<AppState>();
    let export_pnml = move |_| {
        let Some(name) = pou.with_untracked(|p| p.as_ref().map(|p| p.name.clone())) else { return };
        let project = state.project.get_untracked();
        leptos::task::spawn_local(async move {
            match crate::import::pnml(&project, &name).await {
                Ok(xml) => {
                    if let Err(e) =
                        crate::download::download(&format!("{name}.pnml"), "application/xml", &xml)
                    {
                        state.error(e);
                    }
                }
                Err(e) => state.error(tf(K::petri_export_failed, &[("error", &e.to_string())])),
            }
        });
    };
    let export_svg = move |_| {
        let Some(name) = pou.with_untracked(|p| p.as_ref().map(|p| p.name.clone())) else { return };
        match canvas_svg(&editor.canvas_id()) {
            Some(text) => {
                if let Err(e) =
                    crate::download::download(&format!("{name}.svg"), "image/svg+xml", &text)
                {
                    state.error(e);
                }
            }
            None => state.error(t(K::petri_export_not_drawn)),
        }
    };
    let zoom_by = move |f: f64| editor.set_zoom(editor.zoom.get_untracked() * f);
    let fit = move |_| {
        let Some(svg) = crate::dom::by_id::<web_sys::Element>(&editor.canvas_id()) else { return };
        let Some(holder) = svg.closest(".pn-net").ok().flatten() else { return };
        let vb: Vec<f64> = svg
            .get_attribute("viewBox")
            .unwrap_or_default()
            .split_whitespace()
            .filter_map(|v| v.parse().ok())
            .collect();
        if let [_, _, w, h] = vb[..] {
            let fit = (f64::from(holder.client_width()) / w)
                .min(f64::from(holder.client_height().max(200)) / h);
            editor.set_zoom(fit);
        }
    };
    view! {
        <div class="pn-toolbar" role="toolbar" aria-label=t(K::petri_net_tools)>
            {NetTool::all().into_iter().map(|(tool, label)| view! {
                <button class="pn-tool" aria-pressed=move || if editor.tool.get() == tool { "true" } else { "false" }
                    on:click=move |_| editor.choose(tool)>{t(label)}</button>
            }).collect_view()}
            <span class="pn-sep"></span>
            <button on:click=move |_| editor.undo() disabled=move || !editor.can_undo()
                title=t(K::petri_undo_title)>{t(K::petri_undo)}</button>
            <button on:click=move |_| editor.redo() disabled=move || !editor.can_redo()
                title=t(K::petri_redo_title)>{t(K::petri_redo)}</button>
            <span class="pn-sep"></span>
            <button on:click=move |_| zoom_by(1.25)>{t(K::petri_zoom_in)}</button>
            <button on:click=move |_| zoom_by(0.8)>{t(K::petri_zoom_out)}</button>
            <button on:click=fit>{t(K::petri_fit)}</button>
            <span class="pn-sep"></span>
            <button on:click=export_pnml title=t(K::petri_export_pnml_title)>{t(K::petri_export_pnml)}</button>
            <button on:click=export_svg title=t(K::petri_export_svg_title)>{t(K::petri_export_svg)}</button>
        </div>
        // One line whatever it says, so the canvas never moves under a gesture.
        <p class="pn-hint muted small-text" role="status">{move || match (editor.tool.get(), editor.arc_from.get()) {
            (NetTool::Arc, Some(from)) => tf(K::petri_hint_arc_from, &[("from", &from)]),
            (NetTool::Arc, None) => t(K::petri_hint_arc).to_string(),
            (NetTool::Place, _) => t(K::petri_hint_place).to_string(),
            (NetTool::Transition, _) => t(K::petri_hint_transition).to_string(),
            (NetTool::Select, _) => t(K::petri_hint_select).to_string(),
        }}</p>
    }
}

/// The drawn net as a standalone SVG file: its markup with the page's net styles inside
/// (the drawing is styled by class), without the page's interaction attributes.
fn canvas_svg(id: &str) -> Option<String> {
    use wasm_bindgen::JsCast;
    let document = web_sys::window()?.document()?;
    let svg = document.get_element_by_id(id)?.clone_node_with_deep(true).ok()?;
    let svg: web_sys::Element = svg.dyn_into().ok()?;
    for attr in ["id", "tabindex", "style", "role"] {
        let _ = svg.remove_attribute(attr);
    }
    let _ = svg.set_attribute("xmlns", "http://www.w3.org/2000/svg");
    let mut css = String::new();
    let sheets = js_sys::Reflect::get(&document, &"styleSheets".into()).ok()?;
    for sheet in js_sys::try_iter(&sheets).ok()??.flatten() {
        // A sheet from another origin cannot be read: skipped.
        let Ok(rules) = js_sys::Reflect::get(&sheet, &"cssRules".into()) else { continue };
        let Ok(Some(rules)) = js_sys::try_iter(&rules) else { continue };
        for rule in rules.flatten() {
            let text = js_sys::Reflect::get(&rule, &"cssText".into())
                .ok()
                .and_then(|t| t.as_string())
                .unwrap_or_default();
            if text.contains(".pn-") && !text.contains(":focus") {
                css.push_str(&text);
                css.push('\n');
            }
        }
    }
    let style = document.create_element_ns(Some("http://www.w3.org/2000/svg"), "style").ok()?;
    style.set_text_content(Some(&format!(
        "text {{ font-family: monospace; font-size: 12px; }}\n{css}"
    )));
    let _ = svg.insert_before(&style, svg.first_child().as_ref());
    Some(format!("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n{}", svg.outer_html()))
}
