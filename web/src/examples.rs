//! The shipped examples (`examples/*.st` and `*.plcproj.json`): the menu, listed at build
//! time by `build.rs`, and opening one as a new project. The files are copied next to the
//! page (`examples/` in `dist/`) and fetched when chosen.

use plc_core::open::open_plain_by;
use plc_core::project::Project;
use wasm_bindgen::JsCast;
use wasm_bindgen_futures::JsFuture;

use crate::i18n::{said_text, shown_lang, t, tf, K};

mod naming {
    #![allow(dead_code)]
    include!("examples/naming.rs");
}
mod list {
    include!(concat!(env!("OUT_DIR"), "/examples.rs"));
}

/// One example of the menu.
#[derive(Debug, Clone, PartialEq)]
pub struct Example {
    /// Its file name in `examples/`.
    pub file: &'static str,
    /// Its title in English (the project's name in the file, or the file's name).
    pub title: &'static str,
    /// Its title in the page's catalogue: what the menu shows, in the language shown.
    pub key: K,
    /// Its one-line description in the page's catalogue (the menu entry's tooltip).
    pub about: K,
}

/// Every shipped example, in menu order (ladder projects, ST, then Petri nets).
pub fn examples() -> Vec<Example> {
    list::EXAMPLES
        .iter()
        .map(|&(file, title, _, key, about)| Example { file, title, key, about })
        .collect()
}

/// The example `file` (its text) as a new project.
pub fn project_of(file: &str, text: &str) -> Result<Project, String> {
    let name = naming::humanise(naming::stem(file));
    let mut project = open_plain_by(&name, text, crate::lazy::project_reader())
        .map_err(|e| said_text(e.said()))?
        .ok_or_else(|| tf(K::state_example_not_project, &[("file", file)]))?
        .project;
    if project.name.trim().is_empty() {
        project.name = name;
    }
    Ok(project)
}

/// Fetches the example `file` from the site and opens it as a new project, named with
/// its title in the language shown.
pub async fn open(file: &str) -> Result<Project, String> {
    let Some(&(_, _, _, key, _)) = list::EXAMPLES.iter().find(|(f, _, _, _, _)| *f == file) else {
        return Err(tf(K::state_example_missing, &[("file", file)]));
    };
    let fail = |_| tf(K::state_example_unreachable, &[("file", file)]);
    let window = web_sys::window().ok_or("no window")?;
    let response: web_sys::Response =
        JsFuture::from(window.fetch_with_str(&format!("examples/{file}")))
            .await
            .map_err(fail)?
            .dyn_into()
            .map_err(|_| fail(wasm_bindgen::JsValue::NULL))?;
    if !response.ok() {
        return Err(tf(
            K::state_example_http,
            &[("file", file), ("status", &response.status().to_string())],
        ));
    }
    let text = JsFuture::from(response.text().map_err(fail)?).await.map_err(fail)?;
    let text = text.as_string().unwrap_or_default();
    // A ladder or Petri net example needs the diagram models' readers (a chunk).
    crate::lazy::readers_for(&text).await.map_err(|e| e.to_string())?;
    let mut project = project_of(file, &text)?;
    if shown_lang() != plc_core::i18n::Lang::En {
        project.name = t(key).to_string();
    }
    Ok(project)
}

#[cfg(test)]
mod tests;
