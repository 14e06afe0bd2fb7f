//! The page header: the app title, the open project's name, the project menu (open,
//! new, open an example, rename, duplicate, delete, export, import, share), `Help` and the
//! `Theme` switch. On a small screen (≤ 700 px wide, issue 34) the actions fold into a
//! `Menu` button that opens them as a panel.

use leptos::ev;
use leptos::html;
use leptos::prelude::*;
use plc_core::project::Project;
use wasm_bindgen::JsCast;
use wasm_bindgen_futures::JsFuture;

use crate::components::help::help_menu;
use crate::components::share_box::{copy_to_clipboard, ShareBox};
use crate::components::theme::ThemeSwitch;
use crate::examples;
use crate::exercises::{Exercises, Screen};
use crate::i18n::{t, tf, I18n, K};
use crate::import::import_text;
use crate::state::AppState;
use plc_core::i18n::Lang;

/// The first free "Untitled N" name.
fn untitled_name(existing: &[String]) -> String {
    (1..)
        .map(|n| format!("Untitled {n}"))
        .find(|name| !existing.iter().any(|e| e.eq_ignore_ascii_case(name)))
        .unwrap_or_else(|| "Untitled".to_string())
}

/// Reads the chosen file (a project file, PLCopen XML, PNML or ST) and imports it as a new
/// project (code of the `import_ui` chunk: `lazy::import_file`).
pub(crate) async fn import_file(state: AppState, file: web_sys::File) {
    let name = file.name();
    let text = match JsFuture::from(file.text()).await {
        Ok(v) => v.as_string().unwrap_or_default(),
        Err(_) => {
            state.error(tf(K::header_read_failed, &[("name", &name)]));
            return;
        }
    };
    let stem = name.split('.').next().filter(|s| !s.is_empty()).unwrap_or("Imported");
    match import_text(stem, &text).await {
        Ok(opened) => {
            let pname = opened.project.name.clone();
            if !state.add_and_open(opened.project) {
                return; // the banner says it is open but not saved
            }
            let kind = crate::import::kind_text(opened.kind);
            let mut text =
                tf(K::header_imported, &[("project", &pname), ("name", &name), ("kind", kind)]);
            if !opened.notes.is_empty() {
                let notes: Vec<String> = opened.notes.iter().map(|n| n.text()).collect();
                text.push(' ');
                text.push_str(&tf(K::header_import_notes, &[("notes", &notes.join("; "))]));
            }
            state.info(text);
        }
        Err(e) => {
            state.error(tf(K::header_import_failed, &[("name", &name), ("error", &e.to_string())]))
        }
    }
}

/// Copies the share link to the clipboard (when allowed) and shows it.
async fn share(state: AppState, shown: RwSignal<Option<String>>) {
    let link = match state.share_link().await {
        Ok(link) => link,
        Err(e) => return state.error(tf(K::header_share_failed, &[("error", &e.to_string())])),
    };
    shown.set(Some(link.clone()));
    if copy_to_clipboard(&link).await {
        state.info(tf(K::header_share_copied, &[("link", &link)]));
    } else {
        state.info(tf(K::header_share_copy, &[("link", &link)]));
    }
}

/// The `Language` select: English, Polski, Čeština, each in its own language; the choice
/// applies at once and is kept. Its accessible name keeps the English word beside the
/// translation, so a student lost in a foreign language still finds it.
#[component]
fn LanguageSelect() -> impl IntoView {
    let i18n = expect_context::<I18n>();
    // The exercise catalogue has a `Language` filter of its own (the languages an exercise
    // is written in): while it is shown, the page's language is left to the project's
    // screen, so that one control answers to the name.
    let catalogue = expect_context::<crate::exercises::Exercises>().screen;
    let in_catalogue = move || catalogue.get() == crate::exercises::Screen::Catalogue;
    let word = t(K::header_language);
    let name = if i18n.shown.get_untracked() == Lang::En {
        word.to_string()
    } else {
        format!("{word} (Language)")
    };
    view! {
        <select class="language-select" aria-label=name.clone() title=name hidden=in_catalogue
            prop:value=move || i18n.lang.get().tag()
            on:change=move |ev: ev::Event| {
                if let Some(lang) = Lang::from_tag(&event_target_value(&ev)) {
                    i18n.choose(lang);
                }
            }>
            {Lang::ALL.into_iter().map(|l| view! {
                <option value=l.tag() lang=l.tag() selected=move || i18n.lang.get() == l>{l.native_name()}</option>
            }).collect_view()}
        </select>
    }
}

/// The header with the project menu.
#[component]
pub fn Header() -> impl IntoView {
    let state = expect_context::<AppState>();
    let exercises = expect_context::<Exercises>();
    let renaming = RwSignal::new(false);
    let rename_input = NodeRef::<html::Input>::new();
    let file_input = NodeRef::<html::Input>::new();
    let share_link = RwSignal::new(None::<String>);
    // The small screen's `Menu` panel: open or not; the button takes the focus back.
    let menu_open = RwSignal::new(false);
    let menu_button = NodeRef::<html::Button>::new();
    let actions = NodeRef::<html::Div>::new();
    let header = NodeRef::<html::Header>::new();
    let close_menu = move |focus: bool| {
        menu_open.set(false);
        if let Some(b) = menu_button.get_untracked().filter(|_| focus) {
            let _ = b.focus();
        }
    };
    let toggle_menu = move |_| {
        let open = !menu_open.get_untracked();
        menu_open.set(open);
        // The first action takes the focus, once the panel is shown.
        if open {
            request_animation_frame(move || {
                let first = actions
                    .get_untracked()
                    .and_then(|a| a.query_selector("button, select").ok().flatten())
                    .and_then(|e| e.dyn_into::<web_sys::HtmlElement>().ok());
                if let Some(first) = first {
                    let _ = first.focus();
                }
            });
        }
    };
    // Esc closes the panel (after a menu inside it, which takes its own Esc first).
    let on_actions_key = move |ev: ev::KeyboardEvent| {
        if ev.key() == "Escape" && menu_open.get_untracked() && !ev.default_prevented() {
            ev.prevent_default();
            close_menu(true);
        }
    };
    // An action taken closes the panel (not the `Help` button, which opens its own menu).
    let on_actions_click = move |ev: ev::MouseEvent| {
        let button = ev
            .target()
            .and_then(|t| t.dyn_into::<web_sys::Element>().ok())
            .and_then(|e| e.closest("button, a").ok().flatten());
        if menu_open.get_untracked() && button.is_some_and(|b| !b.has_attribute("aria-haspopup")) {
            close_menu(true);
        }
    };
    let on_actions_change = move |ev: ev::Event| {
        let file = ev.target().and_then(|t| t.dyn_into::<web_sys::HtmlInputElement>().ok());
        if menu_open.get_untracked() && file.is_none() {
            close_menu(true);
        }
    };
    // A tap outside the header closes the panel.
    let outside = window_event_listener(ev::pointerdown, move |ev| {
        if !menu_open.get_untracked() {
            return;
        }
        let target = ev.target().and_then(|t| t.dyn_into::<web_sys::Node>().ok());
        let inside = header.get_untracked().is_some_and(|h| h.contains(target.as_ref()));
        if !inside {
            close_menu(false);
        }
    });
    on_cleanup(move || outside.remove());

    // A different project: its share link is not this one's.
    Effect::new(move |_| {
        state.project_id.track();
        share_link.set(None);
        renaming.set(false);
    });
    // Focus and select the name when renaming starts.
    Effect::new(move |_| {
        if renaming.get() {
            if let Some(input) = rename_input.get() {
                let _ = input.focus();
                input.select();
            }
        }
    });

    let name = move || state.project.with(|p| p.name.clone());
    let confirm_rename = move || {
        if !renaming.get_untracked() {
            return;
        }
        renaming.set(false);
        if let Some(input) = rename_input.get_untracked() {
            state.rename(&input.value());
        }
    };
    let new_project = move |_| {
        let names: Vec<String> =
            state.projects.with_untracked(|ps| ps.iter().map(|p| p.name.clone()).collect());
        state.add_and_open(Project::new(untitled_name(&names)));
    };
    let delete = move |_| {
        let name = state.project.with_untracked(|p| p.name.clone());
        let ok = web_sys::window()
            .and_then(|w| {
                w.confirm_with_message(&tf(K::header_delete_confirm, &[("name", &name)])).ok()
            })
            .unwrap_or(false);
        if ok {
            state.delete_current();
            state.info(tf(K::header_deleted, &[("name", &name)]));
        }
    };
    let export = move |_| state.export_project();
    let export_xml = move |_| {
        let project = state.project.get_untracked();
        leptos::task::spawn_local(async move {
            match crate::import::plcopen_xml(&project).await {
                Ok(xml) => {
                    let name = crate::state::project_file_name(&project.name)
                        .replace(".plcproj.json", ".xml");
                    if let Err(e) = crate::download::download(&name, "application/xml", &xml) {
                        state.error(e);
                    }
                }
                Err(e) => {
                    state.error(tf(K::header_export_xml_failed, &[("error", &e.to_string())]))
                }
            }
        });
    };
    let on_file = move |_| {
        let Some(input) = file_input.get_untracked() else { return };
        let file = input.files().and_then(|f| f.get(0));
        input.set_value("");
        if let Some(file) = file {
            state.opening_new_project();
            leptos::task::spawn_local(async move {
                let name = file.name();
                match crate::lazy::import_file(state, file).await {
                    Ok(importing) => importing.await,
                    Err(_) => state.error(tf(
                        K::header_import_failed,
                        &[("name", &name), ("error", t(K::lazy_load_failed))],
                    )),
                }
                state.opened_new_project();
            });
        }
    };
    let on_share = move |_| leptos::task::spawn_local(share(state, share_link));
    let on_select = move |ev: ev::Event| {
        let id = event_target_value(&ev);
        if !id.is_empty() && Some(&id) != state.project_id.get_untracked().as_ref() {
            state.open(&id);
        }
    };

    view! {
        <header class="app-header" node_ref=header>
            <h1 class="app-title">{t(K::app_title)}</h1>
            <div class="project-title">
                {move || if renaming.get() {
                    view! {
                        <input class="rename-input" type="text" node_ref=rename_input aria-label=t(K::header_project_name)
                            prop:value=name
                            on:keydown=move |ev: ev::KeyboardEvent| match ev.key().as_str() {
                                "Enter" => { ev.prevent_default(); confirm_rename(); }
                                "Escape" => renaming.set(false),
                                _ => {}
                            }
                            on:blur=move |_| confirm_rename()/>
                    }.into_any()
                } else {
                    view! { <span class="project-name" title=t(K::header_open_project_title)>{name}</span> }.into_any()
                }}
            </div>
            <button class="header-button menu-toggle" node_ref=menu_button aria-controls="header-actions"
                aria-expanded=move || menu_open.get().to_string() on:click=toggle_menu>{t(K::phone_menu)}</button>
            // A wide screen lays these out in the header's row (`display: contents`); a small
            // one shows them only while the `Menu` panel is open.
            <div class="header-actions" id="header-actions" node_ref=actions class:open=move || menu_open.get()
                on:keydown=on_actions_key on:click=on_actions_click on:change=on_actions_change>
            <button class="exercises-button" aria-pressed=move || (exercises.screen.get() == Screen::Catalogue).to_string()
                on:click=move |_| exercises.screen.update(|s| *s = if *s == Screen::Catalogue { Screen::Workspace } else { Screen::Catalogue })
                title=t(K::header_exercises_title)>{t(K::header_exercises)}</button>
            {help_menu()}
            <LanguageSelect/>
            <ThemeSwitch/>
            <nav class="project-menu" aria-label=t(K::header_project_menu)>
                <label class="project-select">
                    <span class="visually-hidden">{t(K::header_open_project)}</span>
                    <select aria-label=t(K::header_open_project) on:change=on_select
                        prop:value=move || state.project_id.get().unwrap_or_default()>
                        {move || {
                            let current = state.project_id.get();
                            let damaged = state.damaged.get();
                            let unsaved = current.is_none().then(|| view! {
                                <option value="" selected=true>{tf(K::header_not_saved, &[("name", &name())])}</option>
                            });
                            let stored = state.projects.get().into_iter().map(|p| {
                                let selected = current.as_deref() == Some(p.id.as_str());
                                let label = if damaged.contains_key(&p.id) {
                                    tf(K::header_damaged, &[("name", &p.name)])
                                } else {
                                    p.name.clone()
                                };
                                view! { <option value=p.id.clone() selected=selected>{label}</option> }
                            }).collect_view();
                            (unsaved, stored)
                        }}
                    </select>
                </label>
                <button on:click=new_project>{t(K::header_new_project)}</button>
                <button on:click=move |_| renaming.set(true) disabled=move || renaming.get()>{t(K::header_rename)}</button>
                <label class="project-select">
                    <span class="visually-hidden">{t(K::header_open_example)}</span>
                    <select aria-label=t(K::header_open_example) title=t(K::header_open_example_title)
                        on:change=move |ev: ev::Event| {
                            let file = event_target_value(&ev);
                            if let Some(sel) = ev.target().and_then(|t| t.dyn_into::<web_sys::HtmlSelectElement>().ok()) {
                                sel.set_value("");
                            }
                            if file.is_empty() {
                                return;
                            }
                            state.opening_new_project();
                            leptos::task::spawn_local(async move {
                                let opened = match crate::lazy::open_example(file).await {
                                    Ok(opening) => opening.await,
                                    Err(_) => Err(t(K::lazy_load_failed).to_string()),
                                };
                                match opened {
                                    Ok(p) => {
                                        let title = p.name.clone();
                                        if state.add_and_open(p) {
                                            state.info(tf(K::header_opened_example, &[("title", &title)]));
                                        }
                                    }
                                    Err(e) => state.error(tf(K::header_example_failed, &[("error", &e.to_string())])),
                                }
                                state.opened_new_project();
                            });
                        }>
                        <option value="" selected=true>{t(K::header_open_example_choose)}</option>
                        {examples::examples().into_iter().map(|e| view! {
                            <option value=e.file title=t(e.about)>{t(e.key)}</option>
                        }).collect_view()}
                    </select>
                </label>
                <button on:click=move |_| state.duplicate()>{t(K::header_duplicate)}</button>
                <button on:click=delete>{t(K::header_delete)}</button>
                <button on:click=export title=t(K::header_export_title)>{t(K::header_export)}</button>
                <button on:click=export_xml title=t(K::header_export_xml_title)>{t(K::header_export_xml)}</button>
                <button on:click=move |_| { if let Some(i) = file_input.get_untracked() { i.click(); } }
                    title=t(K::header_import_title)>{t(K::header_import)}</button>
                <input type="file" class="visually-hidden" tabindex="-1" node_ref=file_input
                    accept=".json,.plcproj.json,.plcsub,.xml,.pnml,.st,application/json,text/xml" aria-label=t(K::header_import_file)
                    on:change=on_file/>
                <button on:click=on_share title=t(K::header_share_title)>{t(K::header_share)}</button>
            </nav>
            </div>
            {move || share_link.get().map(|link| view! {
                <ShareBox link=link label=t(K::header_share_link) close_label=t(K::header_close_share_link)
                    on_close=move || share_link.set(None)/>
            })}
        </header>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names() {
        assert_eq!(untitled_name(&["Untitled 1".into(), "x".into()]), "Untitled 2");
    }
}
