//! The editor pane: the POU navigator (the ST source, then each ladder POU, SFC chart,
//! network POU and Petri net POU), the selected POU's view, and the project's problem list.
//!
//! The ST editor stays mounted while another POU is shown (hidden), so its undo history
//! and caret survive switching; ladder and net views are built when selected.

use leptos::prelude::*;

use crate::components::editor::Editor;
use crate::components::problems::Problems;
use crate::i18n::{t, tf, K};
use crate::lazy::{self, lazy_view, What};
use crate::state::{AppState, PouView};

/// One entry of the navigator.
#[derive(Debug, Clone, PartialEq)]
struct NavItem {
    view: PouView,
    /// Short language badge: ST, LD, PN.
    badge: &'static str,
    /// What the entry is called.
    name: String,
    /// What it is ("Ladder diagram Latch"), the end of its accessible name.
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
            name: t(K::pou_st_source).into(),
            label: t(K::pou_st_source_label).into(),
            errors: errors_in(None),
        }];
        items.extend(p.ladder.iter().map(|l| NavItem {
            view: PouView::Ladder(l.name.clone()),
            badge: "LD",
            name: l.name.clone(),
            label: tf(K::pou_ladder_label, &[("name", &l.name)]),
            errors: errors_in(Some(&l.name)),
        }));
        items.extend(state.sfc_charts.get().into_iter().map(|name| NavItem {
            view: PouView::Sfc(name.clone()),
            badge: "SFC",
            label: tf(K::pou_sfc_label, &[("name", &name)]),
            errors: 0,
            name,
        }));
        items.extend(p.networks.iter().map(|n| {
            let badge = n.language.name();
            NavItem {
                view: PouView::Network(n.name.clone()),
                badge,
                name: n.name.clone(),
                label: tf(K::pou_network_label, &[("language", badge), ("name", &n.name)]),
                errors: errors_in(Some(&n.name)),
            }
        }));
        items.extend(p.petri.iter().map(|n| NavItem {
            view: PouView::Petri(n.name.clone()),
            badge: "PN",
            name: n.name.clone(),
            label: tf(K::pou_petri_label, &[("name", &n.name)]),
            errors: errors_in(Some(&n.name)),
        }));
        items
    })
}

/// Which of the `one`, `few` and `many` keys says `n` of something in the language shown.
fn plural(n: usize, [one, few, many]: [K; 3]) -> K {
    crate::i18n::plural(n as u64, one, few, many)
}

/// A tab's accessible name: its visible text first (badge, name, error count; voice control
/// users say what they see), then what it is.
fn tab_name(item: &NavItem) -> String {
    let errors = match item.errors {
        0 => String::new(),
        n => {
            let key = plural(n, [K::pou_errors_one, K::pou_errors_few, K::pou_errors_many]);
            format!(" {}", tf(key, &[("n", &n.to_string())]))
        }
    };
    format!("{} {}{errors}, {}", item.badge, item.name, item.label)
}

/// The POU navigator.
#[component]
fn Navigator() -> impl IntoView {
    let state = expect_context::<AppState>();
    let items = Memo::new(move |_| nav_items(state));
    let tabs = move || {
        let running = state.running.get();
        items
            .get()
            .into_iter()
            .map(|item| {
                let target = item.view.clone();
                let selected = {
                    let v = item.view.clone();
                    move || state.view.get() == v
                };
                let runs = running.as_deref().is_some_and(|r| r.eq_ignore_ascii_case(&item.name))
                    && item.view != PouView::St;
                let title = if runs { t(K::pou_runs_title) } else { "" };
                view! {
                    <button class="pou-tab" aria-label=tab_name(&item) title=title
                        aria-pressed=move || if selected() { "true" } else { "false" }
                        on:click=move |_| state.view.set(target.clone())>
                        <span class=format!("pou-badge pou-badge-{}", item.badge.to_ascii_lowercase())>{item.badge}</span>
                        " "
                        <span>{item.name.clone()}</span>
                        {runs.then(|| view! { " " <span class="pou-running" aria-hidden="true">"▶"</span> })}
                        {(item.errors > 0).then(|| view! {
                            " " <span class="pou-errors" aria-hidden="true">{item.errors}</span>
                        })}
                    </button>
                }
            })
            .collect_view()
    };
    // The two New buttons (and their dialogs) stay mounted while the tabs change.
    view! {
        <nav class="pou-nav" aria-label=t(K::pou_nav)>
            {tabs}
            <NewPou petri=false/>
            <NewPou petri=true/>
        </nav>
    }
}

/// `New ladder POU` or `New Petri net POU`: the button, and while it is open the dialog
/// (`components::new_pou`, loaded on first use: the first screen has a size budget).
#[component]
fn NewPou(petri: bool) -> impl IntoView {
    let title = t(if petri { K::pou_new_petri } else { K::pou_new_ladder });
    let open = RwSignal::new(false);
    view! {
        <button class="pou-tab pou-new" data-kind=if petri { "petri" } else { "ladder" }
            aria-haspopup="dialog" on:click=move |_| {
                open.set(true);
                // The editor and the pass that build the new POU come while it is named.
                leptos::task::spawn_local(async move {
                    let _ = lazy::preload_editor(petri).await;
                });
            }>{title}</button>
        {move || open.get().then(|| {
            lazy_view(What::NewPouDialog, move || lazy::new_pou_dialog(petri, open))
        })}
    }
}

/// The editor pane.
#[component]
pub fn PouPane() -> impl IntoView {
    let state = expect_context::<AppState>();
    let view = Memo::new(move |_| state.view.get());
    let opening = move || {
        state.opening_shared.get()
            || state.opening_stored.with(Option::is_some)
            || state.opening_new.get() > 0
    };
    view! {
        <Navigator/>
        {move || {
            let words = if state.opening_shared.get() {
                K::state_opening_shared
            } else {
                K::state_opening_project
            };
            opening().then(|| view! { <p class="lazy-loading" role="status">{t(words)}</p> })
        }}
        <div class="pou-st" style:display=move || {
            if view.get() == PouView::St && !opening() { "" } else { "none" }
        }>
            <Editor/>
        </div>
        {move || match view.get() {
            PouView::St => ().into_any(),
            // Each view comes from its own chunk, fetched the first time it is shown.
            PouView::Ladder(name) => {
                lazy_view(What::LadderEditor, move || lazy::ladder_view(name.clone()))
            }
            PouView::Petri(name) => {
                lazy_view(What::PetriEditor, move || lazy::petri_view(name.clone()))
            }
            PouView::Sfc(name) => lazy_view(What::SfcChart, move || lazy::sfc_view(name.clone())),
            PouView::Network(name) => {
                lazy_view(What::NetworkView, move || lazy::network_view(name.clone()))
            }
        }}
        <Problems/>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tab_is_named_by_its_visible_text_first() {
        let mut item = NavItem {
            view: PouView::St,
            badge: "LD",
            name: "Latch".into(),
            label: "Ladder diagram Latch".into(),
            errors: 0,
        };
        assert_eq!(tab_name(&item), "LD Latch, Ladder diagram Latch");
        item.errors = 1;
        assert_eq!(tab_name(&item), "LD Latch 1 error, Ladder diagram Latch");
        item.errors = 3;
        assert_eq!(tab_name(&item), "LD Latch 3 errors, Ladder diagram Latch");
    }
}
