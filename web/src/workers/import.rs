//! The import worker's work: opening PLCopen XML and PNML files and writing PLCopen XML and
//! PNML, in a chunk of the app (`split_import_worker.wasm`) that only the import worker
//! loads (it runs the page's module, so the engine is not downloaded twice). It answers
//! each message `[file stem, text]` with a JSON string
//! `{"project": <project file>, "kind": "PLCopen XML" | "PNML" | …, "warnings": [...],
//! "notes": [...]}` (`warnings` in English, `notes` as data: [`Note`]) or
//! `{"error": "...", "error_sentence": ...}` (the error in English and as data); the exports `["export-plcopen", "", project file]` and
//! `["export-pnml", POU name, project file]` are answered with `{"xml": ...}`.

use plc_core::exercise::Sentence;
use plc_core::open::open_text_by;
use wasm_bindgen::JsValue;

use crate::import::Note;

/// An error's reply: its English text, and the error as data when it is (the page shows it
/// in its language).
fn error_json(english: String, said: plc_core::diagnostics::Said) -> serde_json::Value {
    serde_json::json!({ "error": english, "error_sentence": Sentence::from(said) })
}

/// The reply to one request.
fn reply(stem: &str, text: &str) -> String {
    // The page reads project files and ST itself (`import::import_text`): what comes here
    // is XML, read without the diagram models' readers.
    let value = match open_text_by(stem, text, crate::lazy::project_reader()) {
        Ok(opened) => {
            let kind = opened.kind.description();
            let notes: Vec<Note> = opened.warnings.iter().map(Note::from).collect();
            serde_json::json!({
                "project": opened.project.to_file(),
                "kind": kind,
                "warnings": opened.warnings.iter().map(ToString::to_string).collect::<Vec<_>>(),
                "notes": notes,
            })
        }
        Err(e) => error_json(e.to_string(), e.said()),
    };
    value.to_string()
}

/// The reply to an export request: the project file as PLCopen XML (`what` is
/// `export-plcopen`), or its Petri net POU `pou` as PNML (`export-pnml`).
fn export_reply(what: &str, pou: &str, project_file: &str) -> String {
    let value = match crate::lazy::project_reader()(project_file) {
        Ok(project) if what == "export-pnml" => {
            match project.petri.iter().find(|p| p.name.eq_ignore_ascii_case(pou)) {
                Some(net) => serde_json::json!({ "xml": plc_core::pnml::export(net) }),
                None => {
                    // `no_pou`: the page words it in the language shown.
                    serde_json::json!({
                        "error": format!("the project has no Petri net POU named {pou}"),
                        "no_pou": pou,
                    })
                }
            }
        }
        Ok(project) => serde_json::json!({ "xml": plc_core::plcopen::export(&project) }),
        Err(e) => serde_json::json!({ "error": e.to_string() }),
    };
    value.to_string()
}

/// The answer to one message of the page.
pub async fn answer(request: &JsValue) -> String {
    let request = js_sys::Array::from(request);
    let first = request.get(0).as_string().unwrap_or_default();
    let second = request.get(1).as_string().unwrap_or_default();
    let export = matches!(first.as_str(), "export-plcopen" | "export-pnml");
    if request.length() == 3 && export {
        let file = request.get(2).as_string().unwrap_or_default();
        // A project with diagram POUs is read with their models' readers (a chunk).
        if let Err(e) = crate::lazy::readers_for(&file).await {
            return serde_json::json!({ "error": e.to_string() }).to_string();
        }
        export_reply(&first, &second, &file)
    } else {
        reply(&first, &second)
    }
}

#[cfg(test)]
mod tests {
    use super::reply;

    #[test]
    fn answers_with_the_project_or_the_error() {
        let pnml = r#"<?xml version="1.0"?><pnml xmlns="http://www.pnml.org/version-2009/grammar/pnml">
            <net id="n" type="http://www.pnml.org/version-2009/grammar/ptnet"><name><text>Net</text></name>
            <page id="g"><place id="a"><initialMarking><text>1</text></initialMarking></place></page></net></pnml>"#;
        let ok: serde_json::Value = serde_json::from_str(&reply("x", pnml)).unwrap_or_default();
        assert_eq!(ok["kind"], "PNML");
        assert!(ok["project"].as_str().is_some_and(|p| p.contains("\"petri\"")), "{ok}");
        let bad: serde_json::Value =
            serde_json::from_str(&reply("x", "<?xml version=\"1.0\"?><nope")).unwrap_or_default();
        assert!(bad["error"].as_str().is_some_and(|e| !e.is_empty()), "{bad}");
        let mut project = plc_core::project::Project::new("P");
        let xml: serde_json::Value =
            serde_json::from_str(&super::export_reply("export-plcopen", "", &project.to_file()))
                .unwrap_or_default();
        assert!(xml["xml"].as_str().is_some_and(|x| x.contains("tc6_0201")), "{xml}");
        let _ = project.add_petri_pou("Cycle");
        let pnml: serde_json::Value =
            serde_json::from_str(&super::export_reply("export-pnml", "cycle", &project.to_file()))
                .unwrap_or_default();
        assert!(pnml["xml"].as_str().is_some_and(|x| x.contains("<pnml")), "{pnml}");
        let none: serde_json::Value =
            serde_json::from_str(&super::export_reply("export-pnml", "Nope", &project.to_file()))
                .unwrap_or_default();
        assert!(none["error"].as_str().is_some_and(|e| e.contains("Nope")), "{none}");
    }
}
