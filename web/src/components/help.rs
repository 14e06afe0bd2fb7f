//! The `Help` menu of the header: `Start here` (the guided tour from its first step),
//! `Keyboard shortcuts` (a dialog listing the keys the editors take) and `Problems
//! explained` (the static page of every problem code, `problems.html`).

use leptos::ev;
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
            ("Tab / Shift+Tab", "Move to the next / previous control, or with Tab indenting on, indent / outdent the selected lines"),
            ("Ctrl+M", "Turn Tab indenting on or off (the line under the editor says which)"),
            ("Enter", "New line, keeping the indentation"),
            ("Escape, then Tab", "Leave the editor while Tab indents"),
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

/// The id of the shortcuts dialog.
const DIALOG_ID: &str = "shortcuts-dialog";

/// The button, the menu (closed; `data-help` names what each item does) and the dialog.
fn menu_html() -> String {
    let mut html = String::from(concat!(
        r#"<button class="header-button" data-help="menu" aria-haspopup="menu" aria-expanded="false">Help</button>"#,
        r#"<ul class="menu" role="menu" aria-label="Help" hidden>"#,
        r#"<li role="none"><button role="menuitem" tabindex="-1" data-help="tour">Start here</button></li>"#,
        r#"<li role="none"><button role="menuitem" tabindex="-1" data-help="keys">Keyboard shortcuts</button></li>"#,
        r#"<li role="none"><a role="menuitem" tabindex="-1" data-help="page" href="problems.html" target="_blank" rel="noopener">Problems explained</a></li>"#,
        r#"</ul>"#,
    ));
    // Its content comes from a chunk the first time it opens (`lazy::shortcuts_text`).
    html.push_str(concat!(
        r#"<dialog id="shortcuts-dialog" class="app-dialog shortcuts""#,
        r#" aria-labelledby="shortcuts-title"></dialog>"#
    ));
    html
}

/// The shortcuts dialog's content: the title, the list (focused when it opens, so it
/// opens at its top and the arrow keys scroll it) and `Close`.
pub fn shortcuts_html() -> String {
    let mut html = String::from(
        r#"<h2 id="shortcuts-title">Keyboard shortcuts</h2><p class="muted">On a Mac, Cmd works where Ctrl is written.</p><div class="shortcut-list" tabindex="0" autofocus aria-label="Shortcuts">"#,
    );
    for (area, keys) in SHORTCUTS {
        html.push_str(&format!("<table class=\"shortcut-table\"><caption>{area}</caption><tbody>"));
        for (k, what) in *keys {
            html.push_str(&format!(
                "<tr><th scope=\"row\"><kbd>{k}</kbd></th><td>{what}</td></tr>"
            ));
        }
        html.push_str("</tbody></table>");
    }
    html.push_str(r#"</div><form method="dialog" class="dialog-actions"><button class="primary">Close</button></form>"#);
    html
}

/// The first element under `root` that `selector` finds, as an HTML element.
fn find(root: &web_sys::Element, selector: &str) -> Option<web_sys::HtmlElement> {
    use wasm_bindgen::JsCast;
    root.query_selector(selector).ok().flatten()?.dyn_into().ok()
}

/// Opens or closes the menu under `root` (its first item takes the focus when it opens,
/// the `Help` button when it closes from the keyboard).
fn set_open(root: &web_sys::Element, open: bool, focus: bool) {
    let (Some(button), Some(menu)) = (find(root, "[data-help=menu]"), find(root, ".menu")) else {
        return;
    };
    let _ = button.set_attribute("aria-expanded", if open { "true" } else { "false" });
    menu.set_hidden(!open);
    if focus {
        focus_item(root, if open { Some(0) } else { None });
    }
}

/// Focuses the menu item at `index` (from the end when negative), or the `Help` button
/// (`None`).
fn focus_item(root: &web_sys::Element, index: Option<i32>) {
    use wasm_bindgen::JsCast;
    let target = match index {
        None => find(root, "[data-help=menu]"),
        Some(i) => root.query_selector_all("[role=menuitem]").ok().and_then(|list| {
            let n = list.length() as i32;
            (n > 0).then(|| list.item(i.rem_euclid(n) as u32)?.dyn_into().ok()).flatten()
        }),
    };
    if let Some(t) = target {
        let _ = t.focus();
    }
}

/// The `Help` button and its menu, with the shortcuts dialog: fixed markup handled by one
/// listener per event kind (far less code in the page than a view per element; the first
/// load has a size budget).
pub fn help_menu() -> impl IntoView {
    use wasm_bindgen::JsCast;
    let tour = expect_context::<Tour>();
    let state = expect_context::<crate::state::AppState>();
    let root_of =
        |e: &web_sys::Event| e.current_target().and_then(|t| t.dyn_into::<web_sys::Element>().ok());
    let on_click = move |e: ev::MouseEvent| {
        let Some(root) = root_of(&e) else { return };
        let action = e
            .target()
            .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
            .and_then(|t| t.closest("[data-help]").ok().flatten())
            .and_then(|t| t.get_attribute("data-help"));
        let open = find(&root, ".menu").is_some_and(|m| !m.hidden());
        match action.as_deref() {
            Some("menu") => set_open(&root, !open, true),
            Some("tour") => {
                set_open(&root, false, false);
                tour.restart();
            }
            Some("keys") => {
                set_open(&root, false, false);
                let dialog = root
                    .query_selector(&format!("#{DIALOG_ID}"))
                    .ok()
                    .flatten()
                    .and_then(|d| d.dyn_into::<web_sys::HtmlDialogElement>().ok());
                if let Some(d) = dialog {
                    leptos::task::spawn_local(async move {
                        if d.child_element_count() == 0 {
                            match crate::lazy::shortcuts_text().await {
                                Ok(html) => d.set_inner_html(&html),
                                Err(e) => {
                                    return state
                                        .error(format!("Could not open the shortcuts: {e}."))
                                }
                            }
                        }
                        let _ = d.show_modal();
                    });
                }
            }
            Some("page") => set_open(&root, false, false),
            _ => {}
        }
    };
    let on_key = move |e: ev::KeyboardEvent| {
        let Some(root) = root_of(&e) else { return };
        let Some(menu) = find(&root, ".menu") else { return };
        let key = e.key();
        if menu.hidden() {
            let on_button = e
                .target()
                .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
                .is_some_and(|t| t.get_attribute("data-help").as_deref() == Some("menu"));
            if key == "ArrowDown" && on_button {
                e.prevent_default();
                set_open(&root, true, true);
            }
            return;
        }
        let active = web_sys::window().and_then(|w| w.document()).and_then(|d| d.active_element());
        let items = root.query_selector_all("[role=menuitem]").ok();
        let at = items
            .and_then(|list| {
                (0..list.length()).position(|i| {
                    list.item(i)
                        .is_some_and(|n| active.as_ref().is_some_and(|a| a.is_same_node(Some(&n))))
                })
            })
            .map_or(-1, |p| p as i32);
        match key.as_str() {
            "ArrowDown" => focus_item(&root, Some(at + 1)),
            "ArrowUp" => focus_item(&root, Some(if at < 0 { -1 } else { at - 1 })),
            "Home" => focus_item(&root, Some(0)),
            "End" => focus_item(&root, Some(-1)),
            "Escape" => set_open(&root, false, true),
            _ => return,
        }
        e.prevent_default();
    };
    // Focus leaving the button and the menu (Tab, a click elsewhere) closes it.
    let on_focusout = move |e: ev::FocusEvent| {
        let Some(root) = root_of(&e) else { return };
        let next = e.related_target().and_then(|t| t.dyn_into::<web_sys::Node>().ok());
        if !next.is_some_and(|n| root.contains(Some(&n))) {
            set_open(&root, false, false);
        }
    };
    view! {
        <div class="help-menu" on:click=on_click on:keydown=on_key on:focusout=on_focusout
            inner_html=menu_html()></div>
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
