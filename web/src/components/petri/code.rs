//! The generated CASE OF program beside the net: read-only, highlighted like the ST editor,
//! with the branch each process took on the last scan lit (and scrolled into view), the
//! selected element's lines marked, and a click on a line reported (to select its element).

use std::collections::BTreeMap;

use leptos::html;
use leptos::prelude::*;

use crate::components::editor::text::{gutter_html, highlight_html};
use crate::i18n::{t, K};

/// Line height of the code view in pixels (must match `--code-line` in style.css).
const LINE_PX: f64 = 18.0;
/// Top padding of the code view in pixels (must match `--code-pad`).
const PAD_PX: f64 = 6.0;

fn indent(line: &str) -> usize {
    line.chars().take_while(|c| *c == ' ' || *c == '\t').count()
}

/// Whether a line starts with a CASE label (`31:`, `1, 2:`, `10..19:`), not `x := …`.
fn is_label(line: &str) -> bool {
    let t = line.trim_start();
    let Some((head, rest)) = t.split_once(':') else { return false };
    !head.trim().is_empty()
        && !rest.starts_with('=')
        && head.chars().all(|c| c.is_ascii_digit() || matches!(c, ',' | '.' | ' ' | '-' | '_'))
}

/// The first and last 1-based lines of the CASE branch whose first statement is on
/// `stmt_line`: from its label line to the last line indented deeper than the label.
/// Falls back to the statement's line alone when no label is found above it.
pub fn branch_lines(code: &str, stmt_line: u32) -> (u32, u32) {
    let lines: Vec<&str> = code.lines().collect();
    if lines.is_empty() {
        return (1, 1);
    }
    let i = (stmt_line.max(1) as usize - 1).min(lines.len() - 1);
    let label = if is_label(lines[i]) {
        i
    } else {
        let s = indent(lines[i]);
        let above = (0..i).rev().find(|&j| !lines[j].trim().is_empty() && indent(lines[j]) < s);
        match above {
            Some(j) if is_label(lines[j]) => j,
            _ => return (i as u32 + 1, i as u32 + 1),
        }
    };
    let depth = indent(lines[label]);
    let mut last = label;
    for (k, line) in lines.iter().enumerate().skip(label + 1) {
        if line.trim().is_empty() {
            continue;
        }
        if indent(line) <= depth {
            break;
        }
        last = k;
    }
    (label as u32 + 1, last as u32 + 1)
}

/// The code view. `active` holds the 1-based lines of the statements the CASEs ran.
#[component]
pub fn CodePanel(
    /// The generated program (empty when the net does not compile).
    code: Signal<String>,
    /// The lines of the first statements of the active branches.
    active: Signal<Vec<u32>>,
    /// Line ranges to mark as the selected element's (first and last, 1-based).
    #[prop(optional)]
    marked: Option<Signal<Vec<(u32, u32)>>>,
    /// Called with the 1-based line a click landed on.
    #[prop(optional)]
    on_line: Option<Callback<u32>>,
) -> impl IntoView {
    let frame = NodeRef::<html::Div>::new();
    let html = Memo::new(move |_| code.with(|c| highlight_html(c, &[])));
    let gutter =
        Memo::new(move |_| code.with(|c| gutter_html(c.lines().count(), &BTreeMap::new(), None)));
    let branches = Memo::new(move |_| {
        let mut b: Vec<(u32, u32)> =
            code.with(|c| active.get().iter().map(|&l| branch_lines(c, l)).collect());
        plc_core::order::sort(&mut b);
        b.dedup();
        b
    });
    // Keep the first lit branch in view while the program runs.
    Effect::new(move |_| {
        let Some((first, last)) = branches.get().first().copied() else { return };
        let Some(el) = frame.get() else { return };
        let top = PAD_PX + (first as f64 - 1.0) * LINE_PX;
        let bottom = PAD_PX + last as f64 * LINE_PX;
        let (scroll, height) = (el.scroll_top() as f64, el.client_height() as f64);
        if top < scroll || bottom > scroll + height {
            el.set_scroll_top((top - height / 4.0).max(0.0) as i32);
        }
    });
    let bands = move || {
        let text = code.get();
        let lines: Vec<&str> = text.lines().collect();
        branches
            .get()
            .into_iter()
            .map(|(first, last)| {
                let top = PAD_PX + (first as f64 - 1.0) * LINE_PX;
                let height = (last - first + 1) as f64 * LINE_PX;
                let label = lines.get(first as usize - 1).map(|l| l.trim()).unwrap_or_default();
                view! {
                    <div class="code-active" data-first=first data-last=last data-text=label.to_string()
                        style=format!("top: {top}px; height: {height}px")></div>
                }
            })
            .collect_view()
    };
    let selected_bands = move || {
        marked
            .map(|m| m.get())
            .unwrap_or_default()
            .into_iter()
            .map(|(first, last)| {
                let top = PAD_PX + (first as f64 - 1.0) * LINE_PX;
                let height = (last.max(first) - first + 1) as f64 * LINE_PX;
                view! {
                    <div class="code-selected" data-first=first data-last=last
                        style=format!("top: {top}px; height: {height}px")></div>
                }
            })
            .collect_view()
    };
    let click = move |ev: leptos::ev::MouseEvent| {
        let Some(on_line) = on_line else { return };
        use wasm_bindgen::JsCast;
        let Some(pre) = ev.current_target().and_then(|t| t.dyn_into::<web_sys::Element>().ok())
        else {
            return;
        };
        let y = f64::from(ev.client_y()) - pre.get_bounding_client_rect().top() - PAD_PX;
        if y >= 0.0 {
            on_line.run((y / LINE_PX) as u32 + 1);
        }
    };
    view! {
        <div class="code-frame" node_ref=frame tabindex="0">
            <div class="ed-gutter code-gutter" aria-hidden="true" inner_html=move || gutter.get()></div>
            <pre class="code-view code-lines" aria-label=t(K::petri_generated_code) on:click=click>
                {selected_bands}
                {bands}
                <code inner_html=move || html.get()></code>
            </pre>
        </div>
    }
}

#[cfg(test)]
mod tests;
