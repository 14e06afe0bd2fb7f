//! `Rename POU` and `Delete POU` (after confirming) in the toolbar of a diagram POU's view:
//! the project-level edits of the core (`Project::rename_ladder_pou`, …), the same for
//! ladder, Petri net and network POUs.

use leptos::prelude::*;

use crate::i18n::{said_text, t, tf, K};
use crate::state::{AppState, PouView};

/// Which kind of diagram POU the actions are for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DiagramKind {
    /// A ladder POU.
    Ladder,
    /// A Petri net POU.
    Petri,
    /// A network POU (LD, FBD or SFC kept as an imported file drew it).
    Network,
}

impl DiagramKind {
    /// The keys of the question before deleting and of the note after it.
    fn delete_keys(self) -> (K, K) {
        match self {
            DiagramKind::Ladder => (K::pou_delete_confirm_ladder, K::pou_deleted_ladder),
            DiagramKind::Petri => (K::pou_delete_confirm_petri, K::pou_deleted_petri),
            DiagramKind::Network => (K::pou_delete_confirm_network, K::pou_deleted_network),
        }
    }

    fn view(self, name: String) -> PouView {
        match self {
            DiagramKind::Ladder => PouView::Ladder(name),
            DiagramKind::Petri => PouView::Petri(name),
            DiagramKind::Network => PouView::Network(name),
        }
    }
}

/// The two buttons for the POU `name` (a view is made anew when its POU is renamed).
#[component]
pub fn PouActions(kind: DiagramKind, name: String) -> impl IntoView {
    let state = expect_context::<AppState>();
    let name = StoredValue::new(name);
    let renaming = RwSignal::new(false);
    let rename = move |text: String| {
        renaming.set(false);
        let old = name.get_value();
        let mut project = state.project.get_untracked();
        let done = match kind {
            DiagramKind::Ladder => project.rename_ladder_pou(&old, &text),
            DiagramKind::Petri => project.rename_petri_pou(&old, &text),
            DiagramKind::Network => project.rename_network_pou(&old, &text),
        };
        match done {
            Ok(()) => {
                state.project.set(project);
                state.view.set(kind.view(text.trim().to_string()));
                state.save();
                state.check_now();
            }
            Err(e) => state.error(tf(K::pou_not_renamed, &[("error", &said_text(e.said()))])),
        }
    };
    let delete = move |_| {
        let name = name.get_value();
        let ok = web_sys::window()
            .and_then(|w| {
                w.confirm_with_message(&tf(kind.delete_keys().0, &[("name", &name)])).ok()
            })
            .unwrap_or(false);
        if !ok {
            return;
        }
        let mut project = state.project.get_untracked();
        let done = match kind {
            DiagramKind::Ladder => project.delete_ladder_pou(&name),
            DiagramKind::Petri => project.delete_petri_pou(&name),
            DiagramKind::Network => project.delete_network_pou(&name),
        };
        if done.is_ok() {
            state.project.set(project);
            state.view.set(PouView::St);
            state.save();
            state.check_now();
            state.info(tf(kind.delete_keys().1, &[("name", &name)]));
        }
    };
    view! {
        {move || if renaming.get() {
            view! {
                <input type="text" aria-label=t(K::pou_new_name) autofocus
                    prop:value=name.get_value()
                    on:keydown=move |ev: leptos::ev::KeyboardEvent| match ev.key().as_str() {
                        "Enter" => { ev.prevent_default(); rename(event_target_value(&ev)); }
                        "Escape" => renaming.set(false),
                        _ => {}
                    }/>
            }.into_any()
        } else {
            view! { <button on:click=move |_| renaming.set(true)>{t(K::pou_rename)}</button> }.into_any()
        }}
        <button on:click=delete>{t(K::pou_delete)}</button>

    }
}
