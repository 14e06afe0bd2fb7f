//! The `Help` menu of the header: `Start here` (the guided tour from its first step),
//! `Keyboard shortcuts` (a dialog listing the keys the editors take) and `Problems
//! explained` (the static page of every problem code, `problems.html`).

use leptos::ev;
use leptos::html;
use leptos::prelude::*;

use crate::components::tour::Tour;

/// The keys of the app, by where they work (read from the editors' key handlers; keep in
/// step with them).
const SHORTCUTS: &[(&str, &[(&str, &str)])] = &[
    (
        "ST editor",
        &[
            ("Ctrl+Z", "Undo"),
            ("Ctrl+Shift+Z or Ctrl+Y", "Redo"),
            ("Tab / Shift+Tab", "Indent / outdent the selected lines"),
            ("Enter", "New line, keeping the indentation"),
            ("Escape, then Tab", "Leave the editor (Tab indents otherwise)"),
        ],
    ),
    (
        "Ladder rungs (on a selected cell)",
        &[
            ("Arrow keys", "Select the next cell"),
            ("c / n", "NO contact / NC contact"),
            ("o / s / r", "Coil / set coil / reset coil"),
            ("w / l", "Wire / link down"),
            ("b", "Pick a block"),
            ("Enter or F2", "Edit the operand (a block: its pins)"),
            ("Delete or Backspace", "Clear the cell"),
            ("Ctrl+C / Ctrl+V", "Copy the rung / paste it below"),
            ("Ctrl+Z / Ctrl+Shift+Z or Ctrl+Y", "Undo / redo"),
            ("Ctrl or Alt while dropping", "Copy the dragged element instead of moving it"),
        ],
    ),
    (
        "Ladder operand box",
        &[
            ("Arrow Down / Up", "Choose among the matching names"),
            ("Tab", "Take the chosen name"),
            ("Enter", "Commit the operand"),
            ("Escape", "Take the placement back"),
        ],
    ),
    (
        "Petri net canvas",
        &[
            ("Arrow keys", "Move the selected place or transition by one grid step"),
            ("Enter", "Open its properties"),
            ("Delete or Backspace", "Delete the selection with its arcs"),
            ("Escape", "Back to the Select tool"),
            ("Ctrl+Z / Ctrl+Shift+Z or Ctrl+Y", "Undo / redo"),
        ],
    ),
    (
        "Simulation",
        &[
            ("Space or Enter", "Flip a switch (a push button: held while the key is down)"),
            ("Enter / Escape", "Commit / cancel a value typed in the variable table"),
        ],
    ),
];

/// The shortcut tables as HTML (the text is this file's constants).
fn shortcuts_html() -> String {
    let mut html = String::new();
    for (area, keys) in SHORTCUTS {
        html.push_str(&format!("<table class=\"shortcut-table\"><caption>{area}</caption><tbody>"));
        for (k, what) in *keys {
            html.push_str(&format!(
                "<tr><th scope=\"row\"><kbd>{k}</kbd></th><td>{what}</td></tr>"
            ));
        }
        html.push_str("</tbody></table>");
    }
    html
}

/// The `Help` button and its menu, with the shortcuts dialog.
#[component]
pub fn HelpMenu() -> impl IntoView {
    let tour = expect_context::<Tour>();
    let open = RwSignal::new(false);
    let wrap = NodeRef::<html::Div>::new();
    let button = NodeRef::<html::Button>::new();
    let menu = NodeRef::<html::Ul>::new();
    let dialog = NodeRef::<html::Dialog>::new();

    let items = move || -> Vec<web_sys::HtmlElement> {
        use wasm_bindgen::JsCast;
        let Some(menu) = menu.get_untracked() else { return Vec::new() };
        let Ok(list) = menu.query_selector_all("[role=menuitem]") else { return Vec::new() };
        (0..list.length())
            .filter_map(|i| list.item(i)?.dyn_into::<web_sys::HtmlElement>().ok())
            .collect()
    };
    let focus_item = move |index: i32| {
        let items = items();
        if items.is_empty() {
            return;
        }
        let n = items.len() as i32;
        let _ = items[index.rem_euclid(n) as usize].focus();
    };
    let close = move |refocus: bool| {
        open.set(false);
        if refocus {
            if let Some(b) = button.get_untracked() {
                let _ = b.focus();
            }
        }
    };
    // The menu's first item takes the focus when it opens.
    Effect::new(move |_| {
        if open.get() {
            request_animation_frame(move || focus_item(0));
        }
    });
    // A press anywhere else closes it.
    let outside = window_event_listener(ev::pointerdown, move |e| {
        use wasm_bindgen::JsCast;
        if !open.get_untracked() {
            return;
        }
        let target = e.target().and_then(|t| t.dyn_into::<web_sys::Node>().ok());
        let inside = wrap.get_untracked().is_some_and(|w| w.contains(target.as_ref()));
        if !inside {
            open.set(false);
        }
    });
    on_cleanup(move || outside.remove());

    let on_menu_key = move |e: ev::KeyboardEvent| {
        let items = items();
        let active = web_sys::window().and_then(|w| w.document()).and_then(|d| d.active_element());
        let at = items
            .iter()
            .position(|i| active.as_ref().is_some_and(|a| a.is_same_node(Some(i))))
            .map_or(-1, |p| p as i32);
        match e.key().as_str() {
            "ArrowDown" => focus_item(at + 1),
            "ArrowUp" => focus_item(if at < 0 { -1 } else { at - 1 }),
            "Home" => focus_item(0),
            "End" => focus_item(-1),
            "Escape" => close(true),
            "Tab" => {
                open.set(false);
                return;
            }
            _ => return,
        }
        e.prevent_default();
    };
    let show_shortcuts = move |_| {
        open.set(false);
        if let Some(d) = dialog.get_untracked() {
            let _ = d.show_modal();
        }
    };

    view! {
        <div class="help-menu" node_ref=wrap>
            <button class="header-button" node_ref=button aria-haspopup="menu"
                aria-expanded=move || open.get().to_string()
                on:click=move |_| open.update(|o| *o = !*o)
                on:keydown=move |e: ev::KeyboardEvent| if e.key() == "ArrowDown" {
                    e.prevent_default();
                    open.set(true);
                }>"Help"</button>
            <ul class="menu" role="menu" aria-label="Help" node_ref=menu hidden=move || !open.get()
                on:keydown=on_menu_key>
                <li role="none">
                    <button role="menuitem" tabindex="-1"
                        on:click=move |_| { close(false); tour.restart(); }>"Start here"</button>
                </li>
                <li role="none">
                    <button role="menuitem" tabindex="-1" on:click=show_shortcuts>"Keyboard shortcuts"</button>
                </li>
                <li role="none">
                    <a role="menuitem" tabindex="-1" href="problems.html" target="_blank" rel="noopener"
                        on:click=move |_| close(false)>"Problems explained"</a>
                </li>
            </ul>
            <dialog class="app-dialog shortcuts" node_ref=dialog aria-labelledby="shortcuts-title">
                <h2 id="shortcuts-title">"Keyboard shortcuts"</h2>
                <p class="muted">"On a Mac, Cmd works where Ctrl is written."</p>
                // Fixed text of this file: one block of HTML, not a view per row.
                // Focused first (not the Close button below), so the list opens at its top
                // and the arrow keys scroll it.
                <div class="shortcut-list" tabindex="0" autofocus=true aria-label="Shortcuts"
                    inner_html=shortcuts_html()></div>
                <form method="dialog" class="dialog-actions">
                    <button class="primary">"Close"</button>
                </form>
            </dialog>
        </div>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shortcuts_are_plain_text_in_tables() {
        let html = shortcuts_html();
        assert_eq!(html.matches("<table").count(), SHORTCUTS.len());
        assert!(html.contains("<caption>Ladder rungs (on a selected cell)</caption>"));
        assert!(html.contains(
            "<tr><th scope=\"row\"><kbd>c / n</kbd></th><td>NO contact / NC contact</td></tr>"
        ));
        // Inserted as HTML: the texts must hold no markup of their own.
        for (area, keys) in SHORTCUTS {
            let texts = std::iter::once(*area).chain(keys.iter().flat_map(|(k, w)| [*k, *w]));
            for t in texts {
                assert!(!t.contains(['<', '>', '&']), "{t}");
            }
        }
    }
}
