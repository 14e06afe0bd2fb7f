//! The problem list of the whole project: ST, ladder and Petri net diagnostics, each
//! with its place; clicking one shows that place (the ST line, the ladder cell, the net
//! element). Each problem links to its code's explanation and examples in
//! `problems.html` (generated from the code table: `plc explain --html`), a static page of
//! the site that costs nothing until it is opened.

use leptos::prelude::*;

use crate::state::AppState;

/// "1 error" / "2 errors".
fn count(n: usize, word: &str) -> String {
    if n == 1 {
        format!("1 {word}")
    } else {
        format!("{n} {word}s")
    }
}

/// The problem list with its summary.
#[component]
pub fn Problems() -> impl IntoView {
    let state = expect_context::<AppState>();
    let summary = move || {
        state.diagnostics.with(|ds| {
            let errors = ds.iter().filter(|d| d.error).count();
            format!("{}, {}", count(errors, "error"), count(ds.len() - errors, "warning"))
        })
    };
    let list = move || {
        let ds = state.diagnostics.get();
        if ds.is_empty() {
            return view! { <p class="ed-ok">"No problems found."</p> }.into_any();
        }
        view! {
            <ul class="ed-problems" aria-label="Problems">
                {ds.into_iter().map(|d| {
                    let class = if d.error { "ed-problem ed-problem-err" } else { "ed-problem ed-problem-warn" };
                    let label = format!("{}  {}  {}", d.place_label(), d.code, d.message);
                    let site = d.site.clone();
                    let fix = declare_fix(state, &d);
                    let help = format!("problems.html#{}", d.code);
                    let help_name = format!("Explain {}", d.code);
                    view! {
                        <li>
                            <button class=class title=if d.error { "Error" } else { "Warning" }
                                on:click=move |_| state.reveal(&site)>
                                {label}
                            </button>
                            {fix.map(|(pou, section, name, ty)| {
                                let label = format!("Declare {name}");
                                view! {
                                    <button class="ed-problem-fix" on:click=move |_| {
                                        state.view.set(crate::state::PouView::Ladder(pou.clone()));
                                        state.ladder_declare.update(|q| q.push((pou.clone(), section, name.clone(), ty.clone())));
                                    }>{label}</button>
                                }
                            })}
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
        <section class="panel problems" aria-label="Problems of the project">
            <div class="panel-head">
                <h2>"Problems"</h2>
                <span class="muted small-text">{summary}</span>
            </div>
            {list}
        </section>
    }
}

/// The fix of an undeclared ladder operand (E0418): the POU, and the section, name and type
/// its use implies.
fn declare_fix(
    state: AppState,
    d: &crate::state::DiagView,
) -> Option<(String, &'static str, String, String)> {
    use plc_core::build::Site;
    use plc_core::ladder::{implied_declaration, CellRef};
    if d.code != "E0418" {
        return None;
    }
    let Site::Ladder { pou, cell: Some((r, row, col)) } = &d.site else { return None };
    let name = d.message.split('`').nth(1)?.to_string();
    state.project.with_untracked(|p| {
        let lp = p.ladder.iter().find(|l| l.name.eq_ignore_ascii_case(pou))?;
        let (section, ty) = implied_declaration(lp, CellRef::new(*r, *row, *col), &name)?;
        Some((lp.name.clone(), section, name.clone(), ty))
    })
}
