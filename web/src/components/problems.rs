//! The problem list of the whole project: ST, ladder and Petri net diagnostics, each
//! with its place; clicking one shows that place (the ST line, the ladder cell, the net
//! element). Each problem links to its code's explanation and examples in
//! `problems.html` (generated from the code table: `plc explain --html`), a static page of
//! the site that costs nothing until it is opened.
//!
//! Quick fixes stand beside the problems they fix, each one undo step of the editor it
//! changes: `Replace with NAME` where the message ends in `did you mean NAME?` (in the ST
//! source and in a ladder POU), `Declare NAME` for a name used undeclared (in the ST
//! source, in the POU that uses it; in a ladder POU, with the type its use implies). Core
//! computes every edit (`plc_core::syntax::fix`, `plc_core::ladder`); this list only asks
//! the editor to apply it.

use leptos::prelude::*;
use plc_core::build::Site;
use plc_core::diagnostics::Span;
use plc_core::ladder::{implied_declaration, replace_name, CellRef, LadderEdit};

use crate::i18n::{t, tf, K};
use crate::state::{AppState, DiagView, PouView};

/// `n` things in words (`1 error`, `3 errors`).
fn count(n: usize, [one, few, many]: [K; 3]) -> String {
    tf(crate::i18n::plural(n as u64, one, few, many), &[("n", &n.to_string())])
}

/// A quick fix offered beside a problem.
#[derive(Clone)]
enum Fix {
    /// Put `with` in place of the ST text at `span`.
    StReplace { span: Span, name: String, with: String },
    /// Declare `name` (used undeclared at `span`) in the ST POU that uses it.
    StDeclare { span: Span, name: String, ty: String },
    /// Apply `edit` to ladder POU `pou`.
    Ladder { pou: String, name: String, with: String, edit: LadderEdit },
    /// Declare an undeclared ladder operand (E0418) in `pou`'s declarations.
    LadderDeclare { pou: String, section: &'static str, name: String, ty: String },
}

impl Fix {
    fn label(&self) -> String {
        match self {
            Fix::StReplace { with, .. } | Fix::Ladder { with, .. } => {
                tf(K::editor_replace, &[("with", with)])
            }
            Fix::StDeclare { name, .. } | Fix::LadderDeclare { name, .. } => {
                tf(K::editor_declare, &[("name", name)])
            }
        }
    }

    fn title(&self) -> String {
        match self {
            Fix::StReplace { name, with, .. } | Fix::Ladder { name, with, .. } => {
                tf(K::editor_replace_title, &[("with", with), ("name", name)])
            }
            Fix::StDeclare { name, ty, .. } | Fix::LadderDeclare { name, ty, .. } => {
                tf(K::editor_declare_title, &[("name", name), ("type", ty)])
            }
        }
    }

    /// Asks the editor concerned to apply the fix (one undo step there).
    fn apply(&self, state: AppState) {
        match self.clone() {
            Fix::StReplace { span, with, .. } => {
                let source = state.project.with_untracked(|p| p.source.clone());
                if let Some(text) = plc_core::syntax::fix::replace_span(&source, span, &with) {
                    let caret = span.start as usize + with.len();
                    state.view.set(PouView::St);
                    state.st_fix.set(Some((text, caret)));
                }
            }
            Fix::StDeclare { span, name, ty } => {
                let source = state.project.with_untracked(|p| p.source.clone());
                // A problem to fix comes from a check, which the engine did.
                let Some(engine) = crate::lazy::engine() else { return };
                match (engine.declare)(&source, span, &name, &ty) {
                    Some(text) => {
                        // The caret stays on the use, which moved down by the new line.
                        let caret = span.start as usize + (text.len() - source.len());
                        state.view.set(PouView::St);
                        state.st_fix.set(Some((text, caret)));
                    }
                    None => state.error(tf(K::editor_not_declarable, &[("name", &name)])),
                }
            }
            Fix::Ladder { pou, edit, .. } => {
                state.view.set(PouView::Ladder(pou.clone()));
                state.ladder_fix.update(|q| q.push((pou, edit)));
            }
            Fix::LadderDeclare { pou, section, name, ty } => {
                state.view.set(PouView::Ladder(pou.clone()));
                state.ladder_declare.update(|q| q.push((pou, section, name, ty)));
            }
        }
    }
}

/// The problem list with its summary.
#[component]
pub fn Problems() -> impl IntoView {
    let state = expect_context::<AppState>();
    let summary = move || {
        if !state.engine_ready.get() {
            return String::new();
        }
        state.diagnostics.with(|ds| {
            let errors = ds.iter().filter(|d| d.error).count();
            format!(
                "{}, {}",
                count(errors, [K::editor_errors_one, K::editor_errors_few, K::editor_errors_many]),
                count(
                    ds.len() - errors,
                    [K::editor_warnings_one, K::editor_warnings_few, K::editor_warnings_many]
                )
            )
        })
    };
    let list = move || {
        let ds = state.diagnostics.get();
        if !state.engine_ready.get() {
            return view! { <p class="ed-ok" role="status">{t(K::lazy_loading_checker)}</p> }
                .into_any();
        }
        if ds.is_empty() {
            return view! { <p class="ed-ok">{t(K::editor_no_problems)}</p> }.into_any();
        }
        view! {
            <ul class="ed-problems" aria-label=t(K::editor_problems)>
                {ds.into_iter().map(|d| {
                    let class = if d.error { "ed-problem ed-problem-err" } else { "ed-problem ed-problem-warn" };
                    let label = format!("{}  {}  {}", d.place_label(), d.code, d.message());
                    let site = d.site.clone();
                    let fixes = fixes(state, &d);
                    let help = format!("problems.html#{}", d.code);
                    let help_name = tf(K::editor_explain, &[("code", &d.code)]);
                    view! {
                        <li>
                            <button class=class title=t(if d.error { K::editor_error } else { K::editor_warning })
                                on:click=move |_| state.reveal(&site)>
                                {label}
                            </button>
                            {fixes.into_iter().map(|fix| {
                                let (label, title) = (fix.label(), fix.title());
                                view! {
                                    <button class="ed-problem-fix" title=title
                                        on:click=move |_| fix.apply(state)>{label}</button>
                                }
                            }).collect_view()}
                            <a class="ed-problem-help" href=help target="_blank" rel="noopener"
                                aria-label=help_name.clone() title=help_name>"?"</a>
                        </li>
                    }
                }).collect_view()}
            </ul>
        }
        .into_any()
    };
    view! {
        <section class="panel problems" aria-label=t(K::editor_problems_region)>
            <div class="panel-head">
                <h2>{t(K::editor_problems)}</h2>
                <span class="muted small-text">{summary}</span>
            </div>
            {list}
        </section>
    }
}

/// The fixes of problem `d`: `Replace with NAME` first (the likelier intent when there is
/// a close name), then `Declare NAME`.
fn fixes(state: AppState, d: &DiagView) -> Vec<Fix> {
    let mut out = Vec::new();
    match &d.site {
        Site::St { span, .. } => {
            let name = state.project.with_untracked(|p| {
                p.source.get(span.start as usize..span.end as usize).map(str::to_string)
            });
            let Some(name) = name.filter(|n| plc_core::syntax::is_identifier(n)) else {
                return out;
            };
            if let Some(with) = &d.suggestion {
                out.push(Fix::StReplace { span: *span, name: name.clone(), with: with.clone() });
            }
            // Only a name that is simply not declared (not a value two enumerations share).
            let undeclared = d.english.starts_with(&format!("`{name}` is not declared"));
            if d.code == "E0100" && undeclared && declarable_at(state, *span) {
                let ty = d.implied_type.clone().unwrap_or_else(|| "BOOL".to_string());
                out.push(Fix::StDeclare { span: *span, name, ty });
            }
        }
        Site::Ladder { pou, cell: Some((r, row, col)) } if d.code == "E0418" => {
            let at = CellRef::new(*r, *row, *col);
            let Some(name) = d.english.split('`').nth(1).map(str::to_string) else { return out };
            state.project.with_untracked(|p| {
                let Some(lp) = p.ladder.iter().find(|l| l.name.eq_ignore_ascii_case(pou)) else {
                    return;
                };
                if let Some(with) = &d.suggestion {
                    if let Some(edit) = replace_name(lp, at, &name, with) {
                        let (pou, with) = (lp.name.clone(), with.clone());
                        out.push(Fix::Ladder { pou, name: name.clone(), with, edit });
                    }
                }
                if let Some((section, ty)) = implied_declaration(lp, at, &name) {
                    out.push(Fix::LadderDeclare { pou: lp.name.clone(), section, name, ty });
                }
            });
        }
        _ => {}
    }
    out
}

/// Whether the undeclared name at `span` of the ST source is a variable of its own (not
/// `s.Motr`, not `Mode#Rnu`), which `Declare NAME` can declare.
fn declarable_at(state: AppState, span: Span) -> bool {
    state.project.with_untracked(|p| {
        let before = p.source.get(..span.start as usize).unwrap_or_default().trim_end();
        !(before.ends_with('.') || before.ends_with('#'))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_keep_their_english_words() {
        let forms = [K::editor_errors_one, K::editor_errors_few, K::editor_errors_many];
        assert_eq!(count(1, forms), "1 error");
        assert_eq!(count(3, forms), "3 errors");
        assert_eq!(count(0, forms), "0 errors");
    }
}
