//! The editor pane: the POU navigator (the ST source, then each ladder POU, SFC chart,
//! network POU and Petri net POU), the selected POU's view, and the project's problem list.
//!
//! The ST editor stays mounted while another POU is shown (hidden), so its undo history
//! and caret survive switching; ladder and net views are built when selected.

use leptos::html;
use leptos::prelude::*;
use plc_core::exercise::interface_declarations;
use plc_core::ladder::LadderPouKind;

use crate::components::editor::Editor;
use crate::components::problems::Problems;
use crate::exercises::Exercises;
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
            })
            .collect_view()
    };
    // The two New buttons (and their dialogs) stay mounted while the tabs change.
    view! {
        <nav class="pou-nav" aria-label="POUs">
            {tabs}
            <NewPou petri=false/>
            <NewPou petri=true/>
        </nav>
    }
}

/// Where a suggested POU name starts: in an exercise its id in CamelCase (`latch` →
/// `Latch`, `garage-door` → `GarageDoor`; a language tag such as `ld` is left out), else
/// `Ladder` or `Net`. [`Project::free_pou_name`] adds the first free number.
fn name_base(exercise: Option<&str>, petri: bool) -> String {
    const TAGS: [&str; 6] = ["ld", "st", "il", "sfc", "petri", "fb"];
    let from_exercise: String = exercise
        .unwrap_or_default()
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty() && !TAGS.contains(&w.to_ascii_lowercase().as_str()))
        .map(|w| {
            let mut chars = w.chars();
            chars
                .next()
                .map(|c| c.to_ascii_uppercase().to_string() + chars.as_str())
                .unwrap_or_default()
        })
        .collect();
    if from_exercise.starts_with(|c: char| c.is_ascii_alphabetic()) {
        from_exercise
    } else if petri {
        "Net".to_string()
    } else {
        "Ladder".to_string()
    }
}

/// A core message as a sentence under a field (`Type a name for the POU.`).
fn sentence(message: &str) -> String {
    let mut chars = message.chars();
    let first = chars.next().map(|c| c.to_ascii_uppercase()).map(String::from).unwrap_or_default();
    format!("{first}{}.", chars.as_str())
}

/// `New ladder POU` or `New Petri net POU`: a dialog with a free name already filled in
/// (checked as it is typed), the kind for ladder, `Create` and `Cancel`. Inside an
/// exercise the new POU declares the exercise's interface and, when it is a PROGRAM,
/// becomes the program that runs and is graded.
#[component]
fn NewPou(petri: bool) -> impl IntoView {
    let state = expect_context::<AppState>();
    let exercises = use_context::<Exercises>();
    let title = if petri { "New Petri net POU" } else { "New ladder POU" };
    let dialog = NodeRef::<html::Dialog>::new();
    let input = NodeRef::<html::Input>::new();
    let name = RwSignal::new(String::new());
    let kind = RwSignal::new(LadderPouKind::Program);
    // Recomputed where shown (cheap: one name against the project's POU names).
    let problem = move || {
        name.with(|n| state.project.with(|p| p.check_pou_name(n).err()))
            .map(|e| sentence(&e.to_string()))
    };
    let interface = move || {
        exercises.and_then(|ex| {
            ex.open.with_untracked(|o| o.as_ref().map(|o| o.opened.view.interface.clone()))
        })
    };
    let exercise_id = move || {
        exercises
            .and_then(|ex| ex.open.with_untracked(|o| o.as_ref().map(|o| o.opened.view.id.clone())))
    };
    let error_id = if petri { "new-petri-error" } else { "new-ladder-error" };
    let show = move |_| {
        let base = name_base(exercise_id().as_deref(), petri);
        name.set(state.project.with_untracked(|p| p.free_pou_name(&base)));
        // The editor and the pass that build the new POU come while the user names it.
        leptos::task::spawn_local(async move {
            let _ = lazy::preload_editor(petri).await;
        });
        if let Some(d) = dialog.get_untracked() {
            let _ = d.show_modal();
        }
        if let Some(i) = input.get_untracked() {
            let _ = i.focus();
            i.select();
        }
    };
    let close = move || {
        if let Some(d) = dialog.get_untracked() {
            d.close();
        }
    };
    let create_now = move || {
        let text = name.get_untracked().trim().to_string();
        let mut project = state.project.get_untracked();
        let program = petri || kind.get_untracked() == LadderPouKind::Program;
        let declared = interface().filter(|_| program).map(|i| interface_declarations(&i));
        let added = match (petri, &declared) {
            (true, Some(d)) => project.add_petri_pou_with(&text, d),
            (true, None) => project.add_petri_pou(&text),
            (false, Some(d)) => project.add_ladder_pou_with(
                &text,
                LadderPouKind::Program,
                &format!("{d}VAR\nEND_VAR\n"),
            ),
            (false, None) => project.add_ladder_pou(&text, kind.get_untracked()),
        };
        if let Err(e) = added {
            // Checked as typed; the project may have changed meanwhile.
            state.error(format!("Not created: {e}."));
            return;
        }
        let in_exercise = declared.is_some();
        if program
            && (in_exercise
                || (project.settings.program.is_none() && state.running.get_untracked().is_none()))
        {
            project.settings.program = Some(text.clone());
        }
        state.project.set(project);
        state.save();
        state.check_now();
        state.view.set(if petri {
            PouView::Petri(text.clone())
        } else {
            PouView::Ladder(text.clone())
        });
        close();
        if in_exercise {
            state.info(format!(
                "{text} declares the exercise's interface and is now the program that runs and that Check grades (Program under Simulation chooses another)."
            ));
        }
    };
    // Create waits for the editor and its pass, so the new POU is built (and its PROGRAM
    // runs) before it is shown.
    let create = move || {
        if untrack(problem).is_some() {
            return;
        }
        leptos::task::spawn_local(async move {
            let _ = lazy::preload_editor(petri).await;
            create_now();
        });
    };
    view! {
        <button class="pou-tab pou-new" data-kind=if petri { "petri" } else { "ladder" }
            aria-haspopup="dialog" on:click=show>{title}</button>
        <dialog class="app-dialog pou-dialog" node_ref=dialog aria-label=title>
            <h2>{title}</h2>
            <form on:submit=move |ev: leptos::ev::SubmitEvent| { ev.prevent_default(); create(); }>
                <label class="field">
                    <span>"Name"</span>
                    <input type="text" node_ref=input aria-label="POU name" spellcheck="false" autocomplete="off"
                        prop:value=move || name.get()
                        aria-invalid=move || problem().is_some().to_string()
                        aria-describedby=error_id
                        on:input=move |ev| name.set(event_target_value(&ev))/>
                </label>
                <p class="field-error" id=error_id aria-live="polite">{problem}</p>
                {(!petri).then(|| view! {
                    <label class="field">
                        <span>"Kind"</span>
                        <select aria-label="POU kind" on:change=move |ev| kind.set(
                            if event_target_value(&ev) == "FUNCTION_BLOCK" { LadderPouKind::FunctionBlock } else { LadderPouKind::Program })>
                            <option value="PROGRAM">"PROGRAM"</option>
                            <option value="FUNCTION_BLOCK">"FUNCTION_BLOCK"</option>
                        </select>
                    </label>
                })}
                <p class="muted small-text" hidden=move || !exercises.is_some_and(|ex| ex.open.with(|o| o.as_ref().is_some_and(|o| !o.opened.view.interface.is_empty())))>
                    "A PROGRAM made here declares the exercise's interface and becomes the program that is checked."
                </p>
                <div class="dialog-actions">
                    <button type="submit" class="primary" disabled=move || problem().is_some()>"Create"</button>
                    <button type="button" on:click=move |_| close()>"Cancel"</button>
                </div>
            </form>
        </dialog>
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_suggested_name_comes_from_the_exercise() {
        assert_eq!(name_base(None, false), "Ladder");
        assert_eq!(name_base(None, true), "Net");
        assert_eq!(name_base(Some("latch"), false), "Latch");
        assert_eq!(name_base(Some("garage-door"), true), "GarageDoor");
        assert_eq!(name_base(Some("counter-reset-ld"), false), "CounterReset");
        assert_eq!(name_base(Some("2-hand"), false), "Ladder", "a name cannot start with a digit");
        let p = plc_core::project::Project::new("p");
        assert_eq!(p.free_pou_name(&name_base(Some("latch"), false)), "Latch1");
    }

    #[test]
    fn core_messages_read_as_sentences() {
        assert_eq!(sentence("type a name for the POU"), "Type a name for the POU.");
        assert_eq!(sentence("“1x” is not a name"), "“1x” is not a name.");
    }
}
