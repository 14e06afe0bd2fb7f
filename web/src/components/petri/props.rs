//! The properties of the selected net element (`Name`, `Initial tokens`, `Capacity` (empty:
//! unlimited), `CASE label` and `Actions` of a place; `Name`, `Guard` and `Priority` of a transition; `Weight` of an
//! arc) and the net's declarations. Changes apply as you type, a moment after the last key,
//! each field's typing one undo step; a value that cannot be taken is said beside it.

use std::time::Duration;

use leptos::prelude::*;
use plc_core::build::Site;
use plc_core::petri::{NetEdit, NetElement, PetriPou, TextPart};

use super::editor::{NetEditor, Selection};
use crate::components::code_field::{CodeField, DeclarationsBox, FieldProblem};
use crate::i18n::{t, tf, K};
use crate::state::AppState;

/// Pause after the last key before a field's value is applied.
const APPLY_DELAY: Duration = Duration::from_millis(300);

/// Puts the focus into the first field of the properties panel (Enter on an element).
pub fn focus_first_field() {
    request_animation_frame(|| {
        use wasm_bindgen::JsCast;
        let field = web_sys::window()
            .and_then(|w| w.document())
            .and_then(|d| d.query_selector(".pn-props input, .pn-props textarea").ok().flatten())
            .and_then(|e| e.dyn_into::<web_sys::HtmlElement>().ok());
        if let Some(field) = field {
            let _ = field.focus();
        }
    });
}

/// The problems of a POU's element text (`part` of `element`), for a code field.
fn text_problems(
    state: AppState,
    pou: &str,
    element: &NetElement,
    part: TextPart,
) -> Vec<FieldProblem> {
    state.diagnostics.with(|ds| {
        ds.iter()
            .filter_map(|d| match &d.site {
                Site::Petri { pou: p, element: Some(e), at: Some(at) }
                    if p.eq_ignore_ascii_case(pou) && e == element && at.part == part =>
                {
                    Some((at.line, at.column, d.error, format!("{}  {}", d.code, d.message())))
                }
                _ => None,
            })
            .collect()
    })
}

/// One text field of the panel: `label`, the model's value, and the edit a typed value
/// makes (or why it cannot be taken).
fn field(
    editor: NetEditor,
    label: &'static str,
    group: String,
    numeric: bool,
    value: Signal<String>,
    edit: impl Fn(&str) -> Result<NetEdit, String> + Copy + Send + Sync + 'static,
) -> impl IntoView {
    let problem = RwSignal::new(None::<String>);
    let generation = StoredValue::new(0u64);
    let group = StoredValue::new(group);
    let apply = move |text: String| match edit(&text) {
        Ok(e) => {
            problem.set(None);
            group.with_value(|g| editor.apply(&[e], Some(g)));
        }
        Err(why) => problem.set(Some(why)),
    };
    view! {
        <label class="field">
            <span>{label}</span>
            // Textboxes, numbers too (the issue names them so; inputmode brings the digits
            // keyboard on phones).
            <input type="text" inputmode=if numeric { "numeric" } else { "text" } aria-label=label spellcheck="false"
                prop:value=move || value.get()
                on:input=move |ev| {
                    let text = event_target_value(&ev);
                    generation.update_value(|g| *g += 1);
                    let mine = generation.get_value();
                    set_timeout(move || {
                        if generation.try_get_value() == Some(mine) {
                            apply(text);
                        }
                    }, APPLY_DELAY);
                }
                on:change=move |ev| {
                    generation.update_value(|g| *g += 1);
                    apply(event_target_value(&ev));
                    editor.close_group();
                }
                on:keydown=move |ev: leptos::ev::KeyboardEvent| if ev.key() == "Escape" {
                    ev.prevent_default();
                    editor.focus_selected();
                }/>
            {move || problem.get().map(|p| view! { <span class="field-error" role="alert">{p}</span> })}
        </label>
    }
}

fn number(text: &str, what: &str) -> Result<u32, String> {
    text.trim().parse::<u32>().map_err(|_| tf(K::petri_whole_number, &[("what", what)]))
}

/// The properties panel of the selection.
#[component]
pub fn Properties(editor: NetEditor, pou: Memo<Option<PetriPou>>) -> impl IntoView {
    let state = expect_context::<AppState>();
    // Drawn again only when another element is selected: typing changes the POU, and the
    // fields follow it without being replaced (they keep the focus).
    let selection = Memo::new(move |_| editor.selected.get());
    move || {
        let sel = selection.get()?;
        let name = pou.with_untracked(|p| p.as_ref().map(|p| p.name.clone()))?;
        let exists = pou.with_untracked(|p| {
            p.as_ref().is_some_and(|p| match &sel {
                Selection::Element(id) => p.kind_of(id).is_some(),
                Selection::Arc(f, t) => p.net.arcs.iter().any(|a| a.from == *f && a.to == *t),
            })
        });
        if !exists {
            return None;
        }
        let body = match sel {
            Selection::Element(id) => {
                let kind = pou.with_untracked(|p| p.as_ref().and_then(|p| p.kind_of(&id)));
                let sid = StoredValue::new(id.clone());
                let place = move |p: &PetriPou| sid.with_value(|id| p.net.place(id).cloned());
                let trans = move |p: &PetriPou| sid.with_value(|id| p.net.transition(id).cloned());
                let name_of = Signal::derive(move || {
                    pou.with(|p| {
                        let p = p.as_ref()?;
                        sid.with_value(|id| {
                            p.net
                                .place(id)
                                .map(|q| q.name.clone())
                                .or_else(|| p.net.transition(id).map(|t| t.name.clone()))
                                .or_else(|| {
                                    p.net
                                        .macro_places
                                        .iter()
                                        .find(|m| m.id == *id)
                                        .map(|m| m.name.clone())
                                })
                        })
                    })
                    .unwrap_or_default()
                });
                let name_field = field(
                    editor,
                    t(K::petri_name),
                    format!("{id}.name"),
                    false,
                    name_of,
                    move |text| {
                        Ok(NetEdit::SetName { id: sid.get_value(), name: text.to_string() })
                    },
                );
                let title = match kind {
                    Some(plc_core::petri::ElementKind::Place) => {
                        tf(K::petri_place_name, &[("name", &id)])
                    }
                    Some(plc_core::petri::ElementKind::Transition) => {
                        tf(K::petri_transition_name, &[("name", &id)])
                    }
                    _ => tf(K::petri_macro_place_name, &[("name", &id)]),
                };
                let extra = match kind {
                    Some(plc_core::petri::ElementKind::Place) => {
                        let tokens = Signal::derive(move || {
                            pou.with(|p| p.as_ref().and_then(place).map(|q| q.tokens.to_string()))
                                .unwrap_or_default()
                        });
                        let capacity = Signal::derive(move || {
                            pou.with(|p| {
                                p.as_ref()
                                    .and_then(place)
                                    .and_then(|q| q.capacity)
                                    .map(|c| c.to_string())
                            })
                            .unwrap_or_default()
                        });
                        let label = Signal::derive(move || {
                            pou.with(|p| p.as_ref().and_then(place).map(|q| q.label.to_string()))
                                .unwrap_or_default()
                        });
                        let actions = Signal::derive(move || {
                            pou.with(|p| p.as_ref().and_then(place).map(|q| q.actions))
                                .unwrap_or_default()
                        });
                        let element = NetElement::Place(id.clone());
                        let pou_name = name.clone();
                        let problems = Signal::derive(move || {
                            text_problems(state, &pou_name, &element, TextPart::Actions)
                        });
                        let on_commit = Callback::new(move |text: String| {
                            editor.apply(
                                &[NetEdit::SetActions { id: sid.get_value(), text }],
                                Some(&format!("{}.actions", sid.get_value())),
                            );
                        });
                        let on_leave = Callback::new(move |()| editor.close_group());
                        view! {
                            {field(editor, t(K::petri_initial_tokens), format!("{id}.tokens"), true, tokens, move |text| {
                                Ok(NetEdit::SetTokens { id: sid.get_value(), tokens: number(text, t(K::petri_initial_tokens))? })
                            })}
                            {field(editor, t(K::petri_capacity), format!("{id}.capacity"), true, capacity, move |text| {
                                let capacity = if text.trim().is_empty() { None } else { Some(number(text, t(K::petri_capacity))?) };
                                Ok(NetEdit::SetCapacity { id: sid.get_value(), capacity })
                            })}
                            {field(editor, t(K::petri_case_label), format!("{id}.label"), true, label, move |text| {
                                let label = text.trim().parse::<i64>().map_err(|_| t(K::petri_case_label_number).to_string())?;
                                Ok(NetEdit::SetLabel { id: sid.get_value(), label })
                            })}
                            <div class="field pn-actions">
                                <span>{t(K::petri_actions)}</span>
                                <CodeField label=t(K::petri_actions) text=actions on_commit=on_commit on_leave=on_leave
                                    problems=problems min_rows=3 max_rows=12/>
                            </div>
                        }
                        .into_any()
                    }
                    Some(plc_core::petri::ElementKind::Transition) => {
                        let guard = Signal::derive(move || {
                            pou.with(|p| p.as_ref().and_then(trans).map(|t| t.guard))
                                .unwrap_or_default()
                        });
                        let priority = Signal::derive(move || {
                            pou.with(|p| p.as_ref().and_then(trans).map(|t| t.priority.to_string()))
                                .unwrap_or_default()
                        });
                        let element = NetElement::Transition(id.clone());
                        let pou_name = name.clone();
                        let guard_problems = move || {
                            text_problems(state, &pou_name, &element, TextPart::Guard)
                                .into_iter()
                                .map(|(_, _, _, m)| m)
                                .collect::<Vec<_>>()
                        };
                        view! {
                            {field(editor, t(K::petri_guard), format!("{id}.guard"), false, guard, move |text| {
                                Ok(NetEdit::SetGuard { id: sid.get_value(), text: text.to_string() })
                            })}
                            {field(editor, t(K::petri_priority), format!("{id}.priority"), true, priority, move |text| {
                                Ok(NetEdit::SetPriority { id: sid.get_value(), priority: number(text, t(K::petri_priority))? })
                            })}
                            <ul class="pn-details-problems">
                                {move || guard_problems().into_iter().map(|m| view! { <li>{m}</li> }).collect_view()}
                            </ul>
                        }
                        .into_any()
                    }
                    _ => ().into_any(),
                };
                view! {
                    <h3>{title}</h3>
                    <div class="pn-prop-fields">
                        {name_field}
                        {extra}
                    </div>
                }
                .into_any()
            }
            Selection::Arc(from, to) => {
                let ends = StoredValue::new((from.clone(), to.clone()));
                let weight = Signal::derive(move || {
                    pou.with(|p| {
                        let (f, t) = ends.get_value();
                        p.as_ref()?
                            .net
                            .arcs
                            .iter()
                            .find(|a| a.from == f && a.to == t)
                            .map(|a| a.weight.to_string())
                    })
                    .unwrap_or_default()
                });
                view! {
                    <h3>{tf(K::petri_arc_label, &[("from", &from), ("to", &to)])}</h3>
                    <div class="pn-prop-fields">
                        {field(editor, t(K::petri_weight), format!("{from}>{to}.weight"), true, weight, move |text| {
                            let (from, to) = ends.get_value();
                            let weight = number(text, t(K::petri_weight))?;
                            if weight == 0 {
                                return Err(t(K::petri_weight_at_least_one).to_string());
                            }
                            Ok(NetEdit::SetWeight { from, to, weight })
                        })}
                    </div>
                }
                .into_any()
            }
        };
        Some(view! {
            <div class="pn-props" role="group" aria-label=t(K::petri_properties)>
                {body}
                <button class="pn-props-delete" on:click=move |_| editor.delete_selection()>{t(K::petri_delete)}</button>
            </div>
        })
    }
}

/// The net's declarations (its inputs for guards, outputs for actions): a code field with
/// the problems the build finds in them, each typing one undo step of the net editor.
#[component]
pub fn NetDeclarations(editor: NetEditor, pou: Memo<Option<PetriPou>>) -> impl IntoView {
    let state = expect_context::<AppState>();
    let text = Signal::derive(move || {
        pou.with(|p| p.as_ref().map(|p| p.declarations.clone())).unwrap_or_default()
    });
    let name = Memo::new(move |_| pou.with(|p| p.as_ref().map(|p| p.name.clone())));
    let problems = Signal::derive(move || {
        let name = name.get().unwrap_or_default();
        text_problems(state, &name, &NetElement::Declarations, TextPart::Text)
    });
    let open =
        RwSignal::new(pou.with_untracked(|p| p.as_ref().is_some_and(|p| p.net.places.is_empty())));
    let reveal = Signal::derive(move || match state.focus.get() {
        Some(Site::Petri { pou: p, element: Some(NetElement::Declarations), at: Some(at) })
            if name.with(|n| n.as_deref().is_some_and(|n| n.eq_ignore_ascii_case(&p))) =>
        {
            Some((at.line, at.column))
        }
        _ => None,
    });
    let on_commit = Callback::new(move |text: String| {
        editor.apply(&[NetEdit::SetDeclarations { text }], Some("declarations"));
    });
    let on_leave = Callback::new(move |()| editor.close_group());
    view! {
        <DeclarationsBox open=open text=text on_commit=on_commit on_leave=on_leave
            problems=problems reveal=reveal/>
    }
}
