//! The `New ladder POU` / `New Petri net POU` dialog: a free name filled in (after the
//! open exercise, else `Ladder1`, `Net1`), checked as it is typed with the core's messages,
//! the kind for ladder, `Create` and `Cancel`. Inside an exercise the new PROGRAM declares
//! the exercise's interface and becomes the program that runs and is graded. Loaded on
//! first use (`lazy::new_pou_dialog`).

use leptos::html;
use leptos::prelude::*;
use plc_core::exercise::interface_declarations;
use plc_core::ladder::LadderPouKind;

use crate::exercises::Exercises;
use crate::i18n::{said_text, t, tf, K};
use crate::lazy;
use crate::state::{AppState, PouView};

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

/// Opens `dialog` modal with `input` focused and selected, once the dialog is in the page
/// (waiting at most `frames` animation frames for that).
fn show_when_connected(
    dialog: web_sys::HtmlDialogElement,
    input: web_sys::HtmlInputElement,
    frames: u32,
) {
    if !dialog.is_connected() {
        if frames > 0 {
            request_animation_frame(move || show_when_connected(dialog, input, frames - 1));
        }
        return;
    }
    if !dialog.open() {
        let _ = dialog.show_modal();
    }
    let _ = input.focus();
    input.select();
}

/// The `New ladder POU` or `New Petri net POU` dialog, opened modal as it is shown: a free
/// name already filled in (checked as it is typed), the kind for ladder, `Create` and
/// `Cancel`. Inside an exercise the new POU declares the exercise's interface and, when it
/// is a PROGRAM, becomes the program that runs and is graded. Closing it sets `open` false
/// (the button's owner then drops it).
#[component]
pub fn NewPouDialog(petri: bool, open: RwSignal<bool>) -> impl IntoView {
    let state = expect_context::<AppState>();
    let exercises = use_context::<Exercises>();
    let title = t(if petri { K::pou_new_petri } else { K::pou_new_ladder });
    let dialog = NodeRef::<html::Dialog>::new();
    let input = NodeRef::<html::Input>::new();
    let exercise_id = exercises
        .and_then(|ex| ex.open.with_untracked(|o| o.as_ref().map(|o| o.opened.view.id.clone())));
    let base = name_base(exercise_id.as_deref(), petri);
    let name = RwSignal::new(state.project.with_untracked(|p| p.free_pou_name(&base)));
    let kind = RwSignal::new(LadderPouKind::Program);
    // Recomputed where shown (cheap: one name against the project's POU names).
    let problem = move || {
        name.with(|n| state.project.with(|p| p.check_pou_name(n).err()))
            .map(|e| sentence(&said_text(e.said())))
    };
    let interface = move || {
        exercises.and_then(|ex| {
            ex.open.with_untracked(|o| o.as_ref().map(|o| o.opened.view.interface.clone()))
        })
    };
    let error_id = if petri { "new-petri-error" } else { "new-ladder-error" };
    // Modal as soon as it is in the page (built while its chunk loaded, it is put into the
    // page a moment later), with the suggested name selected.
    Effect::new(move |_| {
        if let (Some(d), Some(i)) = (dialog.get(), input.get()) {
            show_when_connected(d, i, 60);
        }
    });
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
            state.error(tf(K::pou_not_created, &[("error", &said_text(e.said()))]));
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
            state.info(tf(K::pou_declares_interface, &[("name", &text)]));
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
        // Closed by Create, Cancel or Escape (the focus goes back to the button).
        <dialog class="app-dialog pou-dialog" node_ref=dialog aria-label=title
            on:close=move |_| open.set(false)>
            <h2>{title}</h2>
            <form on:submit=move |ev: leptos::ev::SubmitEvent| { ev.prevent_default(); create(); }>
                <label class="field">
                    <span>{t(K::pou_name)}</span>
                    <input type="text" node_ref=input aria-label=t(K::pou_name_label) spellcheck="false" autocomplete="off"
                        prop:value=move || name.get()
                        aria-invalid=move || problem().is_some().to_string()
                        aria-describedby=error_id
                        on:input=move |ev| name.set(event_target_value(&ev))/>
                </label>
                <p class="field-error" id=error_id aria-live="polite">{problem}</p>
                {(!petri).then(|| view! {
                    <label class="field">
                        <span>{t(K::pou_kind)}</span>
                        <select aria-label=t(K::pou_kind_label) on:change=move |ev| kind.set(
                            if event_target_value(&ev) == "FUNCTION_BLOCK" { LadderPouKind::FunctionBlock } else { LadderPouKind::Program })>
                            <option value="PROGRAM">"PROGRAM"</option>
                            <option value="FUNCTION_BLOCK">"FUNCTION_BLOCK"</option>
                        </select>
                    </label>
                })}
                <p class="muted small-text" hidden=move || !exercises.is_some_and(|ex| ex.open.with(|o| o.as_ref().is_some_and(|o| !o.opened.view.interface.is_empty())))>
                    {t(K::pou_exercise_note)}
                </p>
                <div class="dialog-actions">
                    <button type="submit" class="primary" disabled=move || problem().is_some()>{t(K::pou_create)}</button>
                    <button type="button" on:click=move |_| close()>{t(K::pou_cancel)}</button>

                </div>
            </form>
        </dialog>
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
