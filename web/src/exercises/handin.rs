//! The exercise page's `Hand in` and `Export SCORM package`.
//!
//! - `Hand in` asks once for `Your name` (kept in this browser) and downloads
//!   `EXERCISE-ID--NAME.plcsub`: the attempt's project file carrying the exercise's id,
//!   the name and the time (`plc_core::exercise::HandIn`), which `plc grade` grades.
//! - `Export SCORM package` has the exercise worker pack the site (the files
//!   `scripts/build-web.sh` listed in `site-files.txt`), the exercise and its starter into
//!   a package an LMS imports; the page only downloads it. Hidden inside an LMS.

use leptos::ev;
use leptos::prelude::*;
use plc_core::exercise::HandIn;
use plc_core::project::{Project, StorageBackend};
use wasm_bindgen::{JsCast, JsValue};

use crate::dom::by_id;

use super::protocol::{Reply, Request};
use super::Exercises;
use crate::download::{download, download_parts};
use crate::i18n::{t, tf, K};
use crate::state::AppState;
use crate::storage::LocalStorage;

/// Where the browser keeps the student's name.
const NAME_KEY: &str = "plc-student-name";

/// The name dialog: `Your name`, required and not only spaces; Cancel closes it (static
/// markup: one element for the page to build instead of nine; the texts hold no markup).
fn dialog_html() -> String {
    format!(
        r#"<dialog id="handin-dialog" class="handin-dialog" aria-labelledby="handin-title">
<form method="dialog"><h3 id="handin-title">{}</h3>
<label>{} <input id="handin-name" type="text" autocomplete="name" maxlength="80" required pattern=".*\S.*" autofocus aria-describedby="handin-help"></label>
<p id="handin-help" class="handin-help">{}</p>
<div class="handin-buttons"><button type="submit" class="primary">{}</button><button type="submit" value="cancel" formnovalidate>{}</button></div>
</form></dialog>"#,
        t(K::exercise_hand_in),
        t(K::exercise_your_name),
        t(K::exercise_name_help),
        t(K::exercise_download_hand_in),
        t(K::exercise_cancel),
    )
}

fn stored_name() -> Option<String> {
    LocalStorage::open().get(NAME_KEY).ok().flatten().filter(|n| !n.trim().is_empty())
}

/// Downloads the hand-in of the open attempt as `name`.
fn hand_in(ex: Exercises, state: AppState, name: &str) {
    let Some(open) = ex.open.get_untracked() else { return };
    let id = open.opened.view.id.clone();
    let when = String::from(js_sys::Date::new_0().to_iso_string());
    let project = state.project.with_untracked(Project::to_file);
    let text = HandIn::file_text(&project, &id, name, &when);
    let file = HandIn::file_name(&id, name);
    match download(&file, "application/json", &text) {
        Ok(()) => state.info(tf(
            K::exercise_handed_in,
            &[
                ("file", &file),
                ("title", open.opened.view.title_in(crate::i18n::shown_lang())),
                ("name", name.trim()),
            ],
        )),
        Err(e) => state.error(e),
    }
}

/// Has the exercise worker pack the open exercise, then downloads the package.
async fn export_scorm(ex: Exercises, state: AppState) {
    let Some(open) = ex.open.get_untracked() else { return };
    let id = open.opened.view.id.clone();
    // The site's root: the page's folder (the app's own files are one level down).
    let site = web_sys::window()
        .and_then(|w| w.location().href().ok())
        .and_then(|href| web_sys::Url::new_with_base("./", &href).ok())
        .map(|url| url.href())
        .unwrap_or_default();
    let request = match serde_json::to_string(&Request::Scorm { link: open.opened.link, site }) {
        Ok(r) => r,
        Err(e) => return state.error(e.to_string()),
    };
    let answer = crate::import::ask_worker_raw(super::WORKER, &JsValue::from_str(&request)).await;
    let bytes = match answer {
        Ok(v) if v.is_instance_of::<js_sys::Uint8Array>() => v,
        Ok(v) => {
            let e = match serde_json::from_str::<Reply>(&v.as_string().unwrap_or_default()) {
                Ok(Reply::Error(f)) => f.text(),
                _ => t(K::exercise_no_package).to_string(),
            };
            return state.error(tf(K::exercise_scorm_failed, &[("error", &e)]));
        }
        Err(e) => return state.error(tf(K::exercise_scorm_failed, &[("error", &e)])),
    };
    let file = format!("{id}-scorm.zip");
    match download_parts(&file, "application/zip", &bytes) {
        Ok(()) => state.info(tf(K::exercise_scorm_downloaded, &[("file", &file)])),
        Err(e) => state.error(e),
    }
}

/// `Hand in` and `Export SCORM package`, with the name dialog (a modal `<dialog>`: the
/// browser keeps the focus in it, Escape closes it, an empty name is not accepted).
#[component]
pub fn HandInActions() -> impl IntoView {
    let state = expect_context::<AppState>();
    let ex = expect_context::<Exercises>();
    let packing = RwSignal::new(false);
    let name = RwSignal::new(stored_name());
    let ask = || {
        if let Some(d) = by_id::<web_sys::HtmlDialogElement>("handin-dialog") {
            let _ = d.show_modal();
        }
    };
    let start = move |_| match name.get_untracked() {
        Some(n) => hand_in(ex, state, &n),
        None => ask(),
    };
    // `method="dialog"`: the submit closes the dialog (Cancel too, without the name).
    let submit = move |e: ev::SubmitEvent| {
        if e.submitter().is_some_and(|b| b.get_attribute("value").as_deref() == Some("cancel")) {
            return;
        }
        let typed = by_id::<web_sys::HtmlInputElement>("handin-name").map(|i| i.value());
        let typed = typed.unwrap_or_default().trim().to_string();
        if typed.is_empty() {
            return;
        }
        let _ = LocalStorage::open().set(NAME_KEY, &typed);
        name.set(Some(typed.clone()));
        hand_in(ex, state, &typed);
    };
    let forget = move |_| {
        let _ = LocalStorage::open().remove(NAME_KEY);
        name.set(None);
        ask();
    };
    let export = move |_| {
        if packing.get_untracked() {
            return;
        }
        packing.set(true);
        state.info(t(K::exercise_packing));
        leptos::task::spawn_local(async move {
            export_scorm(ex, state).await;
            packing.set(false);
        });
    };
    view! {
        <button on:click=start title=t(K::exercise_hand_in_title)>{t(K::exercise_hand_in)}</button>
        <button class="link handin-name" hidden=move || name.with(Option::is_none) on:click=forget>{t(K::exercise_change_name)}</button>
        <button class="lms-hidden" on:click=export title=t(K::exercise_export_scorm_title) disabled=move || packing.get()>{t(K::exercise_export_scorm)}</button>
        <div class="handin" on:submit=submit inner_html=dialog_html()></div>

    }
}
