//! The Structured Text editor: a transparent `<textarea>` over a `<pre>` that shows the
//! lexer's highlighting, diagnostic squiggles and the marked (fault) line, beside a
//! line-number gutter; a status line below. (The problem list of the whole project is its
//! own panel, `problems.rs`.)
//!
//! The text area stays the only editable surface (so selection, IME, paste and screen
//! readers keep working); the layers behind it only mirror its text and scroll. Edits the
//! editor makes itself (Tab, Enter, undo) replace the text programmatically, which breaks
//! the browser's own undo, so the editor keeps its own history of (text, selection)
//! snapshots.

pub(crate) mod text;

use std::collections::BTreeMap;
use std::time::Duration;

use leptos::ev;
use leptos::html;
use leptos::prelude::*;
use plc_core::project::StorageBackend;
use web_sys::HtmlTextAreaElement;

use crate::components::variables::why_label;
use crate::i18n::{t, tf, K};
use crate::state::{AppState, PouView};
use text::{byte_to_utf16, line_col, offset_of, utf16_to_byte, Edit, LineInfo, Mark};

/// Row height of the editor in pixels (must match `--ed-line` in style.css).
const LINE_PX: i32 = 20;
/// Padding of the text area and the layers in pixels (must match `--ed-pad`).
const PAD_PX: i32 = 8;
/// Pause after the last keystroke before checking and saving.
const CHECK_DELAY: Duration = Duration::from_millis(300);
/// Typing within this many milliseconds of the last snapshot joins the same undo step.
const COALESCE_MS: f64 = 1000.0;
/// Undo steps kept.
const HISTORY_MAX: usize = 300;

/// The text area's content and selection (UTF-16 offsets, as the DOM counts).
#[derive(Debug, Clone, PartialEq, Default)]
struct Snap {
    text: String,
    start: u32,
    end: u32,
}

/// The editor's undo and redo stacks.
#[derive(Debug, Clone, Default)]
struct History {
    undo: Vec<Snap>,
    redo: Vec<Snap>,
    /// When the last undo step was recorded by typing (None after any other edit).
    last_typing_ms: Option<f64>,
}

/// Everything the editor's handlers share (all handles, so it is `Copy`).
#[derive(Clone, Copy)]
struct Ed {
    state: AppState,
    ta: NodeRef<html::Textarea>,
    hl: NodeRef<html::Pre>,
    gutter: NodeRef<html::Div>,
    history: RwSignal<History>,
    /// The text area as of the last change or caret move.
    current: StoredValue<Snap>,
    /// Caret line and column (1-based).
    cursor: RwSignal<(usize, usize)>,
    /// Debounce generation: a pending check runs only if no keystroke came after it.
    generation: StoredValue<u64>,
    /// A check is scheduled but has not run yet.
    pending: StoredValue<bool>,
    /// Escape was pressed: the next Tab moves focus instead of indenting.
    tab_leaves: StoredValue<bool>,
    /// Tab indents (turned on and off with Ctrl+M, kept in local storage); off, Tab moves
    /// focus as everywhere else on the page, so the editor is never a keyboard trap.
    tab_indents: RwSignal<bool>,
}

/// The local storage key noting that Tab indents in the ST editor.
const TAB_INDENTS_KEY: &str = "plc-trainer/v1/tab-indents";

/// The editor's hint about Tab, shown under the text (`Ctrl+M` switches).
fn tab_hint(indents: bool) -> &'static str {
    t(if indents { K::editor_tab_indents } else { K::editor_tab_moves_focus })
}

impl Ed {
    fn textarea(&self) -> Option<HtmlTextAreaElement> {
        self.ta.get_untracked()
    }

    fn read(&self) -> Option<Snap> {
        let ta = self.textarea()?;
        let text = ta.value();
        let start = ta.selection_start().ok().flatten().unwrap_or(0);
        let end = ta.selection_end().ok().flatten().unwrap_or(start);
        Some(Snap { text, start, end })
    }

    /// Updates the caret status (and the remembered selection) from the text area.
    fn sync_cursor(&self) {
        let Some(snap) = self.read() else { return };
        let byte = utf16_to_byte(&snap.text, snap.end);
        self.cursor.set(line_col(&snap.text, byte));
        self.current.update_value(|c| {
            if c.text == snap.text {
                c.start = snap.start;
                c.end = snap.end;
            }
        });
    }

    /// The text changed: store it, and check and save after a pause.
    fn changed(&self, text: String) {
        self.state.set_source(text);
        self.generation.update_value(|g| *g += 1);
        self.pending.set_value(true);
        let generation = self.generation.get_value();
        let ed = *self;
        set_timeout(
            move || {
                if ed.generation.try_get_value() == Some(generation) {
                    ed.flush();
                }
            },
            CHECK_DELAY,
        );
    }

    /// Runs a pending check and save now.
    fn flush(&self) {
        if self.pending.try_get_value() != Some(true) {
            return;
        }
        self.pending.set_value(false);
        // Run may have checked this text already (a check restarts the simulator).
        self.state.check_if_pending();
        self.state.save();
    }

    /// The user typed, pasted or cut (a native edit).
    fn on_input(&self) {
        let Some(new) = self.read() else { return };
        let before = self.current.get_value();
        let now = js_sys::Date::now();
        self.history.update(|h| {
            let joins = h.last_typing_ms.is_some_and(|t| now - t < COALESCE_MS);
            if !joins {
                push_capped(&mut h.undo, before);
                h.last_typing_ms = Some(now);
            }
            h.redo.clear();
        });
        self.current.set_value(new.clone());
        self.sync_cursor();
        self.changed(new.text);
    }

    /// Puts a snapshot into the text area (no history change).
    fn put(&self, snap: &Snap) {
        let Some(ta) = self.textarea() else { return };
        if ta.value() != snap.text {
            // Replacing the value may reset the scroll position: keep it.
            let (top, left) = (ta.scroll_top(), ta.scroll_left());
            ta.set_value(&snap.text);
            ta.set_scroll_top(top);
            ta.set_scroll_left(left);
        }
        let _ = ta.set_selection_range(snap.start, snap.end);
        self.current.set_value(snap.clone());
        self.sync_cursor();
        self.changed(snap.text.clone());
        self.sync_scroll();
    }

    /// Applies an edit the editor computed (Tab, Enter …) as one undo step.
    fn apply(&self, edit: Edit) {
        let before = self.current.get_value();
        let snap = Snap {
            start: byte_to_utf16(&edit.text, edit.start),
            end: byte_to_utf16(&edit.text, edit.end),
            text: edit.text,
        };
        self.history.update(|h| {
            push_capped(&mut h.undo, before);
            h.redo.clear();
            h.last_typing_ms = None;
        });
        self.put(&snap);
    }

    fn undo(&self) {
        let current = self.read().unwrap_or_else(|| self.current.get_value());
        let mut target = None;
        self.history.update(|h| {
            if let Some(s) = h.undo.pop() {
                push_capped(&mut h.redo, current);
                target = Some(s);
            }
            h.last_typing_ms = None;
        });
        if let Some(s) = target {
            self.put(&s);
        }
    }

    fn redo(&self) {
        let current = self.read().unwrap_or_else(|| self.current.get_value());
        let mut target = None;
        self.history.update(|h| {
            if let Some(s) = h.redo.pop() {
                push_capped(&mut h.undo, current);
                target = Some(s);
            }
            h.last_typing_ms = None;
        });
        if let Some(s) = target {
            self.put(&s);
        }
    }

    /// The selection as byte offsets into the current text.
    fn selection_bytes(&self) -> Option<(String, usize, usize)> {
        let snap = self.read()?;
        let s = utf16_to_byte(&snap.text, snap.start);
        let e = utf16_to_byte(&snap.text, snap.end);
        Some((snap.text, s, e))
    }

    fn on_keydown(&self, ev: &web_sys::KeyboardEvent) {
        if ev.is_composing() {
            return;
        }
        let key = ev.key();
        let ctrl = ev.ctrl_key() || ev.meta_key();
        let tab_leaves = self.tab_leaves.get_value();
        self.tab_leaves.set_value(key == "Escape");
        match key.as_str() {
            k if ctrl && !ev.alt_key() && !ev.shift_key() && k.eq_ignore_ascii_case("m") => {
                ev.prevent_default();
                let on = !self.tab_indents.get_untracked();
                self.tab_indents.set(on);
                let mut store = crate::storage::LocalStorage::open();
                let _ = if on {
                    store.set(TAB_INDENTS_KEY, "on")
                } else {
                    store.remove(TAB_INDENTS_KEY)
                };
            }
            "Tab" if !ctrl && !ev.alt_key() && !tab_leaves && self.tab_indents.get_untracked() => {
                ev.prevent_default();
                if let Some((text, s, e)) = self.selection_bytes() {
                    let edit = if ev.shift_key() {
                        text::outdent(&text, s, e)
                    } else {
                        text::indent(&text, s, e)
                    };
                    if edit.text != text || edit.start != s || edit.end != e {
                        self.apply(edit);
                    }
                }
            }
            "Enter" if !ctrl && !ev.alt_key() && !ev.shift_key() => {
                ev.prevent_default();
                if let Some((text, s, e)) = self.selection_bytes() {
                    self.apply(text::newline(&text, s, e));
                }
            }
            k if ctrl && !ev.alt_key() && k.eq_ignore_ascii_case("z") => {
                ev.prevent_default();
                if ev.shift_key() {
                    self.redo();
                } else {
                    self.undo();
                }
            }
            k if ctrl && !ev.alt_key() && !ev.shift_key() && k.eq_ignore_ascii_case("y") => {
                ev.prevent_default();
                self.redo();
            }
            _ => {}
        }
    }

    /// Keeps the highlight layer and the gutter scrolled with the text area.
    fn sync_scroll(&self) {
        let Some(ta) = self.textarea() else { return };
        let (top, left) = (ta.scroll_top(), ta.scroll_left());
        if let Some(pre) = self.hl.get_untracked() {
            pre.set_scroll_top(top);
            pre.set_scroll_left(left);
        }
        if let Some(g) = self.gutter.get_untracked() {
            g.set_scroll_top(top);
        }
    }

    /// Moves the caret to 1-based `line` and character `column`, focuses the text area
    /// and scrolls the place into view.
    fn jump(&self, line: u32, column: u32) {
        let Some(ta) = self.textarea() else { return };
        let text = ta.value();
        let byte = offset_of(&text, line, column);
        let u = byte_to_utf16(&text, byte);
        let _ = ta.focus();
        let _ = ta.set_selection_range(u, u);
        let (line, col) = line_col(&text, byte);
        let y = PAD_PX + (line as i32 - 1) * LINE_PX;
        let height = ta.client_height();
        if y < ta.scroll_top() || y + LINE_PX > ta.scroll_top() + height {
            ta.set_scroll_top((y - height / 3).max(0));
        }
        // Roughly 8.4 px per character in the monospace font at 14 px.
        let x = (col as f64 * 8.4) as i32;
        let width = ta.client_width();
        if x < ta.scroll_left() || x > ta.scroll_left() + width - 40 {
            ta.set_scroll_left((x - width / 2).max(0));
        }
        self.sync_scroll();
        self.sync_cursor();
    }
}

fn push_capped(stack: &mut Vec<Snap>, snap: Snap) {
    if stack.last() == Some(&snap) {
        return;
    }
    stack.push(snap);
    if stack.len() > HISTORY_MAX {
        stack.remove(0);
    }
}

/// The ST editor with its gutter, problem list and status line.
#[component]
pub fn Editor() -> impl IntoView {
    let state = expect_context::<AppState>();
    let ed = Ed {
        state,
        ta: NodeRef::new(),
        hl: NodeRef::new(),
        gutter: NodeRef::new(),
        history: RwSignal::new(History::default()),
        current: StoredValue::new(Snap::default()),
        cursor: RwSignal::new((1, 1)),
        generation: StoredValue::new(0),
        pending: StoredValue::new(false),
        tab_leaves: StoredValue::new(false),
        tab_indents: RwSignal::new(
            crate::storage::LocalStorage::open().get(TAB_INDENTS_KEY).ok().flatten().is_some(),
        ),
    };

    // The project's source → the text area (on open, import, or any change made elsewhere).
    Effect::new(move |_| {
        let Some(ta) = ed.ta.get() else { return };
        let source = state.project.with(|p| p.source.clone());
        if ta.value() != source {
            ta.set_value(&source);
            let _ = ta.set_selection_range(0, 0);
            ed.current.set_value(Snap { text: source, start: 0, end: 0 });
            ed.sync_cursor();
            ed.sync_scroll();
        }
    });
    // Another project: its own history.
    Effect::new(move |_| {
        state.project_id.track();
        ed.history.set(History::default());
    });
    // Jump requests (the fault banner's "Go to line", a clicked problem) and quick fixes
    // from the problem list (`Replace with NAME`, `Declare NAME`: one undo step each, the
    // caret at the fix), once the editor is mounted and shown.
    Effect::new(move |_| {
        let mounted = ed.ta.get().is_some() && state.view.get() == PouView::St;
        let (jump, fix) = (state.jump_to.get(), state.st_fix.get());
        if !mounted {
            return;
        }
        if let Some((line, column)) = jump {
            ed.jump(line, column);
            state.jump_to.set(None);
        }
        if let Some((text, caret)) = fix {
            state.st_fix.set(None);
            let caret = text::floor_boundary(&text, caret);
            ed.apply(Edit { text, start: caret, end: caret });
            ed.flush();
            if let Some(ta) = ed.textarea() {
                let _ = ta.focus();
            }
        }
    });
    // Never lose the last keystrokes when the page closes.
    let _ = window_event_listener(ev::beforeunload, move |_| ed.flush());

    let highlighted = Memo::new(move |_| {
        let marks: Vec<Mark> = state.diagnostics.with(|ds| {
            ds.iter()
                .filter_map(|d| {
                    let (_, _, start, end) = d.st()?;
                    Some(Mark { start: start as usize, end: end as usize, error: d.error })
                })
                .collect()
        });
        state.project.with(|p| text::highlight_html(&p.source, &marks))
    });
    let gutter = Memo::new(move |_| {
        let lines = state.project.with(|p| p.source.split('\n').count());
        let mut info: BTreeMap<usize, LineInfo> = BTreeMap::new();
        state.diagnostics.with(|ds| {
            for d in ds {
                let Some((line, ..)) = d.st() else { continue };
                let li = info.entry(line as usize).or_default();
                li.diag = Some(li.diag.unwrap_or(false) || d.error);
                li.messages.push(format!("{}  {}", d.code, d.message()));
            }
        });
        let marked = state.marked_line.get().map(|l| l as usize);
        text::gutter_html(lines, &info, marked)
    });
    let marked_band = move || {
        state.marked_line.get().map(|l| {
            let top = PAD_PX + (l.max(1) as i32 - 1) * LINE_PX;
            view! { <div class="ed-marked" style=format!("top: {top}px")></div> }
        })
    };

    // The branch each CASE took on the last scan, lit while the program runs.
    let active_bands = move || {
        state
            .active_lines
            .get()
            .into_iter()
            .map(|l| {
                let top = PAD_PX + (l.max(1) as i32 - 1) * LINE_PX;
                view! { <div class="ed-active" style=format!("top: {top}px")></div> }
            })
            .collect_view()
    };

    // `Why is NAME TRUE?` for the assignment on the caret's line (issue 36), while the
    // program runs and the variable can be read.
    let assigned = Memo::new(move |_| {
        let line = ed.cursor.get().0;
        state.project.with(|p| assigned_on(&p.source, line))
    });
    let line_why = move || {
        let name = assigned.get()?;
        let value = state.read(&name)?;
        let label = why_label(&name, &value);
        Some(
            view! {
                <button class="small" aria-label=label.clone() title=label
                    on:click=move |_| state.ask_why(&name)>{t(K::why_title)}</button>
            }
            .into_any(),
        )
    };

    view! {
        <div class="panel editor">
            <div class="ed-toolbar">
                <h2>{t(K::editor_structured_text)}</h2>
                <span class="ed-spacer"></span>
                <button on:click=move |_| { ed.undo(); if let Some(t) = ed.textarea() { let _ = t.focus(); } }
                    disabled=move || ed.history.with(|h| h.undo.is_empty()) title=t(K::editor_undo_title)>{t(K::editor_undo)}</button>
                <button on:click=move |_| { ed.redo(); if let Some(t) = ed.textarea() { let _ = t.focus(); } }
                    disabled=move || ed.history.with(|h| h.redo.is_empty()) title=t(K::editor_redo_title)>{t(K::editor_redo)}</button>
            </div>
            <div class="ed-frame" class:ed-running=move || state.marked_line.get().is_some()>
                <div class="ed-gutter" aria-hidden="true" node_ref=ed.gutter inner_html=move || gutter.get()></div>
                <div class="ed-code">
                    <pre class="ed-hl" aria-hidden="true" node_ref=ed.hl>
                        {active_bands}
                        {marked_band}
                        <code inner_html=move || highlighted.get()></code>
                    </pre>
                    <textarea
                        class="ed-input"
                        node_ref=ed.ta
                        aria-label=t(K::editor_st_source)
                        aria-describedby="ed-tab-hint"
                        aria-keyshortcuts="Control+M"
                        spellcheck="false"
                        autocapitalize="off"
                        autocomplete="off"
                        wrap="off"
                        on:input=move |_| ed.on_input()
                        on:keydown=move |ev| ed.on_keydown(&ev)
                        on:keyup=move |_| ed.sync_cursor()
                        on:click=move |_| ed.sync_cursor()
                        on:select=move |_| ed.sync_cursor()
                        on:focus=move |_| ed.sync_cursor()
                        on:scroll=move |_| ed.sync_scroll()
                        on:blur=move |_| ed.flush()
                    ></textarea>
                </div>
            </div>
            <div class="ed-status">
                <span>{move || { let (l, c) = ed.cursor.get(); tf(K::editor_cursor, &[("line", &l.to_string()), ("column", &c.to_string())]) }}</span>
                {line_why}
                <span id="ed-tab-hint" class="ed-tab-hint" aria-live="polite">{move || tab_hint(ed.tab_indents.get())}</span>
            </div>
        </div>
    }
}

/// The variable assigned on 1-based `line` of `source` (`Motor := …;` gives `Motor`).
fn assigned_on(source: &str, line: usize) -> Option<String> {
    let text = source.split('\n').nth(line.checked_sub(1)?)?;
    let (target, _) = text.split_once(":=")?;
    let target = target.trim();
    let ok = target.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && target.chars().all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '[' | ']'));
    ok.then(|| target.to_string())
}
