//! The ladder view and editor: a ladder POU's rungs drawn in SVG by hand over an ARIA grid
//! of cells that selects, takes palette tools, keys and operands (`editor.rs` maps them to
//! the core's edits), live while its PROGRAM runs — power flow from the hidden `LdPow_*`
//! variables, contact and coil states, block values — or as the POU's readable ST view.

mod declarations;
mod draw;
pub(crate) use draw::coil_letter;
mod editor;
pub mod geometry;
mod live;
mod zoom;

use leptos::prelude::*;
use plc_core::build::Site;
use plc_core::ladder::{
    describe_cell, st_view_pou, CellRef, Element, LadderPou, LadderPouKind, PinKind,
};

use crate::components::editor::text::{highlight_html, highlight_line_html};
use crate::components::pou_actions::{DiagramKind, PouActions};
use crate::i18n::{t, tf, K};
use crate::state::AppState;
use declarations::DeclarationsEditor;
use draw::{rung_svg, RungCtx};
use editor::{DragSource, LadderEditor, RungAction, Tool, STANDARD_BLOCKS};
use geometry::{rung_geometry, NodePower};
use live::{LadderLive, Probes};
use zoom::{SideToggle, ViewPrefs, ZoomControls};

/// Scrolls the element with `id` into view.
pub(crate) fn scroll_to(id: &str) {
    if let Some(el) = crate::dom::by_id::<web_sys::Element>(id) {
        el.scroll_into_view_with_bool(false);
    }
}

/// What the header says about live values (`instance`: the function block instance shown).
fn live_status(state: AppState, pou: &LadderPou, instance: Option<String>) -> Option<String> {
    let running = state.running.get();
    if pou.kind == LadderPouKind::FunctionBlock {
        return Some(match (running, instance) {
            (Some(r), Some(i)) => tf(K::ladder_live_instance, &[("instance", &i), ("program", &r)]),
            (Some(r), None) => tf(K::ladder_no_instance, &[("program", &r), ("pou", &pou.name)]),
            (None, _) => t(K::ladder_not_running).into(),
        });
    }
    match running {
        Some(r) if r.eq_ignore_ascii_case(&pou.name) => None,
        Some(r) => Some(tf(K::ladder_runs_other, &[("program", &r), ("pou", &pou.name)])),
        None => Some(t(K::ladder_not_running).into()),
    }
}

/// The room (drawing units) the operand box needs beside a cell.
const OPERAND_ROOM: f64 = 130.0;

/// The grid of a rung's cells over its drawing: one `gridcell` per cell, named by its
/// place and content, selected by click, focus or arrow keys, taking keys and double-clicks.
/// `Why is NAME TRUE?` on a contact or coil while its POU runs (issue 36): opens the
/// explanation of its operand at the scan shown.
fn why_button(live: Memo<Option<LadderLive>>, element: &Element) -> Option<impl IntoView> {
    let (Element::Contact { operand, .. } | Element::Coil { operand, .. }) = element else {
        return None;
    };
    let state = expect_context::<AppState>();
    let op = StoredValue::new(operand.trim().to_string());
    Some(move || {
        let value = live.with(|l| op.with_value(|o| l.as_ref()?.bool_of(o)))?;
        let label =
            op.with_value(|o| plc_core::why::why_label(o, &plc_core::vm::Value::Bool(value)));
        Some(view! {
            <button class="ld-why" aria-label=label title=t(K::ladder_why)
                on:pointerdown=move |ev: leptos::ev::PointerEvent| ev.stop_propagation()
                on:dblclick=move |ev: leptos::ev::MouseEvent| ev.stop_propagation()
                on:keydown=move |ev: leptos::ev::KeyboardEvent| ev.stop_propagation()
                on:click=move |ev: leptos::ev::MouseEvent| {
                    ev.stop_propagation();
                    op.with_value(|o| state.ask_why(o));
                }>"?"</button>
        })
    })
}

fn rung_grid(
    editor: LadderEditor,
    rung: &plc_core::ladder::Rung,
    index: usize,
    live: Memo<Option<LadderLive>>,
) -> impl IntoView {
    let geo = rung_geometry(rung);
    let pct = |v: f64, of: f64| if of > 0.0 { v / of * 100.0 } else { 0.0 };
    // Selectors: a change of the selection or of the drop target wakes the two cells it
    // concerns, not every cell of the POU.
    let selection = Selector::new(move || editor.selected.get());
    // Where a drag would drop in this rung: (row, column, rows covered, allowed). A block
    // shows its whole footprint.
    let drop_here = Memo::new(move |_| {
        editor.drag.with(|d| {
            let d = d.as_ref().filter(|d| d.moved)?;
            let (at, ok) = d.target.filter(|(c, _)| c.rung == index)?;
            Some((at.row, at.col, d.footprint, ok))
        })
    });
    let dropped_on = move |row: usize, col: usize, ok: bool| {
        drop_here.with(|t| {
            t.is_some_and(|(r, c, h, allowed)| {
                allowed == ok && c == col && (r..r + h).contains(&row)
            })
        })
    };
    let rows = (0..rung.rows())
        .map(|row| {
            let cells = rung.cells[row]
                .iter()
                .enumerate()
                .map(|(col, cell)| {
                    let at = CellRef::new(index, row, col);
                    let (x0, x1) = geo.col_span(col);
                    let style = format!(
                        "left:{:.3}%;top:{:.3}%;width:{:.3}%;height:{:.3}%",
                        pct(x0, geo.width),
                        pct(row as f64 * geo.row_h, geo.height),
                        pct(x1 - x0, geo.width),
                        pct(geo.row_h, geo.height)
                    );
                    let label = tf(
                        K::ladder_cell,
                        &[
                            ("rung", &(index + 1).to_string()),
                            ("row", &(row + 1).to_string()),
                            ("column", &(col + 1).to_string()),
                            ("cell", &describe_cell(cell)),
                        ],
                    );
                    let why = why_button(live, &cell.element);
                    let is_selected = selection.clone();
                    let selected = move || is_selected.selected(&Some(at));
                    let first = selection.clone();
                    let tab_selected = selection.clone();
                    let tabindex = move || {
                        let none = at == CellRef::default() && first.selected(&None);
                        if tab_selected.selected(&Some(at)) || none {
                            "0"
                        } else {
                            "-1"
                        }
                    };
                    let power = move || {
                        live.with(|l| {
                            l.as_ref().map(|l| if l.powered(index, row, col) { "on" } else { "off" })
                        })
                    };
                    view! {
                        <div role="gridcell" class="ld-cell" id=editor.cell_id(at) style=style
                            data-at=format!("{index}-{row}-{col}")
                            class:ld-drop-ok=move || dropped_on(row, col, true)
                            class:ld-drop-bad=move || dropped_on(row, col, false)
                            on:pointerdown=move |ev: leptos::ev::PointerEvent| editor.press(DragSource::Cell(at), &ev)
                            aria-label=label tabindex=tabindex
                            aria-selected=move || if selected() { "true" } else { "false" }
                            data-power=power
                            on:click=move |_| editor.selected.set(Some(at))
                            on:focus=move |_| {
                                if editor.selected.get_untracked() != Some(at) {
                                    editor.selected.set(Some(at));
                                }
                            }
                            on:dblclick=move |_| editor.edit_operand(at)
                            on:keydown=move |ev: leptos::ev::KeyboardEvent| {
                                let ctrl = ev.ctrl_key() || ev.meta_key();
                                if !ev.alt_key() && editor.key(at, &ev.key(), ctrl, ev.shift_key()) {
                                    ev.prevent_default();
                                }
                            }>{why}</div>
                    }
                })
                .collect_view();
            view! { <div role="row" class="ld-grid-row">{cells}</div> }
        })
        .collect_view();
    // A redraw of this rung replaces its cells: when that took the focus away from the
    // selected cell (it is on the page body now), give it back to the new cell.
    Effect::new(move |_| {
        let Some(at) = editor.selected.get_untracked().filter(|a| a.rung == index) else { return };
        let document = web_sys::window().and_then(|w| w.document());
        let lost = document.as_ref().is_some_and(|d| {
            d.active_element().is_none_or(|a| a.tag_name().eq_ignore_ascii_case("body"))
        });
        if lost {
            use wasm_bindgen::JsCast;
            let el = document
                .and_then(|d| d.get_element_by_id(&editor.cell_id(at)))
                .and_then(|e| e.dyn_into::<web_sys::HtmlElement>().ok());
            if let Some(el) = el {
                let _ = el.focus();
            }
        }
    });
    let operand_box = move || {
        let (at, _) = editor.operand_at.get().filter(|(c, _)| c.rung == index)?;
        let (x0, x1) = geo.col_span(at.col);
        // Beside the element just placed, never over it: right of its cell, or left of it
        // when the box would not fit before the right rail.
        let top = pct(at.row as f64 * geo.row_h, geo.height);
        let style = if x1 + OPERAND_ROOM <= geo.width {
            format!("left:calc({:.3}% + 4px);top:{top:.3}%", pct(x1, geo.width))
        } else {
            format!("right:calc({:.3}% + 4px);top:{top:.3}%", 100.0 - pct(x0, geo.width))
        };
        // Focused as soon as it is in the page, before the next key arrives.
        let input = NodeRef::<leptos::html::Input>::new();
        input.on_load(|el| {
            let _ = el.focus();
            el.select();
        });
        let choices = editor.operand_choices();
        let active = editor.choice_active;
        let active_id = move || active.get().map(|i| format!("ld-choice-{i}"));
        let list = move || {
            let list = choices.get();
            (!list.is_empty()).then(|| view! {
                <ul class="ld-choices" id="ld-operand-choices" role="listbox" aria-label=t(K::ladder_operand_choices)>
                    {list.into_iter().enumerate().map(|(i, c)| {
                        let text = c.text.clone();
                        view! {
                            <li role="option" id=format!("ld-choice-{i}")
                                aria-selected=move || if active.get() == Some(i) { "true" } else { "false" }
                                on:pointerdown=move |ev: leptos::ev::PointerEvent| ev.prevent_default()
                                on:click=move |_| editor.take_choice(&text)>
                                <span class="mono">{c.text}</span>
                                <span class="ld-choice-detail">{c.detail}</span>
                            </li>
                        }
                    }).collect_view()}
                </ul>
            })
        };
        Some(view! {
            <div class="ld-operand" style=style>
                <input class="ld-operand-box mono" type="text" aria-label=t(K::ladder_operand) node_ref=input
                    aria-autocomplete="list" aria-controls="ld-operand-choices"
                    aria-activedescendant=active_id autocomplete="off"
                    prop:value=move || editor.operand_text.get_untracked() spellcheck="false"
                    on:input=move |ev| {
                        editor.operand_text.set(event_target_value(&ev));
                        active.set(None);
                    }
                    on:keydown=move |ev: leptos::ev::KeyboardEvent| {
                        let count = choices.with_untracked(Vec::len);
                        let chosen = active.get_untracked()
                            .and_then(|i| choices.with_untracked(|c| c.get(i).map(|c| c.text.clone())));
                        match ev.key().as_str() {
                            "ArrowDown" if count > 0 => {
                                ev.prevent_default();
                                active.set(Some(active.get_untracked().map_or(0, |i| (i + 1) % count)));
                            }
                            "ArrowUp" if count > 0 => {
                                ev.prevent_default();
                                active.set(Some(active.get_untracked().map_or(count - 1, |i| (i + count - 1) % count)));
                            }
                            "Tab" if chosen.is_some() => {
                                ev.prevent_default();
                                if let (Some(text), Some(el)) = (chosen, input.get_untracked()) {
                                    el.set_value(&text);
                                    editor.operand_text.set(text);
                                    active.set(None);
                                }
                            }
                            "Enter" => {
                                ev.prevent_default();
                                match chosen {
                                    Some(text) => editor.take_choice(&text),
                                    None => editor.commit_operand(),
                                }
                            }
                            "Escape" => { ev.prevent_default(); editor.cancel_operand(); }
                            _ => {}
                        }
                    }
                    on:blur=move |ev| {
                        // A redraw of the rungs removes the box (and draws it again): only a
                        // blur of a box still in the page commits.
                        use wasm_bindgen::JsCast;
                        let input = ev.target().and_then(|t| t.dyn_into::<web_sys::Node>().ok());
                        request_animation_frame(move || {
                            if input.is_some_and(|n| n.is_connected()) && editor.operand_at.get_untracked().is_some() {
                                editor.commit_operand();
                            }
                        });
                    }/>
                {list}
            </div>
        })
    };
    view! {
        <div class="ld-grid" role="grid" aria-label=tf(K::ladder_rung_cells, &[("rung", &(index + 1).to_string())])>{rows}</div>
        {operand_box}
    }
}

/// One rung: its number, label and comment above its drawing.
#[component]
fn RungView(
    rung: plc_core::ladder::Rung,
    index: usize,
    pou: String,
    live: Memo<Option<LadderLive>>,
    editor: LadderEditor,
) -> impl IntoView {
    let state = expect_context::<AppState>();
    let shared = StoredValue::new(rung.clone());
    // This rung's part of the live state: its cells and drawing subscribe to it, not to
    // the whole POU's (thousands of subscribers to one source made every change cost
    // time squared in their number).
    let values = live::rung_values(&rung);
    let live = Memo::new(move |_| live.with(|l| l.as_ref().map(|l| l.slice(index, &values))));
    let nodes = Memo::new(move |_| {
        live.with(|l| {
            l.as_ref().map(|l| {
                shared.with_value(|r| NodePower::new(r, |row, col| l.powered(index, row, col)))
            })
        })
    });
    let ctx = RungCtx { state, live, nodes, rung: index };
    view! {
        <div class="ld-rung" id=format!("ld-rung-{index}")>
            <div class="ld-rung-head">
                <span class="ld-rung-no">{index + 1}</span>
                <input class="ld-label-box mono" type="text" aria-label=tf(K::ladder_rung_label, &[("rung", &(index + 1).to_string())])
                    placeholder=t(K::ladder_label_placeholder) title=t(K::ladder_label_title) spellcheck="false"
                    prop:value=rung.label.clone().unwrap_or_default()
                    on:change=move |ev| {
                        let text = event_target_value(&ev).trim().to_string();
                        let label = (!text.is_empty()).then_some(text);
                        editor.apply(&plc_core::ladder::LadderEdit::SetLabel { rung: index, label }, None);
                    }/>
                <input class="ld-comment" type="text" aria-label=tf(K::ladder_rung_comment, &[("rung", &(index + 1).to_string())])
                    placeholder=t(K::ladder_rung_comment_placeholder) prop:value=rung.comment.clone()
                    on:change=move |ev| {
                        editor.apply(&plc_core::ladder::LadderEdit::SetComment { rung: index, text: event_target_value(&ev) }, None);
                    }/>
            </div>
            <div class="ld-scroll">
                <div class="ld-canvas">
                    {rung_svg(ctx, &rung, &pou)}
                    {rung_grid(editor, &rung, index, live)}
                </div>
            </div>
        </div>
    }
}

/// The view of ladder POU `name`.
#[component]
pub fn LadderView(name: String) -> impl IntoView {
    let state = expect_context::<AppState>();
    let key = name.clone();
    let pou = Memo::new(move |_| {
        state.project.with(|p| p.ladder.iter().find(|l| l.name == key).cloned())
    });
    // Whether this POU can be live: the PROGRAM the simulator runs, or a function block
    // (live in its first instance, when the running program has one).
    let runs_here = Memo::new(move |_| {
        let running = state.running.get();
        pou.with(|p| {
            p.as_ref().is_some_and(|p| match p.kind {
                LadderPouKind::Program => {
                    running.as_deref().is_some_and(|r| r.eq_ignore_ascii_case(&p.name))
                }
                LadderPouKind::FunctionBlock => running.is_some(),
            })
        })
    });
    let fb_name = Memo::new(move |_| {
        pou.with(|p| {
            p.as_ref().filter(|p| p.kind == LadderPouKind::FunctionBlock).map(|p| p.name.clone())
        })
    });
    // The instance whose values a function block POU shows (re-read on every scan, as the
    // program may have been rebuilt; a memo, so an unchanged answer wakes nothing).
    let instance = Memo::new(move |_| {
        let fb = fb_name.get()?;
        state.with_readout(|s| live::first_instance(s, &fb)).flatten()
    });
    // What to read from the simulator: worked out only while this POU runs (it lowers the
    // whole POU, too slow to redo on every edit of a large one that is not running).
    let probes = Memo::new(move |_| {
        if !runs_here.get() {
            return None;
        }
        pou.with(|p| p.as_ref().map(Probes::of))
    });
    let live = Memo::new(move |_| {
        if !runs_here.get() {
            return None;
        }
        let inst = instance.get();
        if fb_name.with(Option::is_some) && inst.is_none() {
            return None;
        }
        probes.with(|pr| {
            pr.as_ref()
                .and_then(|pr| state.with_readout(|s| LadderLive::read(s, pr, inst.as_deref())))
        })
    });
    let show_st = RwSignal::new(false);
    let prefs = ViewPrefs::load();
    let view_id = format!("ld-view-{name}");
    let zoom_for = view_id.clone();
    let editor = LadderEditor::new(state, &name);
    // The declarations start open in a POU without elements yet (there is nothing else
    // to read), closed otherwise.
    let decls_open = RwSignal::new(pou.with_untracked(|p| {
        p.as_ref().is_some_and(|p| {
            p.rungs.iter().all(|r| r.cells.iter().flatten().all(|c| c.element == Element::Empty))
        })
    }));
    // Drags follow the pointer anywhere in the window and drop on the cell under it.
    let moves = window_event_listener(leptos::ev::pointermove, move |ev| {
        if let Some(zoom) = editor.pinch.moved(&ev, prefs.zoom.get_untracked()) {
            prefs.set_zoom(zoom);
        } else if editor.drag.with_untracked(Option::is_some) {
            editor.pointer_move(f64::from(ev.client_x()), f64::from(ev.client_y()));
        }
    });
    let ups = window_event_listener(leptos::ev::pointerup, move |ev| {
        editor.pinch.up(&ev);
        editor.release(
            f64::from(ev.client_x()),
            f64::from(ev.client_y()),
            ev.ctrl_key() || ev.alt_key(),
        );
    });
    let cancels = window_event_listener(leptos::ev::pointercancel, move |ev| {
        editor.pinch.up(&ev);
        editor.drag.set(None)
    });
    on_cleanup(move || {
        moves.remove();
        ups.remove();
        cancels.remove();
    });
    // Declarations asked for from the problem list (Declare NAME) are added here, each an
    // edit of the declarations as they are then; its other fixes (Replace with NAME) are
    // applied as they come. Each is one undo step.
    let this_pou = name.clone();
    Effect::new(move |_| {
        let mine = |p: &String| p.eq_ignore_ascii_case(&this_pou);
        let declares: Vec<_> =
            state.ladder_declare.with(|q| q.iter().filter(|d| mine(&d.0)).cloned().collect());
        let fixes: Vec<_> =
            state.ladder_fix.with(|q| q.iter().filter(|f| mine(&f.0)).cloned().collect());
        if !declares.is_empty() {
            state.ladder_declare.update(|q| q.retain(|d| !mine(&d.0)));
        }
        if !fixes.is_empty() {
            state.ladder_fix.update(|q| q.retain(|f| !mine(&f.0)));
        }
        for (_, section, var, ty) in declares {
            if let Some(current) = editor.pou() {
                let text = plc_core::ladder::declare(&current.declarations, section, &var, &ty);
                editor.apply(&plc_core::ladder::LadderEdit::SetDeclarations { text }, None);
            }
        }
        for (_, edit) in fixes {
            editor.apply(&edit, None);
        }
    });
    let ghost = move || {
        let d = editor.drag.get().filter(|d| d.moved)?;
        let label = match &d.source {
            DragSource::Tool(t) => t.label(),
            DragSource::Cell(at) => {
                editor.pou().and_then(|p| p.cell(*at).map(describe_cell)).unwrap_or_default()
            }
        };
        // Clear of the cell it would drop on: above it (below it at the top of the window),
        // or beside the pointer when it is over no cell.
        let target = d.target.and_then(|(at, _)| {
            let document = web_sys::window()?.document()?;
            Some(document.get_element_by_id(&editor.cell_id(at))?.get_bounding_client_rect())
        });
        let style = match target {
            Some(r) if r.top() >= 40.0 => {
                format!("left:{}px;top:{}px;transform:translateY(-100%)", r.left(), r.top() - 6.0)
            }
            Some(r) => format!(
                "left:{}px;top:{}px",
                r.left(),
                r.bottom() + (d.footprint.max(1) - 1) as f64 * r.height() + 6.0
            ),
            None => format!("left:{}px;top:{}px", d.at.0 + 16.0, d.at.1 + 16.0),
        };
        Some(view! { <div class="ld-ghost" aria-hidden="true" style=style>{label}</div> })
    };

    // A clicked problem or a fault: scroll its rung into view.
    let this = name.clone();
    Effect::new(move |_| {
        for site in [state.focus.get(), state.fault_site.get()].into_iter().flatten() {
            if let Site::Ladder { pou, cell: Some((r, row, col)) } = site {
                if pou.eq_ignore_ascii_case(&this) {
                    show_st.set(false);
                    scroll_to(&format!("ld-rung-{r}"));
                    // The problem's cell becomes the selected one, with the focus.
                    let at = CellRef::new(r, row, col);
                    if editor.selected.get_untracked() != Some(at) {
                        editor.selected.set(Some(at));
                    }
                    editor.focus_selected();
                }
            }
        }
    });

    let exists = Memo::new(move |_| pou.with(Option::is_some));
    let name_for_rungs = name.clone();
    let body = move || {
        if !exists.get() {
            return view! { <p class="muted">{t(K::ladder_pou_gone)}</p> }.into_any();
        }
        if show_st.get() {
            let Some(p) = pou.get() else { return ().into_any() };
            let html = highlight_html(&st_view_pou(&p), &[]);
            let (il, _) = plc_core::ladder::il_view(&p);
            let il_html = highlight_html(&il, &[]);
            return view! {
                <pre class="code-view" tabindex="0" aria-label=tf(K::ladder_as_st, &[("name", &p.name)])>
                    <code inner_html=html></code>
                </pre>
                <section class="ld-il-view" role="region" aria-label=t(K::ladder_il_view)>
                    <h3>{t(K::ladder_instruction_list)}</h3>
                    <pre class="code-view" tabindex="0" aria-label=tf(K::ladder_as_il, &[("name", &p.name)])>
                        <code inner_html=il_html></code>
                    </pre>
                </section>
            }
            .into_any();
        }
        // Each rung is drawn again only when it changed: an edit in a POU of a hundred rungs
        // redraws one, and a check that marks or clears a problem redraws none (the marks
        // follow the problems by themselves, `draw::marks`).
        let pou_name = name_for_rungs.clone();
        let keyed = move || {
            let Some(p) = pou.get() else { return Vec::new() };
            p.rungs
                .into_iter()
                .enumerate()
                .map(|(index, rung)| {
                    use std::hash::{Hash, Hasher};
                    let mut h = std::collections::hash_map::DefaultHasher::new();
                    // (its JSON: the writer is in the page already, a Debug format would add code)
                    serde_json::to_string(&rung).unwrap_or_default().hash(&mut h);
                    (index, h.finish(), rung)
                })
                .collect::<Vec<_>>()
        };
        view! {
            <For each=keyed key=|(index, hash, _)| (*index, *hash)
                children=move |(index, _, rung)| view! {
                    <RungView rung=rung index=index pou=pou_name.clone() live=live editor=editor/>
                }/>
        }
        .into_any()
    };
    let status =
        move || pou.with(|p| p.as_ref().and_then(|p| live_status(state, p, instance.get())));
    view! {
        <section class="panel ladder-view" id=view_id aria-label=tf(K::ladder_view_label, &[("name", &name)])>
            <div class="ed-toolbar">
                <h2>{t(K::ladder_heading)}</h2>
                <span class="pou-title">{name.clone()}</span>
                <span class="muted small-text">{move || pou.with(|p| match p.as_ref().map(|p| p.kind) {
                    Some(LadderPouKind::FunctionBlock) => "FUNCTION_BLOCK",
                    _ => "PROGRAM",
                })}</span>
                <span class="ed-spacer"></span>
                <SideToggle prefs=prefs/>
                <button aria-pressed=move || if show_st.get() { "true" } else { "false" }
                    title=t(K::ladder_st_view_title)
                    on:click=move |_| show_st.update(|s| *s = !*s)>{t(K::ladder_st_view)}</button>
            </div>
            {move || status().map(|s| view! { <p class="view-note">{s}</p> })}
            <DeclarationsEditor editor=editor pou=pou open=decls_open/>
            <Toolbar editor=editor name=name.clone()>
                <ZoomControls prefs=prefs pou=pou view_id=zoom_for.clone()/>
            </Toolbar>
            {ghost}
            <PinBoxes editor=editor pou=pou/>
            <div class="ld-body" class:ld-side-hidden=move || !prefs.side.get()
                style=move || format!("--ld-zoom:{}", prefs.zoom.get())>
                <div class="ld-rungs">{body}</div>
                {move || prefs.side.get().then(|| view! { <StBeside editor=editor pou=pou/> })}
            </div>
        </section>
    }
}

/// The ladder toolbar: undo/redo, the rung and grid actions, the POU's rename and delete,
/// `children` (the zoom), the palette and the block picker (`b` on a cell).
#[component]
fn Toolbar(editor: LadderEditor, name: String, children: Children) -> impl IntoView {
    let state = expect_context::<AppState>();
    let all_blocks = Memo::new(move |_| {
        let mut list: Vec<String> = STANDARD_BLOCKS.iter().map(|b| b.to_string()).collect();
        list.extend(state.project.with(|p| p.catalog().user_block_names()));
        list
    });
    let user_blocks = Memo::new(move |_| state.project.with(|p| p.catalog().user_block_names()));
    let tool_button = move |tool: Tool, title: String| {
        let label = tool.label();
        let dragged = tool.clone();
        view! {
            <button class="ld-tool" title=title on:click=move |_| editor.use_tool(&tool, None)
                on:pointerdown=move |ev: leptos::ev::PointerEvent| editor.press(DragSource::Tool(dragged.clone()), &ev)>{label}</button>
        }
    };
    view! {
        <div class="ld-toolbar" role="toolbar" aria-label=t(K::ladder_rungs)>
            <button on:click=move |_| editor.undo() disabled=move || !editor.can_undo()
                title=t(K::ladder_undo_title)>{t(K::ladder_undo)}</button>
            <button on:click=move |_| editor.redo() disabled=move || !editor.can_redo()
                title=t(K::ladder_redo_title)>{t(K::ladder_redo)}</button>
            {RungAction::all().into_iter().map(|(action, label)| view! {
                <button on:click=move |_| editor.rung_action(action)>{t(label)}</button>
            }).collect_view()}
            <PouActions kind=DiagramKind::Ladder name=name.clone()/>
            {children()}
        </div>
        {move || editor.picker_open.get().then(|| {
            let picker = NodeRef::<leptos::html::Select>::new();
            picker.on_load(|el| { let _ = el.focus(); });
            // Typing in the list moves its choice (and fires change) letter by letter: a
            // block typed by name is taken on Enter; a choice made with the mouse at once.
            let typing = StoredValue::new(false);
            view! {
                <label class="field ld-picker">
                    <span>{t(K::ladder_block_type)}</span>
                    <select aria-label=t(K::ladder_block_type) node_ref=picker
                        on:keydown=move |ev: leptos::ev::KeyboardEvent| match ev.key().as_str() {
                            "Enter" => { ev.prevent_default(); editor.pick_block(Some(event_target_value(&ev))); }
                            "Escape" => { ev.prevent_default(); editor.pick_block(None); }
                            _ => typing.set_value(true),
                        }
                        on:change=move |ev| if !typing.get_value() { editor.pick_block(Some(event_target_value(&ev))) }>
                        <option value="" selected=true>{t(K::ladder_choose_block)}</option>
                        {all_blocks.get().into_iter().map(|b| view! { <option value=b.clone()>{b.clone()}</option> }).collect_view()}
                    </select>
                </label>
            }
        })}
        <div class="ld-palette" role="toolbar" aria-label=t(K::ladder_palette)>
            {Tool::elements().into_iter().map(|tool| {
                let title = tf(K::ladder_put_tool, &[("tool", &tool.label().to_lowercase())]);
                tool_button(tool, title)
            }).collect_view()}
            {STANDARD_BLOCKS.iter().map(|b| tool_button(Tool::Block(b.to_string()), tf(K::ladder_put_block, &[("block", b)]))).collect_view()}
            {move || user_blocks.get().into_iter().map(|b| {
                let title = tf(K::ladder_put_block, &[("block", &b)]);
                tool_button(Tool::Block(b), title)
            }).collect_view()}
        </div>
    }
}

/// The pin boxes of the selected block: `PIN of INSTANCE` (`PT of T1`), or for a function
/// `PIN of TYPE at rung R`.
#[component]
fn PinBoxes(editor: LadderEditor, pou: Memo<Option<LadderPou>>) -> impl IntoView {
    let state = expect_context::<AppState>();
    move || {
        let at = editor.selected.get()?;
        let block = pou.with(|p| {
            let cell = p.as_ref()?.cell(at)?;
            match &cell.element {
                Element::Block(b) => Some(b.clone()),
                _ => None,
            }
        })?;
        let catalog = state.project.with_untracked(|p| p.catalog());
        let ty = catalog.block(&block.type_name)?.clone();
        let owner = match &block.instance {
            Some(i) => i.clone(),
            None => tf(
                K::ladder_block_at_rung,
                &[("block", &block.type_name), ("rung", &(at.rung + 1).to_string())],
            ),
        };
        let power_in = block.power_input().to_string();
        let power_out = block.power_output().to_string();
        let pins: Vec<(PinKind, String, String)> = ty
            .inputs
            .iter()
            .filter(|p| {
                !p.name.eq_ignore_ascii_case(&power_in) && !p.name.eq_ignore_ascii_case("EN")
            })
            .map(|p| {
                let bound = block.inputs.iter().find(|b| b.name.eq_ignore_ascii_case(&p.name));
                (
                    PinKind::Input,
                    p.name.clone(),
                    bound.map(|b| b.operand.clone()).unwrap_or_default(),
                )
            })
            .chain(
                ty.outputs
                    .iter()
                    .filter(|p| {
                        !p.name.eq_ignore_ascii_case(&power_out)
                            && !p.name.eq_ignore_ascii_case("ENO")
                    })
                    .map(|p| {
                        let bound =
                            block.outputs.iter().find(|b| b.name.eq_ignore_ascii_case(&p.name));
                        (
                            PinKind::Output,
                            p.name.clone(),
                            bound.map(|b| b.operand.clone()).unwrap_or_default(),
                        )
                    }),
            )
            .collect();
        let height = block.height;
        let height_label = tf(K::ladder_height_of, &[("owner", &owner)]);
        // Enter and Escape give the focus back to the cell; leaving a changed box commits it
        // (its change event), so Escape first puts back what the box held.
        let back_to_cell = move |ev: leptos::ev::KeyboardEvent, original: &str| {
            let key = ev.key();
            if key == "Escape" {
                use wasm_bindgen::JsCast;
                let input =
                    ev.target().and_then(|t| t.dyn_into::<web_sys::HtmlInputElement>().ok());
                if let Some(input) = input {
                    input.set_value(original);
                }
            }
            if key == "Enter" || key == "Escape" {
                ev.prevent_default();
                editor.focus_selected();
            }
        };
        let pins = pins.into_iter().map(|(kind, pin, value)| {
                    let label = tf(K::ladder_pin_of, &[("pin", &pin), ("owner", &owner)]);
                    let name = pin.clone();
                    let original = value.clone();
                    view! {
                        <label class="field">
                            <span>{label.clone()}</span>
                            <input class="mono" type="text" aria-label=label prop:value=value spellcheck="false"
                                on:keydown=move |ev| back_to_cell(ev, &original)
                                on:change=move |ev| editor.set_pin(at, kind, &name, &event_target_value(&ev))/>
                        </label>
                    }
                }).collect_view();
        Some(view! {
            <div class="ld-pins" role="group" aria-label=tf(K::ladder_pins_of, &[("owner", &owner)])>
                {pins}
                <label class="field">
                    <span>{height_label.clone()}</span>
                    <input type="number" min="1" max="16" aria-label=height_label prop:value=height.to_string()
                        on:keydown=move |ev| back_to_cell(ev, &height.to_string())
                        on:change=move |ev| {
                            let done = match event_target_value(&ev).trim().parse::<u32>() {
                                Ok(h) if h >= 1 => editor.apply(&plc_core::ladder::LadderEdit::ResizeBlock { at, height: h }, None),
                                _ => {
                                    state.error(t(K::ladder_bad_height));
                                    false
                                }
                            };
                            if !done {
                                // The box shows the height the block still has.
                                use wasm_bindgen::JsCast;
                                if let Some(el) = ev.target().and_then(|t| t.dyn_into::<web_sys::HtmlInputElement>().ok()) {
                                    el.set_value(&height.to_string());
                                }
                            }
                        }/>
                </label>

            </div>
        })
    }
}

/// A view's text as lines, each with the rung it comes from (`map`: 1-based line → rung).
fn lines_with_rungs(body: &str, map: &[(u32, usize)]) -> Vec<(String, Option<usize>)> {
    body.lines()
        .enumerate()
        .map(|(i, l)| {
            let rung = map.iter().find(|(line, _)| *line as usize == i + 1).map(|(_, r)| *r);
            (l.to_string(), rung)
        })
        .collect()
}

/// The POU as readable ST beside the rungs (below them when the view is narrow), and as
/// Instruction List below it where its rungs have one (on screens at least 1,100 px wide;
/// below that the ST view button shows them instead of the rungs; `ST and IL views`
/// collapses them): the selected rung's lines are lit, and clicking a line selects its rung.
#[component]
fn StBeside(editor: LadderEditor, pou: Memo<Option<LadderPou>>) -> impl IntoView {
    let view = Memo::new(move |_| {
        pou.with(|p| {
            p.as_ref().map(|p| {
                let (body, map) = plc_core::ladder::st_view(p);
                let (il, il_map) = plc_core::ladder::il_view(p);
                (p.name.clone(), lines_with_rungs(&body, &map), lines_with_rungs(&il, &il_map))
            })
        })
    });
    let name = Memo::new(move |_| view.with(|v| v.as_ref().map(|(n, _, _)| n.clone())));
    let st = Memo::new(move |_| {
        view.with(|v| v.as_ref().map(|(_, l, _)| l.clone()).unwrap_or_default())
    });
    let il = Memo::new(move |_| {
        view.with(|v| v.as_ref().map(|(_, _, l)| l.clone()).unwrap_or_default())
    });
    move || {
        let name = name.get()?;
        Some(view! {
            <aside class="ld-st-side" aria-label=tf(K::ladder_st_beside, &[("name", &name)])>
                <BesideLines editor=editor lines=st/>
                <section class="ld-il-view" role="region" aria-label=t(K::ladder_il_view)>
                    <h3>{t(K::ladder_instruction_list)}</h3>

                    <BesideLines editor=editor lines=il/>
                </section>
            </aside>
        })
    }
}

/// The lines of one view beside the rungs, the selected rung's lit, a click selecting the
/// line's rung.
#[component]
fn BesideLines(editor: LadderEditor, lines: Memo<Vec<(String, Option<usize>)>>) -> impl IntoView {
    let selected_rung = Memo::new(move |_| editor.selected.get().map(|c| c.rung));
    // Keyed by text, rung and which repeat of the two it is (not by position, which every
    // inserted line shifts): an edit redraws the lines it changed, not all of them.
    let keyed = move || {
        lines.with(|lines| {
            let mut seen: std::collections::HashMap<(String, Option<usize>), usize> =
                std::collections::HashMap::new();
            lines
                .iter()
                .map(|(t, r)| {
                    let n = seen.entry((t.clone(), *r)).or_insert(0);
                    *n += 1;
                    (*n, t.clone(), *r)
                })
                .collect::<Vec<_>>()
        })
    };
    view! {
        // Focusable: keyboard users scroll its long lines.
        <pre class="code-view" tabindex="0">
            <For each=keyed key=|line| line.clone() children=move |(_, text, rung)| {
                let html = highlight_line_html(&text);
                let lit = move || rung.is_some() && selected_rung.get() == rung;
                view! {
                    <div class="ld-st-line" class:lit=lit
                        on:click=move |_| if let Some(r) = rung {
                            editor.selected.set(Some(CellRef::new(r, 0, 0)));
                            editor.focus_selected();
                        }>
                        <code inner_html=html></code>
                    </div>
                }
            }/>
        </pre>
    }
}
