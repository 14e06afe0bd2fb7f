//! The ladder view and editor: a ladder POU's rungs drawn in SVG by hand over an ARIA grid
//! of cells that selects, takes palette tools, keys and operands (`editor.rs` maps them to
//! the core's edits), live while its PROGRAM runs — power flow from the hidden `LdPow_*`
//! variables, contact and coil states, block values — or as the POU's readable ST view.

mod draw;
mod editor;
pub mod geometry;
mod live;

use leptos::prelude::*;
use plc_core::build::Site;
use plc_core::ladder::{
    describe_cell, st_view_pou, CellRef, Element, LadderPou, LadderPouKind, PinKind,
};

use crate::components::editor::text::highlight_html;
use crate::state::AppState;
use draw::{rung_svg, RungCtx};
use editor::{DragSource, LadderEditor, RungAction, Tool, STANDARD_BLOCKS};
use geometry::{rung_geometry, NodePower};
use live::{LadderLive, Probes};

/// Scrolls the element with `id` into view.
pub(crate) fn scroll_to(id: &str) {
    let el = web_sys::window().and_then(|w| w.document()).and_then(|d| d.get_element_by_id(id));
    if let Some(el) = el {
        el.scroll_into_view_with_bool(false);
    }
}

/// What the header says about live values.
fn live_status(state: AppState, pou: &LadderPou) -> Option<String> {
    if pou.kind == LadderPouKind::FunctionBlock {
        return Some(
            "A function block runs inside its instances: shown without live values.".into(),
        );
    }
    match state.running.get() {
        Some(r) if r.eq_ignore_ascii_case(&pou.name) => None,
        Some(r) => Some(format!(
            "The simulator runs PROGRAM {r}: choose {} under Simulation to see this one live.",
            pou.name
        )),
        None => Some("Not running: the project has errors or no PROGRAM.".into()),
    }
}

/// The grid of a rung's cells over its drawing: one `gridcell` per cell, named by its
/// place and content, selected by click, focus or arrow keys, taking keys and double-clicks.
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
    let drop_target = Selector::new(move || {
        editor.drag.with(|d| d.as_ref().filter(|d| d.moved).and_then(|d| d.target))
    });
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
                    let label = format!(
                        "Rung {}, row {}, column {}: {}",
                        index + 1,
                        row + 1,
                        col + 1,
                        describe_cell(cell)
                    );
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
                    let drop_ok = drop_target.clone();
                    let drop_bad = drop_target.clone();
                    view! {
                        <div role="gridcell" class="ld-cell" id=editor.cell_id(at) style=style
                            data-at=format!("{index}-{row}-{col}")
                            class:ld-drop-ok=move || drop_ok.selected(&Some((at, true)))
                            class:ld-drop-bad=move || drop_bad.selected(&Some((at, false)))
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
                            }></div>
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
        let style = format!(
            "left:{:.3}%;top:{:.3}%;width:{:.3}%",
            pct(x0, geo.width),
            pct(at.row as f64 * geo.row_h, geo.height),
            pct((x1 - x0).max(120.0), geo.width)
        );
        // Focused as soon as it is in the page, before the next key arrives.
        let input = NodeRef::<leptos::html::Input>::new();
        input.on_load(|el| {
            let _ = el.focus();
            el.select();
        });
        Some(view! {
            <input class="ld-operand-box mono" type="text" aria-label="Operand" style=style node_ref=input
                prop:value=move || editor.operand_text.get_untracked() spellcheck="false"
                on:input=move |ev| editor.operand_text.set(event_target_value(&ev))
                on:keydown=move |ev: leptos::ev::KeyboardEvent| match ev.key().as_str() {
                    "Enter" => { ev.prevent_default(); editor.commit_operand(); }
                    "Escape" => { ev.prevent_default(); editor.cancel_operand(); }
                    _ => {}
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
        })
    };
    view! {
        <div class="ld-grid" role="grid" aria-label=format!("Rung {} cells", index + 1)>{rows}</div>
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
                {rung.label.clone().filter(|l| !l.trim().is_empty()).map(|l| view! {
                    <span class="ld-label">{format!("{l}:")}</span>
                })}
                <input class="ld-comment" type="text" aria-label=format!("Comment of rung {}", index + 1)
                    placeholder="Rung comment" prop:value=rung.comment.clone()
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
    // What to read from the simulator: worked out only while this POU runs (it lowers the
    // whole POU, too slow to redo on every edit of a large one that is not running).
    let runs_here = Memo::new(move |_| {
        let running = state.running.get();
        pou.with(|p| {
            p.as_ref().is_some_and(|p| {
                p.kind == LadderPouKind::Program
                    && running.as_deref().is_some_and(|r| r.eq_ignore_ascii_case(&p.name))
            })
        })
    });
    let probes = Memo::new(move |_| {
        if !runs_here.get() {
            return None;
        }
        pou.with(|p| p.as_ref().map(Probes::of))
    });
    let live = Memo::new(move |_| {
        let running = state.running.get();
        let runs = pou.with(|p| {
            p.as_ref().is_some_and(|p| {
                p.kind == LadderPouKind::Program
                    && running.as_deref().is_some_and(|r| r.eq_ignore_ascii_case(&p.name))
            })
        });
        if !runs {
            return None;
        }
        probes.with(|pr| pr.as_ref().and_then(|pr| state.with_sim(|s| LadderLive::read(s, pr))))
    });
    let show_st = RwSignal::new(false);
    let editor = LadderEditor::new(state, &name);
    // Drags follow the pointer anywhere in the window and drop on the cell under it.
    let moves = window_event_listener(leptos::ev::pointermove, move |ev| {
        if editor.drag.with_untracked(Option::is_some) {
            editor.pointer_move(f64::from(ev.client_x()), f64::from(ev.client_y()));
        }
    });
    let ups = window_event_listener(leptos::ev::pointerup, move |ev| {
        editor.release(
            f64::from(ev.client_x()),
            f64::from(ev.client_y()),
            ev.ctrl_key() || ev.alt_key(),
        );
    });
    let cancels = window_event_listener(leptos::ev::pointercancel, move |_| editor.drag.set(None));
    on_cleanup(move || {
        moves.remove();
        ups.remove();
        cancels.remove();
    });
    // Declarations asked for from the problem list (Declare NAME) are added here, each an
    // edit of the declarations as they are then.
    let this_pou = name.clone();
    Effect::new(move |_| {
        let mine: Vec<_> = state.ladder_declare.with(|q| {
            q.iter().filter(|(p, ..)| p.eq_ignore_ascii_case(&this_pou)).cloned().collect()
        });
        if mine.is_empty() {
            return;
        }
        state.ladder_declare.update(|q| q.retain(|(p, ..)| !p.eq_ignore_ascii_case(&this_pou)));
        for (_, section, var, ty) in mine {
            if let Some(current) = editor.pou() {
                let text = plc_core::ladder::declare(&current.declarations, section, &var, &ty);
                editor.apply(&plc_core::ladder::LadderEdit::SetDeclarations { text }, None);
            }
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
        Some(view! {
            <div class="ld-ghost" aria-hidden="true"
                style=format!("left:{}px;top:{}px", d.at.0 + 10.0, d.at.1 + 10.0)>{label}</div>
        })
    };

    // A clicked problem or a fault: scroll its rung into view.
    let this = name.clone();
    Effect::new(move |_| {
        for site in [state.focus.get(), state.fault_site.get()].into_iter().flatten() {
            if let Site::Ladder { pou, cell: Some((r, ..)) } = site {
                if pou.eq_ignore_ascii_case(&this) {
                    show_st.set(false);
                    scroll_to(&format!("ld-rung-{r}"));
                }
            }
        }
    });

    let exists = Memo::new(move |_| pou.with(Option::is_some));
    let name_for_rungs = name.clone();
    let body = move || {
        if !exists.get() {
            return view! { <p class="muted">"This ladder POU is no longer in the project."</p> }
                .into_any();
        }
        if show_st.get() {
            let Some(p) = pou.get() else { return ().into_any() };
            let html = highlight_html(&st_view_pou(&p), &[]);
            return view! {
                <pre class="code-view" aria-label=format!("{} as Structured Text", p.name)>
                    <code inner_html=html></code>
                </pre>
            }
            .into_any();
        }
        // Each rung is drawn again only when it, or the problems marked on it, changed: an
        // edit in a POU of a hundred rungs redraws one.
        let pou_name = name_for_rungs.clone();
        let keyed = move || {
            let Some(p) = pou.get() else { return Vec::new() };
            let marks = state.diagnostics.with(|ds| {
                ds.iter()
                    .filter_map(|d| match &d.site {
                        Site::Ladder { pou, cell } if pou.eq_ignore_ascii_case(&p.name) => {
                            Some((cell.map(|c| c.0), format!("{}{}{}", d.code, d.message, d.error)))
                        }
                        _ => None,
                    })
                    .collect::<Vec<_>>()
            });
            p.rungs
                .into_iter()
                .enumerate()
                .map(|(index, rung)| {
                    use std::hash::{Hash, Hasher};
                    let mut h = std::collections::hash_map::DefaultHasher::new();
                    // (its JSON: the writer is in the page already, a Debug format would add code)
                    serde_json::to_string(&rung).unwrap_or_default().hash(&mut h);
                    for (r, m) in &marks {
                        if r.is_none_or(|r| r == index) {
                            m.hash(&mut h);
                        }
                    }
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
    let status = move || pou.with(|p| p.as_ref().and_then(|p| live_status(state, p)));
    view! {
        <section class="panel ladder-view" aria-label=format!("Ladder diagram {name}")>
            <div class="ed-toolbar">
                <h2>"Ladder"</h2>
                <span class="pou-title">{name.clone()}</span>
                <span class="muted small-text">{move || pou.with(|p| match p.as_ref().map(|p| p.kind) {
                    Some(LadderPouKind::FunctionBlock) => "FUNCTION_BLOCK",
                    _ => "PROGRAM",
                })}</span>
                <span class="ed-spacer"></span>
                <button aria-pressed=move || if show_st.get() { "true" } else { "false" }
                    title="Show the POU as readable Structured Text"
                    on:click=move |_| show_st.update(|s| *s = !*s)>"ST view"</button>
            </div>
            {move || status().map(|s| view! { <p class="view-note">{s}</p> })}
            <details class="ld-decls" open=pou.with_untracked(|p| p.as_ref().is_some_and(|p| p.rungs.iter().all(|r| r.cells.iter().flatten().all(|c| c.element == Element::Empty))))>
                <summary>"Declarations"</summary>
                <textarea class="mono ld-decl-text" aria-label="Declarations" spellcheck="false" rows="6"
                    prop:value=move || pou.with(|p| p.as_ref().map(|p| p.declarations.clone()).unwrap_or_default())
                    on:change=move |ev| {
                        editor.apply(&plc_core::ladder::LadderEdit::SetDeclarations { text: event_target_value(&ev) }, None);
                    }></textarea>
            </details>
            <Toolbar editor=editor/>
            {ghost}
            <PinBoxes editor=editor pou=pou/>
            <div class="ld-body">
                <div class="ld-rungs">{body}</div>
                <StBeside editor=editor pou=pou/>
            </div>
        </section>
    }
}

/// The ladder toolbar: undo/redo, the rung and grid actions, the POU's rename and delete,
/// the palette and the block picker (`b` on a cell).
#[component]
fn Toolbar(editor: LadderEditor) -> impl IntoView {
    let state = expect_context::<AppState>();
    let renaming = RwSignal::new(false);
    let rename = move |text: String| {
        renaming.set(false);
        let Some(old) = editor.pou().map(|p| p.name) else { return };
        let mut project = state.project.get_untracked();
        match project.rename_ladder_pou(&old, &text) {
            Ok(()) => {
                let new = text.trim().to_string();
                state.project.set(project);
                state.view.set(crate::state::PouView::Ladder(new));
                state.save();
                state.check_now();
            }
            Err(e) => state.error(format!("Not renamed: {e}.")),
        }
    };
    let delete = move |_| {
        let Some(name) = editor.pou().map(|p| p.name) else { return };
        let ok = web_sys::window()
            .and_then(|w| {
                w.confirm_with_message(&format!(
                    "Delete the ladder POU “{name}”? Undo cannot bring it back."
                ))
                .ok()
            })
            .unwrap_or(false);
        if !ok {
            return;
        }
        let mut project = state.project.get_untracked();
        if project.delete_ladder_pou(&name).is_ok() {
            state.project.set(project);
            state.view.set(crate::state::PouView::St);
            state.save();
            state.check_now();
            state.info(format!("Deleted the ladder POU “{name}”."));
        }
    };
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
        <div class="ld-toolbar" role="toolbar" aria-label="Rungs">
            <button on:click=move |_| editor.undo() disabled=move || !editor.can_undo()
                title="Undo (Ctrl+Z)">"Undo"</button>
            <button on:click=move |_| editor.redo() disabled=move || !editor.can_redo()
                title="Redo (Ctrl+Shift+Z)">"Redo"</button>
            {RungAction::all().into_iter().map(|(action, label)| view! {
                <button on:click=move |_| editor.rung_action(action)>{label}</button>
            }).collect_view()}
            {move || if renaming.get() {
                view! {
                    <input type="text" aria-label="New POU name" autofocus
                        prop:value=editor.pou().map(|p| p.name).unwrap_or_default()
                        on:keydown=move |ev: leptos::ev::KeyboardEvent| match ev.key().as_str() {
                            "Enter" => { ev.prevent_default(); rename(event_target_value(&ev)); }
                            "Escape" => renaming.set(false),
                            _ => {}
                        }/>
                }.into_any()
            } else {
                view! { <button on:click=move |_| renaming.set(true)>"Rename POU"</button> }.into_any()
            }}
            <button on:click=delete>"Delete POU"</button>
        </div>
        {move || editor.picker_open.get().then(|| {
            let picker = NodeRef::<leptos::html::Select>::new();
            picker.on_load(|el| { let _ = el.focus(); });
            view! {
                <label class="field ld-picker">
                    <span>"Block type"</span>
                    <select aria-label="Block type" node_ref=picker
                        on:keydown=move |ev: leptos::ev::KeyboardEvent| match ev.key().as_str() {
                            "Enter" => { ev.prevent_default(); editor.pick_block(Some(event_target_value(&ev))); }
                            "Escape" => { ev.prevent_default(); editor.pick_block(None); }
                            _ => {}
                        }
                        on:change=move |ev| editor.pick_block(Some(event_target_value(&ev)))>
                        <option value="" selected=true>"Choose a block…"</option>
                        {all_blocks.get().into_iter().map(|b| view! { <option value=b.clone()>{b.clone()}</option> }).collect_view()}
                    </select>
                </label>
            }
        })}
        <div class="ld-palette" role="toolbar" aria-label="Palette">
            {Tool::elements().into_iter().map(|t| {
                let title = format!("Put a {} into the selected cell", t.label().to_lowercase());
                tool_button(t, title)
            }).collect_view()}
            {STANDARD_BLOCKS.iter().map(|b| tool_button(Tool::Block(b.to_string()), format!("Put a {b} block into the selected cell"))).collect_view()}
            {move || user_blocks.get().into_iter().map(|b| {
                let title = format!("Put a {b} block into the selected cell");
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
            None => format!("{} at rung {}", block.type_name, at.rung + 1),
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
        Some(view! {
            <div class="ld-pins" role="group" aria-label=format!("Pins of {owner}")>
                {pins.into_iter().map(|(kind, pin, value)| {
                    let label = format!("{pin} of {owner}");
                    let name = pin.clone();
                    view! {
                        <label class="field">
                            <span>{label.clone()}</span>
                            <input class="mono" type="text" aria-label=label prop:value=value spellcheck="false"
                                on:change=move |ev| editor.set_pin(at, kind, &name, &event_target_value(&ev))/>
                        </label>
                    }
                }).collect_view()}
            </div>
        })
    }
}

/// The POU as readable ST beside the rungs (on screens at least 1,100 px wide; below that
/// the ST view button shows it instead of the rungs): the selected rung's lines are lit,
/// and clicking a line selects its rung.
#[component]
fn StBeside(editor: LadderEditor, pou: Memo<Option<LadderPou>>) -> impl IntoView {
    let view = Memo::new(move |_| {
        pou.with(|p| {
            p.as_ref().map(|p| {
                let (body, map) = plc_core::ladder::st_view(p);
                let lines: Vec<(String, Option<usize>)> = body
                    .lines()
                    .enumerate()
                    .map(|(i, l)| {
                        let rung =
                            map.iter().find(|(line, _)| *line as usize == i + 1).map(|(_, r)| *r);
                        (l.to_string(), rung)
                    })
                    .collect();
                (p.name.clone(), lines)
            })
        })
    });
    let selected_rung = Memo::new(move |_| editor.selected.get().map(|c| c.rung));
    move || {
        let (name, lines) = view.get()?;
        Some(view! {
            <aside class="ld-st-side" aria-label=format!("ST beside the rungs of {name}")>
                <pre class="code-view">
                    {lines.into_iter().map(|(text, rung)| {
                        let html = highlight_html(&text, &[]);
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
                    }).collect_view()}
                </pre>
            </aside>
        })
    }
}
