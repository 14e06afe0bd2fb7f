//! The `Help` menu of the header: `Start here` (the guided tour from its first step),
//! `Keyboard shortcuts` (a dialog listing the keys the editors take) and `Problems
//! explained` (the static page of every problem code, `problems.html`).

use leptos::ev;
use leptos::prelude::*;

use crate::components::tour::Tour;
use crate::i18n::{t, tf, K};

/// A shortcut's keys: as the keyboard writes them, or with words (`Enter or F2`).
#[derive(Clone, Copy)]
enum Keys {
    /// Key names only (`Ctrl+Z`).
    Raw(&'static str),
    /// Keys joined by words, translated.
    Said(K),
}

impl Keys {
    fn text(self) -> &'static str {
        match self {
            Keys::Raw(keys) => keys,
            Keys::Said(key) => t(key),
        }
    }
}

/// The keys of the app, by where they work (read from the editors' key handlers; keep in
/// step with them).
const SHORTCUTS: &[(K, &[(Keys, K)])] = {
    use Keys::{Raw, Said};
    &[
        (
            K::help_area_st,
            &[
                (Raw("Ctrl+Z"), K::help_undo),
                (Said(K::help_key_redo), K::help_redo),
                (Raw("Tab / Shift+Tab"), K::help_tab),
                (Raw("Ctrl+M"), K::help_tab_mode),
                (Raw("Enter"), K::help_new_line),
                (Said(K::help_key_escape_tab), K::help_leave_editor),
            ],
        ),
        (
            K::help_area_ladder,
            &[
                (Said(K::help_key_arrows), K::help_next_cell),
                (Raw("c / n"), K::help_contacts),
                (Raw("o / s / r"), K::help_coils),
                (Raw("w / l"), K::help_wires),
                (Raw("b"), K::help_pick_block),
                (Said(K::help_key_enter_f2), K::help_edit_operand),
                (Said(K::help_key_delete), K::help_clear_cell),
                (Raw("Ctrl+C / Ctrl+V"), K::help_copy_rung),
                (Said(K::help_key_undo_redo), K::help_undo_redo),
                (Said(K::help_key_drop_copy), K::help_drop_copy),
            ],
        ),
        (
            K::help_area_operand,
            &[
                (Said(K::help_key_down_up), K::help_choose_name),
                (Raw("Tab"), K::help_take_name),
                (Raw("Enter"), K::help_commit_operand),
                (Raw("Escape"), K::help_take_back),
            ],
        ),
        (
            K::help_area_petri,
            &[
                (Said(K::help_key_arrows), K::help_move_node),
                (Raw("Enter"), K::help_properties),
                (Said(K::help_key_delete), K::help_delete_selection),
                (Raw("Escape"), K::help_select_tool),
                (Said(K::help_key_undo_redo), K::help_undo_redo),
            ],
        ),
        (
            K::help_area_sim,
            &[
                (Said(K::help_key_space_enter), K::help_flip_switch),
                (Raw("Enter / Escape"), K::help_commit_value),
            ],
        ),
    ]
};

/// The id of the shortcuts dialog.
const DIALOG_ID: &str = "shortcuts-dialog";

/// The button, the menu (closed; `data-help` names what each item does) and the dialog.
fn menu_html() -> String {
    let mut html = format!(
        concat!(
            r#"<button class="header-button" data-help="menu" aria-haspopup="menu" aria-expanded="false">{help}</button>"#,
            r#"<ul class="menu" role="menu" aria-label="{help}" hidden>"#,
            r#"<li role="none"><button role="menuitem" tabindex="-1" data-help="tour">{tour}</button></li>"#,
            r#"<li role="none"><button role="menuitem" tabindex="-1" data-help="keys">{keys}</button></li>"#,
            r#"<li role="none"><a role="menuitem" tabindex="-1" data-help="page" href="{page}" target="_blank" rel="noopener">{problems}</a></li>"#,
            r#"</ul>"#,
        ),
        help = t(K::help_help),
        tour = t(K::help_start_here),
        keys = t(K::help_keyboard_shortcuts),
        page = t(K::help_problems_page),
        problems = t(K::help_problems_explained),
    );
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
    let mut html = format!(
        r#"<h2 id="shortcuts-title">{}</h2><p class="muted">{}</p><div class="shortcut-list" tabindex="0" autofocus aria-label="{}">"#,
        t(K::help_keyboard_shortcuts),
        t(K::help_mac),
        t(K::help_shortcuts),
    );
    for (area, keys) in SHORTCUTS {
        html.push_str(&format!(
            "<table class=\"shortcut-table\"><caption>{}</caption><tbody>",
            t(*area)
        ));
        for (k, what) in *keys {
            html.push_str(&format!(
                "<tr><th scope=\"row\"><kbd>{}</kbd></th><td>{}</td></tr>",
                k.text(),
                t(*what)
            ));
        }
        html.push_str("</tbody></table>");
    }
    html.push_str(&format!(
        r#"</div><form method="dialog" class="dialog-actions"><button class="primary">{}</button></form>"#,
        t(K::help_close)
    ));
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
                                    return state.error(tf(
                                        K::help_shortcuts_failed,
                                        &[("error", &e.to_string())],
                                    ))
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
            let texts =
                std::iter::once(t(*area)).chain(keys.iter().flat_map(|(k, w)| [k.text(), t(*w)]));
            for t in texts {
                assert!(!t.contains(['<', '>', '&']), "{t}");
            }
        }
    }
}
