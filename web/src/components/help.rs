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

/// The id of the shortcuts dialog.
const DIALOG_ID: &str = "shortcuts-dialog";

/// The menu's items: `data-help` names what each does.
const MENU_HTML: &str = concat!(
    r#"<li role="none"><button role="menuitem" tabindex="-1" data-help="tour">Start here</button></li>"#,
    r#"<li role="none"><button role="menuitem" tabindex="-1" data-help="keys">Keyboard shortcuts</button></li>"#,
    r#"<li role="none"><a role="menuitem" tabindex="-1" data-help="page" href="problems.html" target="_blank" rel="noopener">Problems explained</a></li>"#,
);

/// The shortcuts dialog's content: the title, the list (focused when it opens, so it
/// opens at its top and the arrow keys scroll it) and `Close`.
fn shortcuts_html() -> String {
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

/// The menu's items, in order.
fn items(menu: &web_sys::Element) -> Vec<web_sys::HtmlElement> {
    use wasm_bindgen::JsCast;
    let Ok(list) = menu.query_selector_all("[role=menuitem]") else { return Vec::new() };
    (0..list.length()).filter_map(|i| list.item(i)?.dyn_into().ok()).collect()
}

/// Focuses the item at `index` (from the end when negative) of the open menu, or the `Help`
/// button itself (`None`).
fn focus_in_menu(index: Option<i32>) {
    use wasm_bindgen::JsCast;
    let Some(doc) = web_sys::window().and_then(|w| w.document()) else { return };
    let target: Option<web_sys::HtmlElement> = match index {
        None => {
            doc.query_selector(".help-menu > button").ok().flatten().and_then(|e| e.dyn_into().ok())
        }
        Some(i) => doc.query_selector(".help-menu .menu").ok().flatten().and_then(|menu| {
            let items = items(&menu);
            let n = items.len() as i32;
            (n > 0).then(|| items[i.rem_euclid(n) as usize].clone())
        }),
    };
    if let Some(t) = target {
        let _ = t.focus();
    }
}

/// The `Help` button and its menu, with the shortcuts dialog. The menu and the dialog are
/// fixed markup handled by one listener each (far less code in the page than a view per
/// item; the first load has a size budget).
#[component]
pub fn HelpMenu() -> impl IntoView {
    use wasm_bindgen::JsCast;
    let tour = expect_context::<Tour>();
    let open = RwSignal::new(false);
    let show = move |on: bool| {
        open.set(on);
        if on {
            request_animation_frame(|| focus_in_menu(Some(0)));
        }
    };
    let on_click = move |e: ev::MouseEvent| {
        let target = e.target().and_then(|t| t.dyn_into::<web_sys::Element>().ok());
        let action = target
            .and_then(|t| t.closest("[data-help]").ok().flatten())
            .and_then(|t| t.get_attribute("data-help"));
        match action.as_deref() {
            Some("menu") => show(!open.get_untracked()),
            Some("tour") => {
                open.set(false);
                tour.restart();
            }
            Some("keys") => {
                open.set(false);
                let dialog = web_sys::window()
                    .and_then(|w| w.document())
                    .and_then(|d| d.get_element_by_id(DIALOG_ID))
                    .and_then(|d| d.dyn_into::<web_sys::HtmlDialogElement>().ok());
                if let Some(d) = dialog {
                    let _ = d.show_modal();
                }
            }
            Some("page") => open.set(false),
            _ => {}
        }
    };
    let on_key = move |e: ev::KeyboardEvent| {
        let key = e.key();
        if !open.get_untracked() {
            if key == "ArrowDown" {
                e.prevent_default();
                show(true);
            }
            return;
        }
        let active = web_sys::window().and_then(|w| w.document()).and_then(|d| d.active_element());
        let menu = web_sys::window()
            .and_then(|w| w.document())
            .and_then(|d| d.query_selector(".help-menu .menu").ok().flatten());
        let at = menu
            .map(|m| items(&m))
            .and_then(|items| {
                items.iter().position(|i| active.as_ref().is_some_and(|a| a.is_same_node(Some(i))))
            })
            .map_or(-1, |p| p as i32);
        let to = match key.as_str() {
            "ArrowDown" => Some(at + 1),
            "ArrowUp" if at < 0 => Some(-1),
            "ArrowUp" => Some(at - 1),
            "Home" => Some(0),
            "End" => Some(-1),
            "Escape" => {
                open.set(false);
                None
            }
            _ => return,
        };
        e.prevent_default();
        focus_in_menu(to);
    };
    // Focus leaving the button and the menu (Tab, a click elsewhere) closes it.
    let on_focusout = move |e: ev::FocusEvent| {
        let next = e.related_target().and_then(|t| t.dyn_into::<web_sys::Node>().ok());
        let current = e.current_target().and_then(|t| t.dyn_into::<web_sys::Node>().ok());
        let inside = current.is_some_and(|c| next.is_some_and(|n| c.contains(Some(&n))));
        if !inside {
            open.set(false);
        }
    };
    view! {
        <div class="help-menu" on:click=on_click on:keydown=on_key on:focusout=on_focusout>
            <button class="header-button" data-help="menu" aria-haspopup="menu"
                aria-expanded=move || open.get().to_string()>"Help"</button>
            <ul class="menu" role="menu" aria-label="Help" hidden=move || !open.get() inner_html=MENU_HTML></ul>
            <dialog id=DIALOG_ID class="app-dialog shortcuts" aria-labelledby="shortcuts-title"
                inner_html=shortcuts_html()></dialog>
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
