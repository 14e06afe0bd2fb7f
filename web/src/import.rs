//! Opening a file the user imports: project files and ST text here, PLCopen XML and PNML
//! in the import worker (`src/workers/import.rs`), which the page starts only then.

use plc_core::exercise::Sentence;
use plc_core::open::{open_plain_by, FileKind};
use plc_core::project::Project;
use wasm_bindgen::closure::Closure;
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_futures::JsFuture;

use crate::i18n::{said_text, sentence_text, t, tf, K};

/// The import worker's name (`src/workers/mod.rs`).
const WORKER: &str = "import";

/// A file opened as a project.
pub struct Imported {
    /// The project.
    pub project: Project,
    /// What the file was read as.
    pub kind: FileKind,
    /// What the import skipped or changed.
    pub notes: Vec<Note>,
}

/// A note on something an import skipped or changed, as the worker sends it: its place in
/// the file (line 0: the file as a whole), its English text and the note as data.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Note {
    /// 1-based line of the element in the file (0: the whole file).
    #[serde(default)]
    pub line: u32,
    /// 1-based column.
    #[serde(default)]
    pub column: u32,
    /// The note in English.
    #[serde(default)]
    pub english: String,
    /// The note as data, shown in the page's language.
    #[serde(default)]
    pub sentence: Option<Sentence>,
}

impl Note {
    /// The note in the language shown, after its place in the file when it has one.
    pub fn text(&self) -> String {
        let note = sentence_text(self.sentence.as_ref(), &self.english);
        if self.line == 0 {
            return note;
        }
        let (line, column) = (self.line.to_string(), self.column.to_string());
        tf(K::header_import_note_at, &[("line", &line), ("column", &column), ("note", &note)])
    }
}

impl From<&plc_core::plcopen::ImportNote> for Note {
    fn from(n: &plc_core::plcopen::ImportNote) -> Self {
        Note {
            line: n.line,
            column: n.column,
            english: n.message.clone(),
            sentence: Some(Sentence::from(n.said.clone())),
        }
    }
}

/// What a file was read as, in the language shown.
pub fn kind_text(kind: FileKind) -> &'static str {
    match kind {
        FileKind::Project => t(K::header_kind_project),
        FileKind::Plcopen => t(K::header_kind_plcopen),
        FileKind::Pnml => t(K::header_kind_pnml),
        FileKind::St => t(K::header_kind_st),
    }
}

/// The file kind whose English description is `description` (as the worker names it).
fn kind_of(description: &str) -> FileKind {
    [FileKind::Project, FileKind::Plcopen, FileKind::Pnml, FileKind::St]
        .into_iter()
        .find(|k| k.description() == description)
        .unwrap_or(FileKind::Plcopen)
}

/// Opens `text` (a file named `stem` without its extension) as a project.
pub async fn import_text(stem: &str, text: &str) -> Result<Imported, String> {
    crate::lazy::readers_for(text).await.map_err(|e| e.to_string())?;
    match open_plain_by(stem, text, crate::lazy::project_reader()) {
        Ok(Some(opened)) => Ok(Imported {
            project: opened.project,
            kind: opened.kind,
            notes: opened.warnings.iter().map(Note::from).collect(),
        }),
        Ok(None) => in_worker(stem, text).await,
        Err(e) => Err(said_text(e.said())),
    }
}

/// The next message `worker` sends (or its error, as a rejection).
fn next_message(worker: &web_sys::Worker) -> JsFuture {
    let promise = js_sys::Promise::new(&mut |resolve, reject| {
        let on_message = Closure::once_into_js(move |ev: web_sys::MessageEvent| {
            let _ = resolve.call1(&JsValue::NULL, &ev.data());
        });
        let on_error = Closure::once_into_js(move |ev: web_sys::Event| {
            let _ = reject.call1(&JsValue::NULL, &ev);
        });
        worker.set_onmessage(Some(on_message.unchecked_ref()));
        worker.set_onerror(Some(on_error.unchecked_ref()));
    });
    JsFuture::from(promise)
}

/// The project as PLCopen XML (TC6 0201), written by the worker (the exporter lives there
/// with the importers, off the first load).
pub async fn plcopen_xml(project: &Project) -> Result<String, String> {
    export_in_worker("export-plcopen", "", project).await
}

/// The Petri net POU `pou` of the project as PNML, written by the worker.
pub async fn pnml(project: &Project, pou: &str) -> Result<String, String> {
    export_in_worker("export-pnml", pou, project).await
}

async fn export_in_worker(what: &str, pou: &str, project: &Project) -> Result<String, String> {
    let request = js_sys::Array::of3(
        &JsValue::from_str(what),
        &JsValue::from_str(pou),
        &JsValue::from_str(&project.to_file()),
    );
    let reply: ExportReply = serde_json::from_str(&ask_worker(&request).await?)
        .map_err(|_| t(K::state_exporter_no_answer).to_string())?;
    if let Some(pou) = reply.no_pou {
        return Err(tf(K::state_no_petri_pou, &[("pou", &pou)]));
    }
    match reply.error {
        Some(e) => Err(e),
        None => Ok(reply.xml),
    }
}

/// Runs the import worker on one file and reads its answer.
async fn in_worker(stem: &str, text: &str) -> Result<Imported, String> {
    let request = js_sys::Array::of2(&JsValue::from_str(stem), &JsValue::from_str(text));
    let reply = ask_worker(&request).await?;
    if let Ok(Reply { project, .. }) = serde_json::from_str::<Reply>(&reply) {
        crate::lazy::readers_for(&project).await.map_err(|e| e.to_string())?;
    }
    read_reply(&reply)
}

/// Sends `request` to a fresh import worker and returns its answer.
async fn ask_worker(request: &js_sys::Array) -> Result<String, String> {
    ask_worker_at(WORKER, request).await
}

/// The folder of the app's files (`globalThis.plcAppBase`, set by `boot.js`), ending in `/`.
pub(crate) fn app_base() -> String {
    js_sys::Reflect::get(&js_sys::global(), &JsValue::from_str("plcAppBase"))
        .ok()
        .and_then(|b| b.as_string())
        .unwrap_or_else(|| "./".to_string())
}

/// Starts the app's worker `name` (`import`, `exercise`): `worker.js` in the folder of the
/// app's files (`globalThis.plcAppBase`, set by `boot.js`), as a module worker.
fn start_worker(name: &str) -> Result<web_sys::Worker, JsValue> {
    let base = app_base();
    let options = web_sys::WorkerOptions::new();
    options.set_type(web_sys::WorkerType::Module);
    options.set_name(name);
    web_sys::Worker::new_with_options(&format!("{base}worker.js"), &options)
}

/// Sends `request` to a fresh worker `name` and returns its answer. The worker says when
/// it is ready (its module and chunk load asynchronously; a message sent before would be
/// lost).
pub async fn ask_worker_at(name: &str, request: &JsValue) -> Result<String, String> {
    ask_worker_raw(name, request).await.map(|v| v.as_string().unwrap_or_default())
}

/// [`ask_worker_at`], the answer as the worker sent it (text, or bytes).
pub async fn ask_worker_raw(name: &str, request: &JsValue) -> Result<JsValue, String> {
    let worker = start_worker(name)
        .map_err(|e| tf(K::state_worker_cannot_start_why, &[("error", &format!("{e:?}"))]))?;
    let stopped = |_| t(K::state_worker_stopped).to_string();
    let answer = async {
        let ready =
            next_message(&worker).await.map_err(|_| t(K::state_worker_cannot_start).to_string())?;
        if ready.as_string().as_deref() != Some("ready") {
            return Err(t(K::state_worker_offline).to_string());
        }
        let reply = next_message(&worker);
        worker
            .post_message(request)
            .map_err(|e| tf(K::state_worker_refused, &[("error", &format!("{e:?}"))]))?;
        reply.await.map_err(stopped)
    }
    .await;
    worker.terminate();
    answer
}

/// The worker's answer to an import.
#[derive(serde::Deserialize)]
struct Reply {
    #[serde(default)]
    error: Option<String>,
    /// The error as data, shown in the page's language.
    #[serde(default)]
    error_sentence: Option<Sentence>,
    #[serde(default)]
    project: String,
    #[serde(default)]
    kind: String,
    #[serde(default)]
    notes: Vec<Note>,
}

/// The worker's answer to an export: a reply of its own, so that the first load (which
/// has the Export buttons) holds none of the import's reading of notes and sentences. Its
/// only error is the page's own project failing to read back, shown in English.
#[derive(serde::Deserialize)]
struct ExportReply {
    #[serde(default)]
    error: Option<String>,
    #[serde(default)]
    xml: String,
    /// The Petri net POU asked for is not in the project.
    #[serde(default)]
    no_pou: Option<String>,
}

/// Reads the worker's JSON answer.
fn read_reply(reply: &str) -> Result<Imported, String> {
    let reply: Reply =
        serde_json::from_str(reply).map_err(|_| t(K::state_importer_no_answer).to_string())?;

    if let Some(error) = reply.error {
        return Err(sentence_text(reply.error_sentence.as_ref(), &error));
    }
    let project = crate::lazy::project_reader()(&reply.project).map_err(|e| said_text(e.said()))?;
    Ok(Imported { project, kind: kind_of(&reply.kind), notes: reply.notes })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn replies_are_read_or_refused() {
        let p = Project::new("Net");
        let note = serde_json::json!({"line": 3, "column": 5, "english": "w"});
        let ok = serde_json::json!({"project": p.to_file(), "kind": "PNML", "notes": [note]});
        let read = read_reply(&ok.to_string()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((read.project.name.as_str(), read.kind), ("Net", FileKind::Pnml));
        assert_eq!(read.notes.iter().map(Note::text).collect::<Vec<_>>(), ["line 3, column 5: w"]);
        assert_eq!(
            read_reply(r#"{"error": "bad XML at 1:2"}"#).err().as_deref(),
            Some("bad XML at 1:2")
        );
        assert!(read_reply("not json").is_err());
    }
}
