//! The ladder view: a ladder POU's rungs drawn in SVG by hand (read-only until the ladder
//! editor exists), live while its PROGRAM runs — power flow from the hidden `LdPow_*`
//! variables, contact and coil states, block values — or as the POU's readable ST view.

mod draw;
pub mod geometry;
mod live;

use leptos::prelude::*;
use plc_core::build::Site;
use plc_core::ladder::{st_view_pou, LadderPou, LadderPouKind};

use crate::components::editor::text::highlight_html;
use crate::state::AppState;
use draw::{rung_svg, RungCtx};
use geometry::NodePower;
use live::{LadderLive, Probes};

/// Scrolls the element with `id` into view.
pub(crate) fn scroll_to(id: &str) {
    let el = web_sys::window().and_then(|w| w.document()).and_then(|d| d.get_element_by_id(id));
    if let Some(el) = el {
        el.scroll_into_view_with_bool(false);
    }
}

/// What the header says about live values.
fn live_status(state: AppState, pou: &LadderPou) -> Option<String> {
    if pou.kind == LadderPouKind::FunctionBlock {
        return Some(
            "A function block runs inside its instances: shown without live values.".into(),
        );
    }
    match state.running.get() {
        Some(r) if r.eq_ignore_ascii_case(&pou.name) => None,
        Some(r) => Some(format!(
            "The simulator runs PROGRAM {r}: choose {} under Simulation to see this one live.",
            pou.name
        )),
        None => Some("Not running: the project has errors or no PROGRAM.".into()),
    }
}

/// One rung: its number, label and comment above its drawing.
#[component]
fn RungView(
    rung: plc_core::ladder::Rung,
    index: usize,
    pou: String,
    live: Memo<Option<LadderLive>>,
) -> impl IntoView {
    let state = expect_context::<AppState>();
    let shared = StoredValue::new(rung.clone());
    let nodes = Memo::new(move |_| {
        live.with(|l| {
            l.as_ref().map(|l| {
                shared.with_value(|r| NodePower::new(r, |row, col| l.powered(index, row, col)))
            })
        })
    });
    let ctx = RungCtx { state, live, nodes, rung: index };
    view! {
        <div class="ld-rung" id=format!("ld-rung-{index}")>
            <div class="ld-rung-head">
                <span class="ld-rung-no">{index + 1}</span>
                {rung.label.clone().filter(|l| !l.trim().is_empty()).map(|l| view! {
                    <span class="ld-label">{format!("{l}:")}</span>
                })}
                <span class="ld-comment">{rung.comment.clone()}</span>
            </div>
            <div class="ld-scroll">{rung_svg(ctx, &rung, &pou)}</div>
        </div>
    }
}

/// The view of ladder POU `name`.
#[component]
pub fn LadderView(name: String) -> impl IntoView {
    let state = expect_context::<AppState>();
    let key = name.clone();
    let pou = Memo::new(move |_| {
        state.project.with(|p| p.ladder.iter().find(|l| l.name == key).cloned())
    });
    let probes = Memo::new(move |_| pou.with(|p| p.as_ref().map(Probes::of)));
    let live = Memo::new(move |_| {
        let running = state.running.get();
        let runs = pou.with(|p| {
            p.as_ref().is_some_and(|p| {
                p.kind == LadderPouKind::Program
                    && running.as_deref().is_some_and(|r| r.eq_ignore_ascii_case(&p.name))
            })
        });
        if !runs {
            return None;
        }
        probes.with(|pr| pr.as_ref().and_then(|pr| state.with_sim(|s| LadderLive::read(s, pr))))
    });
    let show_st = RwSignal::new(false);

    // A clicked problem or a fault: scroll its rung into view.
    let this = name.clone();
    Effect::new(move |_| {
        for site in [state.focus.get(), state.fault_site.get()].into_iter().flatten() {
            if let Site::Ladder { pou, cell: Some((r, ..)) } = site {
                if pou.eq_ignore_ascii_case(&this) {
                    show_st.set(false);
                    scroll_to(&format!("ld-rung-{r}"));
                }
            }
        }
    });

    let body = move || {
        let Some(p) = pou.get() else {
            return view! { <p class="muted">"This ladder POU is no longer in the project."</p> }
                .into_any();
        };
        if show_st.get() {
            let html = highlight_html(&st_view_pou(&p), &[]);
            return view! {
                <pre class="code-view" aria-label=format!("{} as Structured Text", p.name)>
                    <code inner_html=html></code>
                </pre>
            }
            .into_any();
        }
        state.diagnostics.track();
        let pou_name = p.name.clone();
        p.rungs
            .into_iter()
            .enumerate()
            .map(|(index, rung)| {
                view! { <RungView rung=rung index=index pou=pou_name.clone() live=live/> }
            })
            .collect_view()
            .into_any()
    };
    let status = move || pou.with(|p| p.as_ref().and_then(|p| live_status(state, p)));
    view! {
        <section class="panel ladder-view" aria-label=format!("Ladder diagram {name}")>
            <div class="ed-toolbar">
                <h2>"Ladder"</h2>
                <span class="pou-title">{name.clone()}</span>
                <span class="muted small-text">{move || pou.with(|p| match p.as_ref().map(|p| p.kind) {
                    Some(LadderPouKind::FunctionBlock) => "FUNCTION_BLOCK",
                    _ => "PROGRAM",
                })}</span>
                <span class="ed-spacer"></span>
                <button aria-pressed=move || if show_st.get() { "true" } else { "false" }
                    title="Show the POU as readable Structured Text"
                    on:click=move |_| show_st.update(|s| *s = !*s)>"ST view"</button>
            </div>
            {move || status().map(|s| view! { <p class="view-note">{s}</p> })}
            <div class="ld-rungs">{body}</div>
        </section>
    }
}
