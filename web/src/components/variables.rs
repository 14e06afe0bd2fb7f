//! The live variables table (address, name, type, description, value) with expandable
//! structs, arrays and FB instances, editing, forcing, CSV export and breakpoints.

use std::collections::HashSet;

use leptos::prelude::*;
use plc_core::build::is_hidden_variable;
use plc_core::export::{children, is_expandable, value_text};
use plc_core::program::Executable;
use plc_core::semantic::Type;
use plc_core::syntax::VarSection;

use crate::download::download;
use crate::i18n::{t, tf, K};
use crate::state::AppState;

/// The accessible name of a value's `Why?` button: `Why is Motor TRUE?`.
pub fn why_label(name: &str, value: &plc_core::vm::Value) -> String {
    let value = value_text(value);
    tf(K::why_why_is, &[("name", name), ("value", &value)])
}

/// One row of the table.
#[derive(Debug, Clone, PartialEq)]
struct Row {
    path: String,
    label: String,
    depth: usize,
    address: String,
    ty: String,
    comment: String,
    expandable: bool,
    scalar: bool,
}

impl Row {
    /// A key that changes when the row's declaration does (so a recompile re-renders it).
    fn key(&self) -> String {
        format!("{}\u{1}{}\u{1}{}\u{1}{}", self.path, self.ty, self.address, self.comment)
    }
}

fn push_rows(exe: &Executable, open: &HashSet<String>, row: Row, ty: Type, out: &mut Vec<Row>) {
    let expanded = row.expandable && open.contains(&row.path.to_ascii_lowercase());
    let (path, depth) = (row.path.clone(), row.depth);
    out.push(row);
    if !expanded || out.len() > 20_000 {
        return;
    }
    for c in children(exe, &path, ty) {
        let r = Row {
            path: c.path.clone(),
            label: c.label.clone(),
            depth: depth + 1,
            address: String::new(),
            ty: exe.type_table().display(c.ty).to_string(),
            comment: c.comment.clone().unwrap_or_default(),
            expandable: is_expandable(c.ty),
            scalar: c.ty.is_scalar() || c.ty.is_string(),
        };
        push_rows(exe, open, r, c.ty, out);
    }
}

fn rows(exe: &Executable, open: &HashSet<String>) -> Vec<Row> {
    let mut out = Vec::new();
    let mut seen = HashSet::new();
    for e in exe.main_vars() {
        let v = &e.var;
        if v.section == VarSection::InOut
            || is_hidden_variable(&v.name)
            || !seen.insert(v.name.to_ascii_lowercase())
        {
            continue;
        }
        let row = Row {
            path: v.name.clone(),
            label: v.name.clone(),
            depth: 0,
            address: v.location.as_ref().map(|a| a.text.clone()).unwrap_or_default(),
            ty: exe.type_table().display(v.ty).to_string(),
            comment: v.comment.clone().unwrap_or_default(),
            expandable: is_expandable(v.ty),
            scalar: v.ty.is_scalar() || v.ty.is_string(),
        };
        push_rows(exe, open, row, v.ty, &mut out);
    }
    out
}

/// The variables table and the breakpoints.
#[component]
pub fn Variables() -> impl IntoView {
    let state = expect_context::<AppState>();
    let open = RwSignal::new(HashSet::<String>::new());
    // A configuration's program instances start expanded, each once (a row the user
    // collapses stays so across recompiles).
    let shown = StoredValue::new(HashSet::<String>::new());
    Effect::new(move |_| {
        let names: Vec<String> = state
            .with_sim(|s| {
                s.configuration()
                    .map(|c| c.instances.iter().map(|i| i.name.to_ascii_lowercase()).collect())
                    .unwrap_or_default()
            })
            .unwrap_or_default();
        let new: Vec<String> =
            names.into_iter().filter(|n| shown.with_value(|s| !s.contains(n))).collect();
        if !new.is_empty() {
            shown.update_value(|s| s.extend(new.iter().cloned()));
            open.update(|o| o.extend(new));
        }
    });
    let table = Memo::new(move |_| {
        let open = open.get();
        state.with_sim(|s| rows(s.executable(), &open)).unwrap_or_default()
    });
    let export = move |_| {
        // The writer is a chunk of the app, fetched on the first export.
        leptos::task::spawn_local(async move {
            let csv = match crate::lazy::variables_file(state).await {
                Ok(Some(csv)) => csv,
                Ok(None) => {
                    state.error(t(K::sim_no_program_to_export));
                    return;
                }
                Err(e) => {
                    state.error(tf(K::sim_export_failed, &[("error", &e.to_string())]));
                    return;
                }
            };
            if let Err(e) = download("variables.csv", "text/csv", &csv) {
                state.error(e);
            }
        });
    };
    provide_context(open);
    view! {
        <section class="panel variables" aria-label=t(K::sim_variables)>
            <div class="panel-head">
                <h2>{t(K::sim_variables)}</h2>
                <button on:click=export>{t(K::sim_export_csv)}</button>
            </div>
            <div class="table-wrap">
                <table class="var-table">
                    <thead>
                        <tr>
                            <th scope="col">{t(K::sim_address)}</th>
                            <th scope="col">{t(K::sim_name)}</th>
                            <th scope="col">{t(K::sim_type)}</th>
                            <th scope="col">{t(K::sim_description)}</th>
                            <th scope="col">{t(K::sim_value)}</th>
                            <th scope="col"><span class="sr-only">{t(K::sim_actions)}</span></th>
                        </tr>
                    </thead>
                    <tbody>
                        <For each=move || table.get() key=Row::key let:row>
                            <VarRow row=row/>
                        </For>
                    </tbody>
                </table>
            </div>
            <Breakpoints/>
        </section>
    }
}

/// One variable (or part of one).
#[component]
fn VarRow(row: Row) -> impl IntoView {
    let state = expect_context::<AppState>();
    let open = expect_context::<RwSignal<HashSet<String>>>();
    let path = StoredValue::new(row.path.clone());
    let key = row.path.to_ascii_lowercase();
    let is_open = {
        let key = key.clone();
        Memo::new(move |_| open.with(|o| o.contains(&key)))
    };
    let toggle = move |_| {
        let key = key.clone();
        open.update(|o| {
            if !o.remove(&key) {
                o.insert(key);
            }
        });
    };
    let value =
        move || path.with_value(|p| state.read(p).map(|v| value_text(&v)).unwrap_or_default());
    let forced = move || {
        path.with_value(|p| state.with_sim(|s| s.forced().any(|(f, _)| f.eq_ignore_ascii_case(p))))
            .unwrap_or(false)
    };
    let editing = RwSignal::new(false);
    let draft = RwSignal::new(String::new());
    let scalar = row.scalar;
    let start_edit = move || {
        if scalar {
            draft.set(value());
            editing.set(true);
        }
    };
    let commit = move || {
        let text = draft.get_untracked();
        // In the past, the value is written to that scan, which becomes the present.
        state.leave_past_then(move || {
            let result = path.with_value(|p| {
                state.with_sim_mut(|s| {
                    let Some(engine) = crate::lazy::engine() else { return Ok(()) };
                    if s.forced().any(|(f, _)| f.eq_ignore_ascii_case(p)) {
                        (engine.force)(s, p, &text)
                    } else {
                        (engine.write)(s, p, &text)
                    }
                })
            });
            match result {
                Some(Err(e)) => state.error(e.to_string()),
                _ => editing.set(false),
            }
        });
    };
    let force = move |_| {
        let text = if editing.get_untracked() { draft.get_untracked() } else { value() };
        let unforce = forced();
        state.leave_past_then(move || {
            if unforce {
                path.with_value(|p| state.with_sim_mut(|s| s.unforce(p)));
            } else if let Some(Err(e)) = path.with_value(|p| {
                state.with_sim_mut(|s| {
                    crate::lazy::engine().map_or(Ok(()), |e| (e.force)(s, p, &text))
                })
            }) {
                state.error(e.to_string());
            } else {
                editing.set(false);
            }
        });
    };
    let name_cell = {
        let label = row.label.clone();
        let expandable = row.expandable;
        let disclosure_label = tf(K::sim_expand, &[("path", &row.path)]);
        view! {
            <th scope="row" class="var-name" style=format!("padding-left: {}em", 0.4 + row.depth as f64 * 1.2)>
                {expandable.then(|| view! {
                    <button class="disclosure" aria-label=disclosure_label.clone()
                        aria-expanded=move || if is_open.get() { "true" } else { "false" }
                        on:click=toggle.clone()>
                        {move || if is_open.get() { "▾" } else { "▸" }}
                    </button>
                })}
                <span>{label}</span>
                <Show when=forced>
                    <span class="badge-forced" title=t(K::sim_forced)>"F"</span>
                </Show>
            </th>
        }
    };
    let path_text = row.path.clone();
    let child = row.depth > 0;
    // `Why is NAME TRUE?` on every BOOL (issue 36): the name says the value it explains.
    let is_bool = row.ty.eq_ignore_ascii_case("BOOL");
    let why_name = move || {
        path.with_value(|p| {
            let v = state.read(p).unwrap_or(plc_core::vm::Value::Bool(false));
            why_label(p, &v)
        })
    };
    view! {
        <tr class:forced=forced class:child=child>
            <td class="mono">{row.address.clone()}</td>
            {name_cell}
            <td class="mono">{row.ty.clone()}</td>
            // The program's own words: never translated (by the page or the browser).
            <td translate="no">{row.comment.clone()}</td>
            <td class="mono value" on:dblclick=move |_| start_edit()>
                <Show when=move || editing.get()
                    fallback=move || view! { <span>{move || if row.expandable { String::new() } else { value() }}</span> }>
                    <input class="edit" aria-label=tf(K::sim_new_value_of, &[("path", &path.get_value())])
                        prop:value=move || draft.get()
                        on:input=move |ev| draft.set(event_target_value(&ev))
                        on:keydown=move |ev| match ev.key().as_str() {
                            "Enter" => commit(),
                            "Escape" => editing.set(false),
                            _ => {}
                        }
                        on:blur=move |_| editing.set(false)/>
                </Show>
            </td>
            <td class="actions">
                {is_bool.then(|| view! {
                    <button class="small why" aria-label=why_name
                        title=t(K::sim_why_title)
                        on:click=move |_| path.with_value(|p| state.ask_why(p))>{t(K::why_title)}</button>
                }.into_any())}
                {scalar.then(|| view! {
                    <button class="small" aria-label=tf(K::sim_edit, &[("path", &path_text)]) title=t(K::sim_edit_title)
                        on:click=move |_| start_edit()>"✎"</button>
                    <button class="small" class:active=forced
                        aria-label=move || tf(if forced() { K::sim_unforce_name } else { K::sim_force_name }, &[("path", &path.get_value())])
                        on:click=force>
                        {move || t(if forced() { K::sim_unforce } else { K::sim_force })}
                    </button>
                })}
            </td>
        </tr>
    }
}

/// Breakpoints: conditions that pause the PLC at the end of the scan they become true.
#[component]
fn Breakpoints() -> impl IntoView {
    let state = expect_context::<AppState>();
    let text = RwSignal::new(String::new());
    let add = move || match state.add_breakpoint(&text.get_untracked()) {
        Ok(()) => text.set(String::new()),
        Err(e) => state.error(e),
    };
    view! {
        <div class="breakpoints">
            <h3>{t(K::sim_breakpoints)}</h3>
            <div class="control-row">
                <label class="field grow">
                    <span>{t(K::sim_breakpoint_condition)}</span>
                    <input class="mono" placeholder=t(K::sim_breakpoint_placeholder)
                        prop:value=move || text.get()
                        on:input=move |ev| text.set(event_target_value(&ev))
                        on:keydown=move |ev| if ev.key() == "Enter" { add() }/>
                </label>
                <button on:click=move |_| add()>{t(K::sim_add_breakpoint)}</button>
            </div>
            <ul class="bp-list">
                {move || state.breakpoints.get().into_iter().enumerate().map(|(i, (cond, id))| {
                    let inactive = id.is_none();
                    view! {
                        <li class:inactive=inactive>
                            <code>{cond.clone()}</code>
                            {inactive.then(|| view! { <span class="muted">{t(K::sim_breakpoint_inactive)}</span> })}
                            <button class="small" aria-label=tf(K::sim_remove_breakpoint, &[("condition", &cond)])
                                on:click=move |_| state.remove_breakpoint(i)>{t(K::sim_remove)}</button>
                        </li>
                    }
                }).collect_view()}
            </ul>
        </div>
    }
}
