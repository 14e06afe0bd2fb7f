//! The app's two workers, `import` (PLCopen XML and PNML in and out) and `exercise`
//! (exercise files and grading). Each is started from `worker.js` next to the app's module:
//! it runs this same module (the file the page already fetched, so the engine is
//! downloaded once), then [`worker_main`] fetches the worker's own code as a chunk
//! (`split_import_worker.wasm`, `split_exercise_worker.wasm`), listens, and says `"ready"`;
//! the page sends its request only then (`crate::import::ask_worker`). The exercise worker
//! fetches one more chunk, `exercise_toml`, only for an exercise file written in TOML.

mod exercise;
mod import;

use std::future::Future;
use std::pin::Pin;

use plc_core::open::Opened;
use wasm_bindgen::closure::Closure;
use wasm_bindgen::prelude::wasm_bindgen;
use wasm_bindgen::{JsCast, JsValue};

use crate::lazy::LoadFailed;
use leptos::wasm_split::wasm_split;

/// How a worker answers one message (text, or bytes).
type Answer = fn(JsValue) -> Pin<Box<dyn Future<Output = JsValue>>>;

/// The import worker's answer to one message.
#[wasm_split(import_worker, wasm_split_path = ::leptos::wasm_split, fallible)]
fn import_answer() -> Result<Answer, LoadFailed> {
    Ok(|request| Box::pin(async move { JsValue::from_str(&import::answer(&request).await) }))
}

/// The exercise worker's answer to one message.
#[wasm_split(exercise_worker, wasm_split_path = ::leptos::wasm_split, fallible)]
fn exercise_answer() -> Result<Answer, LoadFailed> {
    Ok(|request| Box::pin(exercise::reply(request)))
}

/// Opens a PLCopen XML or PNML file as a project (the XML readers, a chunk of their own:
/// the import worker's code reaches them too, so both workers share it).
#[wasm_split(xml_reader, wasm_split_path = ::leptos::wasm_split, fallible)]
fn open_xml(stem: String, text: String) -> Result<Result<Opened, String>, LoadFailed> {
    // Called for XML only (`open_plain_by` reads the rest), so no project file is read.
    let read = plc_core::project::Project::from_file_without_diagrams;
    Ok(plc_core::open::open_text_by(&stem, &text, read).map_err(|e| e.to_string()))
}

/// Reads an exercise file in TOML and renders its statement, relative links against
/// `base` (the TOML reader and the Markdown renderer, a chunk of their own: the shipped
/// exercises come in the built form, which the exercise worker reads without them).
#[wasm_split(exercise_toml, wasm_split_path = ::leptos::wasm_split, fallible)]
fn read_toml(
    text: String,
    base: Option<String>,
) -> Result<Result<(plc_core::exercise::Exercise, String), String>, LoadFailed> {
    use plc_core::exercise::Exercise;
    // The statement and each translation's rendered (the page shows the language chosen).
    Ok(Exercise::from_toml(&text).map(|e| e.rendered(base.as_deref())).map_err(|e| e.to_string()))
}

/// Scans shown around a failure on the page's timeline.
const PAGE_WINDOW: usize = 100;

/// Grades an attempt and writes its report as JSON (the grader's runs and the report's
/// writer: a chunk of their own, fetched at the first check, not when an exercise opens).
#[wasm_split(exercise_grader, wasm_split_path = ::leptos::wasm_split, fallible)]
fn grade_report(
    exercise: plc_core::exercise::Exercise,
    project: plc_core::project::Project,
    passes: plc_core::build::Lowerings,
) -> Result<Result<String, String>, LoadFailed> {
    use plc_core::exercise::{grade_by, GradeOptions};
    let options = GradeOptions { window: PAGE_WINDOW };
    Ok(grade_by(&exercise, &project, options, &passes)
        .map_err(|e| e.to_string())
        .and_then(|report| serde_json::to_string(&report).map_err(|e| e.to_string())))
}

/// Packs a SCORM 1.2 package of an exercise with the site's files (the manifest and the
/// ZIP writer: a chunk of their own, fetched only for `Export SCORM package`).
#[wasm_split(scorm_package, wasm_split_path = ::leptos::wasm_split, fallible)]
fn scorm_zip(
    exercise: String,
    starters: Vec<plc_core::exercise::LinkedFile>,
    site: Vec<plc_core::exercise::PackageFile>,
) -> Result<Result<Vec<u8>, String>, LoadFailed> {
    use plc_core::exercise::{scorm_package, ScormVersion};
    Ok(scorm_package(&exercise, &starters, site, ScormVersion::Scorm12).map_err(|e| e.to_string()))
}

/// The passes a project's diagram POUs need, fetched when missing (as the page does).
async fn passes_for(
    project: &plc_core::project::Project,
) -> Result<plc_core::build::Lowerings, LoadFailed> {
    crate::lazy::load_lowerings(&crate::lazy::lowerings().lacks(project)).await?;
    Ok(crate::lazy::lowerings())
}

/// Starts the worker named `kind` (`import` or `exercise`) in a worker's global scope.
#[wasm_bindgen]
pub fn worker_main(kind: String) {
    console_error_panic_hook::set_once();
    wasm_bindgen_futures::spawn_local(async move {
        let answer = match kind.as_str() {
            "import" => import_answer().await,
            "exercise" => exercise_answer().await,
            _ => Err(LoadFailed),
        };
        let scope: web_sys::DedicatedWorkerGlobalScope = js_sys::global().unchecked_into();
        let Ok(answer) = answer else {
            // The page then says the worker could not start.
            let _ = scope.post_message(&JsValue::from_str("load-failed"));
            scope.close();
            return;
        };
        let answer_to = scope.clone();
        let on_message =
            Closure::<dyn Fn(web_sys::MessageEvent)>::new(move |ev: web_sys::MessageEvent| {
                let answer_to = answer_to.clone();
                let reply = answer(ev.data());
                wasm_bindgen_futures::spawn_local(async move {
                    let _ = answer_to.post_message(&reply.await);
                });
            });
        scope.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
        on_message.forget();
        // Ready: the page sends its request only now.
        let _ = scope.post_message(&JsValue::from_str("ready"));
    });
}
