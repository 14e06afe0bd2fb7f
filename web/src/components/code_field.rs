//! A small ST editor for a piece of a POU (a ladder POU's declarations, a place's actions,
//! a transition's guard): the main editor's highlighting, squiggles and gutter markers (its
//! `text` module) over a text area the browser edits natively, so its own undo, selection
//! and IME work. A pause in typing, or leaving the field, hands the text to the owner (one
//! model edit, which the owner's history joins with the typing before it).

use std::collections::BTreeMap;
use std::time::Duration;

use leptos::html;
use leptos::prelude::*;

use crate::components::editor::text::{
    byte_to_utf16, gutter_html, highlight_html, offset_of, LineInfo, Mark,
};
use crate::i18n::plural;
use crate::i18n::{t, tf, K};

/// Pause after the last keystroke before the text is handed over.
const COMMIT_DELAY: Duration = Duration::from_millis(300);
/// Must match `--ed-line` and `--ed-pad` in style.css.
const LINE_PX: usize = 20;
const PAD_PX: usize = 8;

/// A problem shown in a code field: 1-based line and column, whether it is an error, and
/// its message.
pub type FieldProblem = (u32, u32, bool, String);

/// The byte span of the word at 1-based `line`, `column` of `text` (at least one character,
/// so a problem at the end of a line still shows).
pub fn word_at(text: &str, line: u32, column: u32) -> (usize, usize) {
    let start = offset_of(text, line, column);
    let rest = &text[start..];
    let len = rest
        .char_indices()
        .find(|(_, c)| !(c.is_alphanumeric() || *c == '_' || *c == '%' || *c == '.'))
        .map_or(rest.len(), |(i, _)| i);
    let len = if len == 0 { rest.chars().next().map_or(0, char::len_utf8) } else { len };
    (start, start + len)
}

/// The code field (see the module comment). `text` is the model's text; `on_commit` gets
/// the typed text; `on_leave` is called when the field loses the focus (after the commit);
/// `reveal` asks for the caret at a line and column (a clicked problem).
#[component]
pub fn CodeField(
    #[prop(into)] label: String,
    text: Signal<String>,
    on_commit: Callback<String>,
    #[prop(optional)] on_leave: Option<Callback<()>>,
    problems: Signal<Vec<FieldProblem>>,
    #[prop(optional)] reveal: Option<Signal<Option<(u32, u32)>>>,
    #[prop(default = 5)] min_rows: usize,
    #[prop(default = 18)] max_rows: usize,
) -> impl IntoView {
    let ta = NodeRef::<html::Textarea>::new();
    let hl = NodeRef::<html::Pre>::new();
    let gutter = NodeRef::<html::Div>::new();
    // The text as typed: ahead of the model until the pending commit is made.
    let draft = RwSignal::new(text.get_untracked());
    let generation = StoredValue::new(0u64);
    let pending = StoredValue::new(false);
    let commit = move || {
        if !pending.get_value() {
            return;
        }
        pending.set_value(false);
        let typed = draft.get_untracked();
        if text.with_untracked(|t| *t != typed) {
            on_commit.run(typed);
        }
    };
    // The model's text changed elsewhere (undo, a declaration added for the user): show it.
    Effect::new(move |_| {
        let model = text.get();
        if pending.get_value() || draft.get_untracked() == model {
            return;
        }
        draft.set(model.clone());
        if let Some(el) = ta.get_untracked() {
            el.set_value(&model);
        }
    });
    let highlighted = Memo::new(move |_| {
        draft.with(|t| {
            let marks: Vec<Mark> = problems.with(|ps| {
                ps.iter()
                    .map(|(line, column, error, _)| {
                        let (start, end) = word_at(t, *line, *column);
                        Mark { start, end, error: *error }
                    })
                    .collect()
            });
            highlight_html(t, &marks)
        })
    });
    let lines = Memo::new(move |_| draft.with(|t| t.split('\n').count()));
    let gutter_text = Memo::new(move |_| {
        let mut info: BTreeMap<usize, LineInfo> = BTreeMap::new();
        problems.with(|ps| {
            for (line, _, error, message) in ps {
                let li = info.entry(*line as usize).or_default();
                li.diag = Some(li.diag.unwrap_or(false) || *error);
                li.messages.push(message.clone());
            }
        });
        gutter_html(lines.get(), &info, None)
    });
    let height = move || {
        let rows = lines.get().clamp(min_rows, max_rows.max(min_rows));
        format!("height:{}px", rows * LINE_PX + 2 * PAD_PX + 4)
    };
    let sync_scroll = move || {
        let Some(el) = ta.get_untracked() else { return };
        if let Some(pre) = hl.get_untracked() {
            pre.set_scroll_top(el.scroll_top());
            pre.set_scroll_left(el.scroll_left());
        }
        if let Some(g) = gutter.get_untracked() {
            g.set_scroll_top(el.scroll_top());
        }
    };
    if let Some(reveal) = reveal {
        Effect::new(move |_| {
            let Some((line, column)) = reveal.get() else { return };
            // On the next frame: the field may be in a disclosure that opens first.
            request_animation_frame(move || {
                let Some(el) = ta.get_untracked() else { return };
                let value = el.value();
                let at = byte_to_utf16(&value, offset_of(&value, line, column));
                let _ = el.focus();
                let _ = el.set_selection_range(at, at);
                sync_scroll();
            });
        });
    }
    let on_input = move |ev| {
        draft.set(event_target_value(&ev));
        pending.set_value(true);
        generation.update_value(|g| *g += 1);
        let mine = generation.get_value();
        set_timeout(
            move || {
                if generation.try_get_value() == Some(mine) {
                    commit();
                }
            },
            COMMIT_DELAY,
        );
    };
    view! {
        <div class="ed-frame code-field" style=height>
            <div class="ed-gutter" aria-hidden="true" node_ref=gutter inner_html=move || gutter_text.get()></div>
            <div class="ed-code">
                <pre class="ed-hl" aria-hidden="true" node_ref=hl>
                    <code inner_html=move || highlighted.get()></code>
                </pre>
                <textarea class="ed-input" node_ref=ta aria-label=label spellcheck="false"
                    autocapitalize="off" autocomplete="off" wrap="off"
                    prop:value=draft.get_untracked()
                    on:input=on_input
                    on:scroll=move |_| sync_scroll()
                    on:blur=move |_| {
                        commit();
                        if let Some(leave) = on_leave {
                            leave.run(());
                        }
                    }></textarea>
            </div>
        </div>
    }
}

/// A POU's `Declarations`: a [`CodeField`] in a disclosure that says how many problems they
/// have and opens when one of them is revealed (ladder and Petri net POUs alike).
#[component]
pub fn DeclarationsBox(
    open: RwSignal<bool>,
    text: Signal<String>,
    on_commit: Callback<String>,
    on_leave: Callback<()>,
    problems: Signal<Vec<FieldProblem>>,
    reveal: Signal<Option<(u32, u32)>>,
) -> impl IntoView {
    Effect::new(move |_| {
        if reveal.get().is_some() {
            open.set(true);
        }
    });
    let count = move || problems.with(Vec::len);
    view! {
        <details class="ld-decls" prop:open=move || open.get()
            on:toggle=move |ev| {
                use wasm_bindgen::JsCast;
                let now = ev.target().and_then(|t| t.dyn_into::<web_sys::HtmlDetailsElement>().ok()).is_some_and(|d| d.open());
                if now != open.get_untracked() {
                    open.set(now);
                }
            }>
            <summary>{t(K::editor_declarations)}
                {move || (count() > 0).then(|| view! {
                    <span class="ld-decl-count">{tf(plural(count() as u64, K::editor_problem_count_one, K::editor_problem_count_few, K::editor_problem_count_many), &[("n", &count().to_string())])}</span>
                })}
            </summary>
            <CodeField label=t(K::editor_declarations) text=text on_commit=on_commit on_leave=on_leave
                problems=problems reveal=reveal/>
        </details>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_problem_marks_the_word_it_points_at() {
        let text = "VAR\n  T1 : TONN;\nEND_VAR";
        let (s, e) = word_at(text, 2, 8);
        assert_eq!(&text[s..e], "TONN");
        let (s, e) = word_at(text, 2, 12);
        assert_eq!(&text[s..e], ";");
        let (s, e) = word_at(text, 3, 8);
        assert_eq!((s, e), (text.len(), text.len()));
    }
}
