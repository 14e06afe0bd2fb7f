//! The declarations of a ladder POU: the shared declarations box (a code field labelled
//! `Declarations` in a disclosure that opens when a problem in them is revealed). Typing in a row is one
//! `SetDeclarations` edit of the ladder editor (one undo step until the field is left).

use leptos::prelude::*;
use plc_core::build::Site;
use plc_core::ladder::{LadderEdit, LadderPou};

use super::editor::LadderEditor;
use crate::components::code_field::{DeclarationsBox, FieldProblem};
use crate::state::AppState;

/// The history group that joins typing in the declarations into one undo step.
const TYPING_GROUP: &str = "declarations";

/// The declarations editor of the ladder POU `pou`.
#[component]
pub fn DeclarationsEditor(
    editor: LadderEditor,
    pou: Memo<Option<LadderPou>>,
    open: RwSignal<bool>,
) -> impl IntoView {
    let state = expect_context::<AppState>();
    let name = Memo::new(move |_| pou.with(|p| p.as_ref().map(|p| p.name.clone())));
    let text = Signal::derive(move || {
        pou.with(|p| p.as_ref().map(|p| p.declarations.clone())).unwrap_or_default()
    });
    let problems = Signal::derive(move || {
        let name = name.get().unwrap_or_default();
        state.diagnostics.with(|ds| {
            ds.iter()
                .filter_map(|d| match &d.site {
                    Site::Declarations { pou, line, column } if pou.eq_ignore_ascii_case(&name) => {
                        Some((*line, *column, d.error, format!("{}  {}", d.code, d.message())))
                    }
                    _ => None,
                })
                .collect::<Vec<FieldProblem>>()
        })
    });
    // A problem in the declarations was clicked: open them and put the caret on it.
    let reveal = Signal::derive(move || match state.focus.get() {
        Some(Site::Declarations { pou, line, column })
            if name.with(|n| n.as_deref().is_some_and(|n| n.eq_ignore_ascii_case(&pou))) =>
        {
            Some((line, column))
        }
        _ => None,
    });
    let on_commit = Callback::new(move |text: String| {
        editor.apply(&LadderEdit::SetDeclarations { text }, Some(TYPING_GROUP));
    });
    let on_leave = Callback::new(move |()| editor.close_group());
    view! {
        <DeclarationsBox open=open text=text on_commit=on_commit on_leave=on_leave
            problems=problems reveal=reveal/>
    }
}
