//! The editor pane: the POU navigator (the ST source, then each ladder POU, SFC chart,
//! network POU and Petri net POU), the selected POU's view, and the project's problem list.
//!
//! The ST editor stays mounted while another POU is shown (hidden), so its undo history
//! and caret survive switching; ladder and net views are built when selected.

use leptos::prelude::*;
use plc_core::ladder::LadderPouKind;

use crate::components::editor::Editor;
use crate::components::problems::Problems;
use crate::lazy::{self, lazy_view};
use crate::state::{AppState, PouView};

/// One entry of the navigator.
#[derive(Debug, Clone, PartialEq)]
struct NavItem {
    view: PouView,
    /// Short language badge: ST, LD, PN.
    badge: &'static str,
    /// What the entry is called.
    name: String,
    /// Its accessible name ("Ladder diagram Latch").
    label: String,
    /// Errors reported in it.
    errors: usize,
}

fn nav_items(state: AppState) -> Vec<NavItem> {
    let errors_in = |pou: Option<&str>| {
        state.diagnostics.with(|ds| {
            ds.iter()
                .filter(|d| d.error)
                .filter(|d| match pou {
                    Some(p) => d.site.pou().is_some_and(|s| s.eq_ignore_ascii_case(p)),
                    None => d.st().is_some(),
                })
                .count()
        })
    };
    state.project.with(|p| {
        let mut items = vec![NavItem {
            view: PouView::St,
            badge: "ST",
            name: "ST source".into(),
            label: "Structured Text source".into(),
            errors: errors_in(None),
        }];
        items.extend(p.ladder.iter().map(|l| NavItem {
            view: PouView::Ladder(l.name.clone()),
            badge: "LD",
            name: l.name.clone(),
            label: format!("Ladder diagram {}", l.name),
            errors: errors_in(Some(&l.name)),
        }));
        items.extend(state.sfc_charts.get().into_iter().map(|name| NavItem {
            view: PouView::Sfc(name.clone()),
            badge: "SFC",
            label: format!("SFC chart {name}"),
            errors: 0,
            name,
        }));
        items.extend(p.networks.iter().map(|n| {
            let badge = n.language.name();
            NavItem {
                view: PouView::Network(n.name.clone()),
                badge,
                name: n.name.clone(),
                label: format!("{badge} network {}", n.name),
                errors: errors_in(Some(&n.name)),
            }
        }));
        items.extend(p.petri.iter().map(|n| NavItem {
            view: PouView::Petri(n.name.clone()),
            badge: "PN",
            name: n.name.clone(),
            label: format!("Petri net {}", n.name),
            errors: errors_in(Some(&n.name)),
        }));
        items
    })
}

/// The POU navigator.
#[component]
fn Navigator() -> impl IntoView {
    let state = expect_context::<AppState>();
    let items = Memo::new(move |_| nav_items(state));
    move || {
        let running = state.running.get();
        view! {
            <nav class="pou-nav" aria-label="POUs">
                {items.get().into_iter().map(|item| {
                    let target = item.view.clone();
                    let selected = {
                        let v = item.view.clone();
                        move || state.view.get() == v
                    };
                    let runs = running.as_deref().is_some_and(|r| r.eq_ignore_ascii_case(&item.name))
                        && item.view != PouView::St;
                    let title = if runs { "This PROGRAM runs in the simulator" } else { "" };
                    view! {
                        <button class="pou-tab" aria-label=item.label.clone() title=title
                            aria-pressed=move || if selected() { "true" } else { "false" }
                            on:click=move |_| state.view.set(target.clone())>
                            <span class=format!("pou-badge pou-badge-{}", item.badge.to_ascii_lowercase())>{item.badge}</span>
                            <span>{item.name.clone()}</span>
                            {runs.then(|| view! { <span class="pou-running" aria-hidden="true">"▶"</span> })}
                            {(item.errors > 0).then(|| view! {
                                <span class="pou-errors" aria-hidden="true">{item.errors}</span>
                            })}
                        </button>
                    }
                }).collect_view()}
                <NewPou petri=false/>
                <NewPou petri=true/>
            </nav>
        }
    }
}

/// `New ladder POU` (name, kind, Create) or `New Petri net POU` (name, Create): a small
/// dialog that adds an empty POU to the project and shows it.
#[component]
fn NewPou(petri: bool) -> impl IntoView {
    let state = expect_context::<AppState>();
    let title = if petri { "New Petri net POU" } else { "New ladder POU" };
    let open = RwSignal::new(false);
    let name = RwSignal::new(String::new());
    let kind = RwSignal::new(LadderPouKind::Program);
    let problem = RwSignal::new(None::<String>);
    // The editor and the pass that builds the new POU come while the user names it; Create
    // waits for them, so the new POU is built (and its PROGRAM runs) before it is shown.
    let preload = move || {
        leptos::task::spawn_local(async move {
            let _ = crate::lazy::preload_editor(petri).await;
        });
    };
    let create_now = move || {
        let text = name.get_untracked().trim().to_string();
        let mut project = state.project.get_untracked();
        let program = petri || kind.get_untracked() == LadderPouKind::Program;
        let added = if petri {
            project.add_petri_pou(&text)
        } else {
            project.add_ladder_pou(&text, kind.get_untracked())
        };
        match added {
            Ok(()) => {
                if program
                    && project.settings.program.is_none()
                    && state.running.get_untracked().is_none()
                {
                    project.settings.program = Some(text.clone());
                }
                state.project.set(project);
                state.save();
                state.check_now();
                state.view.set(if petri { PouView::Petri(text) } else { PouView::Ladder(text) });
                open.set(false);
                name.set(String::new());
                problem.set(None);
            }
            Err(e) => problem.set(Some(e.to_string())),
        }
    };
    let create = move || {
        leptos::task::spawn_local(async move {
            let _ = crate::lazy::preload_editor(petri).await;
            create_now();
        });
    };
    view! {
        <button class="pou-tab pou-new" on:click=move |_| {
                open.update(|o| *o = !*o);
                problem.set(None);
                if open.get_untracked() {
                    preload();
                }
            }
            aria-expanded=move || if open.get() { "true" } else { "false" }>{title}</button>
        {move || open.get().then(|| view! {
            <div class="pou-dialog" role="dialog" aria-label=title>
                <label class="field">
                    <span>"POU name"</span>
                    <input type="text" aria-label="POU name" prop:value=move || name.get()
                        spellcheck="false" autofocus
                        on:input=move |ev| name.set(event_target_value(&ev))
                        on:keydown=move |ev: leptos::ev::KeyboardEvent| match ev.key().as_str() {
                            "Enter" => { ev.prevent_default(); create(); }
                            "Escape" => open.set(false),
                            _ => {}
                        }/>
                </label>
                {(!petri).then(|| view! {
                    <label class="field">
                        <span>"POU kind"</span>
                        <select aria-label="POU kind" on:change=move |ev| kind.set(
                            if event_target_value(&ev) == "FUNCTION_BLOCK" { LadderPouKind::FunctionBlock } else { LadderPouKind::Program })>
                            <option value="PROGRAM" selected=true>"PROGRAM"</option>
                            <option value="FUNCTION_BLOCK">"FUNCTION_BLOCK"</option>
                        </select>
                    </label>
                })}
                <button on:click=move |_| create()>"Create"</button>
                <button on:click=move |_| open.set(false)>"Cancel"</button>
                {move || problem.get().map(|p| view! { <p class="field-error" aria-live="polite">{p}</p> })}
            </div>
        })}
    }
}

/// The editor pane.
#[component]
pub fn PouPane() -> impl IntoView {
    let state = expect_context::<AppState>();
    let view = Memo::new(move |_| state.view.get());
    view! {
        <Navigator/>
        <div class="pou-st" style:display=move || if view.get() == PouView::St { "" } else { "none" }>
            <Editor/>
        </div>
        {move || match view.get() {
            PouView::St => ().into_any(),
            // Each view comes from its own chunk, fetched the first time it is shown.
            PouView::Ladder(name) => {
                lazy_view("the ladder editor", move || lazy::ladder_view(name.clone()))
            }
            PouView::Petri(name) => {
                lazy_view("the Petri net editor", move || lazy::petri_view(name.clone()))
            }
            PouView::Sfc(name) => lazy_view("the SFC chart", move || lazy::sfc_view(name.clone())),
            PouView::Network(name) => {
                lazy_view("the network view", move || lazy::network_view(name.clone()))
            }
        }}
        <Problems/>
    }
}
