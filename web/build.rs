//! Lists the shipped examples (`../examples/*.st` and `*.plcproj.json`) for the app's
//! "Open example" menu: writes `$OUT_DIR/examples.rs` with each file's name, menu title and
//! rank, in menu order. The files themselves are copied next to the page by Trunk and
//! fetched when chosen, so they cost the first load nothing.
//!
//! Lists the shipped exercises (`../exercises/ID/ID.toml`) too: `$OUT_DIR/exercises.rs`
//! holds the catalogue (id, title, level, languages: all the page needs before one is
//! opened; `TITLES` the Polish and Czech titles), and `$OUT_DIR/exercises/ID.json` each exercise with its starter, as the
//! exercise link that opens it (`plc_core::exercise::ExerciseLink`), the exercise in the
//! built form (`core/src/exercise/built_form.rs`: JSON, its statement and its translations'
//! rendered), so that
//! the exercise worker reads it without a TOML reader or a Markdown renderer.
//! `scripts/build-web.sh` puts these files next to the app; the worker fetches the one it
//! opens (natively, in tests, `$OUT_DIR/exercise_files.rs` includes them). The reference
//! solutions and mutants are never shipped.
//!
//! Reads the page's words (`i18n/LANG/PART.json`: per language a folder, per part of the
//! page a file a translator edits, keys starting with the part's name): `$OUT_DIR/i18n.rs`
//! holds one key per English text (`K`) and the English texts, so a key the code names but
//! the catalogue lacks does not compile; each translation is checked against English
//! (every key, nothing more, not empty, the same `{placeholders}`), and the build stops
//! with the list of what is wrong. `$OUT_DIR/i18n/LANG.json` is the translation as an array
//! in key order, which the page fetches when the language is chosen (`scripts/build-web.sh`
//! puts it next to the app).

use std::fmt::Write as _;
use std::path::Path;

/// The package's folder, as cargo gives it when the script runs (not when it was compiled:
/// a build script compiled once may serve another checkout of the same package).
fn manifest_dir() -> std::path::PathBuf {
    std::path::PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").unwrap_or_default())
}

mod naming {
    include!("src/examples/naming.rs");
}

/// The statement's renderer, as the exercise worker would run it.
#[allow(dead_code)]
#[path = "../core/src/exercise/statement.rs"]
mod statement;

/// The built form of an exercise file.
#[allow(dead_code)]
#[path = "../core/src/exercise/built_form.rs"]
mod built_form;

/// The project name and whether it has ladder and Petri net POUs.
fn project_facts(text: &str) -> Option<(String, bool, bool)> {
    let v: serde_json::Value = serde_json::from_str(text).ok()?;
    let has = |k: &str| v.get(k).and_then(|a| a.as_array()).is_some_and(|a| !a.is_empty());
    Some((v.get("name")?.as_str()?.to_string(), has("ladder"), has("petri")))
}

/// What the catalogue needs of an exercise file.
#[derive(serde::Deserialize)]
struct Entry {
    id: String,
    title: String,
    level: u8,
    #[serde(default)]
    order: Option<u32>,
    #[serde(default)]
    languages: Vec<String>,
    #[serde(default)]
    starter: Option<String>,
    #[serde(default)]
    starter_st: Option<String>,
    #[serde(default)]
    starter_ld: Option<String>,
    #[serde(default)]
    starter_petri: Option<String>,
    #[serde(default)]
    starter_sfc: Option<String>,
    /// The translations (`[lang.pl]`, `[lang.cs]`): the catalogue needs their titles.
    #[serde(default)]
    lang: std::collections::BTreeMap<String, EntryLang>,
}

/// What the catalogue needs of a translation: its title.
#[derive(serde::Deserialize)]
struct EntryLang {
    #[serde(default)]
    title: Option<String>,
}

impl Entry {
    /// Every starter file the exercise names, once each.
    fn starter_files(&self) -> Vec<&str> {
        let mut out: Vec<&str> = Vec::new();
        let named = [&self.starter, &self.starter_st, &self.starter_ld, &self.starter_petri];
        for f in named.into_iter().chain([&self.starter_sfc]).filter_map(|f| f.as_deref()) {
            if !out.contains(&f) {
                out.push(f);
            }
        }
        out
    }
}

/// Writes the exercise catalogue and files (see the module's doc).
fn exercises(out: &Path) {
    let dir = manifest_dir().join("../exercises");
    println!("cargo:rerun-if-changed={}", dir.display());
    for file in ["statement.rs", "built_form.rs"] {
        println!("cargo:rerun-if-changed=../core/src/exercise/{file}");
    }
    let mut entries: Vec<(Entry, std::path::PathBuf)> = Vec::new();
    for folder in std::fs::read_dir(&dir).into_iter().flatten().flatten() {
        let id = folder.file_name().to_string_lossy().into_owned();
        let file = folder.path().join(format!("{id}.toml"));
        println!("cargo:rerun-if-changed={}", folder.path().display());
        println!("cargo:rerun-if-changed={}", file.display());
        let Ok(text) = std::fs::read_to_string(&file) else { continue };
        match toml::from_str::<Entry>(&text) {
            Ok(entry) => entries.push((entry, folder.path())),
            Err(e) => panic!("{}: {e}", file.display()),
        }
    }
    entries.sort_by(|a, b| {
        let key = |e: &Entry| (e.level, e.order.unwrap_or(u32::MAX));
        key(&a.0).cmp(&key(&b.0)).then_with(|| a.0.title.cmp(&b.0.title))
    });
    let mut catalogue = String::from(
        "/// The shipped exercises, easiest first: (id, title, level, languages).\npub const CATALOGUE: &[(&str, &str, u8, &[&str])] = &[\n",
    );
    let mut titles = String::from(
        "\n/// The shipped exercises' titles in Polish and Czech, in the catalogue's order: (id, pl, cs),\n/// the English one where a translation has none.\npub const TITLES: &[(&str, &str, &str)] = &[\n",
    );
    let mut files = String::from(
        "/// The shipped exercises as the links that open them: (id, JSON of the link).\npub const FILES: &[(&str, &str)] = &[\n",
    );
    let folder_out = out.join("exercises");
    if let Err(e) = std::fs::create_dir_all(&folder_out) {
        panic!("cannot create {}: {e}", folder_out.display());
    }
    for (e, folder) in &entries {
        let _ = writeln!(
            catalogue,
            "    ({:?}, {:?}, {}, &{:?}),",
            e.id, e.title, e.level, e.languages
        );
        let title_in = |tag: &str| {
            e.lang.get(tag).and_then(|t| t.title.clone()).unwrap_or_else(|| e.title.clone())
        };
        let _ = writeln!(titles, "    ({:?}, {:?}, {:?}),", e.id, title_in("pl"), title_in("cs"));
        let file = folder.join(format!("{}.toml", e.id));
        let text = std::fs::read_to_string(&file).unwrap_or_default();
        let built = built_form::built_form(&text, |m| statement::statement_html(m, None))
            .unwrap_or_else(|err| panic!("{}: {err}", file.display()));
        // Every starter file the exercise names: the one named `starter` in its place, the
        // other languages' in `starters` (as `ExerciseLink::arranged` puts them).
        let mut starter = None;
        let mut starters = Vec::new();
        for name in e.starter_files() {
            let path = folder.join(name);
            println!("cargo:rerun-if-changed={}", path.display());
            let text = std::fs::read_to_string(&path)
                .unwrap_or_else(|err| panic!("{}: {err}", path.display()));
            let linked = serde_json::json!({ "name": name, "text": text });
            if e.starter.as_deref() == Some(name) {
                starter = Some(linked);
            } else {
                starters.push(linked);
            }
        }
        let link =
            serde_json::json!({ "exercise": built, "starter": starter, "starters": starters });
        let target = folder_out.join(format!("{}.json", e.id));
        if let Err(err) = std::fs::write(&target, link.to_string()) {
            panic!("cannot write {}: {err}", target.display());
        }
        let _ =
            writeln!(files, "    ({:?}, include_str!({:?})),", e.id, target.display().to_string());
    }
    catalogue.push_str("];\n");
    catalogue.push_str(&titles);
    catalogue.push_str("];\n");
    files.push_str("];\n");
    for (name, text) in [("exercises.rs", catalogue), ("exercise_files.rs", files)] {
        if let Err(e) = std::fs::write(out.join(name), text) {
            panic!("cannot write {name}: {e}");
        }
    }
}

/// The `{placeholders}` of a text, sorted.
fn placeholders(text: &str) -> Vec<&str> {
    let mut found: Vec<&str> = text
        .split('{')
        .skip(1)
        .filter_map(|part| part.split_once('}').map(|(name, _)| name))
        .collect();
    found.sort_unstable();
    found
}

/// Reads a catalogue file: a JSON object of key → text.
fn catalogue(path: &Path) -> Result<Vec<(String, String)>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let map: serde_json::Map<String, serde_json::Value> =
        serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    map.into_iter()
        .map(|(k, v)| match v {
            serde_json::Value::String(s) => Ok((k, s)),
            _ => Err(format!("{}: `{k}` is not a text", path.display())),
        })
        .collect()
}

/// The part files of one language's folder (`i18n/LANG/PART.json`), sorted by name.
fn part_files(dir: &Path) -> Vec<String> {
    let mut parts: Vec<String> = std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(|e| e.file_name().into_string().ok())
        .filter_map(|n| n.strip_suffix(".json").map(str::to_string))
        .collect();
    parts.sort();
    parts
}

/// The page's words: the key enum and English texts, the translations checked and written
/// as arrays in key order.
fn i18n(out_dir: &Path) {
    let dir = manifest_dir().join("i18n");
    println!("cargo:rerun-if-changed={}", dir.display());
    let mut problems = Vec::new();
    // English, part by part: every key starts with its part's name and a dot.
    let mut en: Vec<(String, String)> = Vec::new();
    let en_dir = dir.join("en");
    println!("cargo:rerun-if-changed={}", en_dir.display());
    let parts = part_files(&en_dir);
    for part in &parts {
        let file = en_dir.join(format!("{part}.json"));
        println!("cargo:rerun-if-changed={}", file.display());
        let texts = catalogue(&file).unwrap_or_else(|e| panic!("{e}"));
        for (key, text) in texts {
            if !key
                .chars()
                .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_' || c == '.')
                || !key.starts_with(&format!("{part}."))
            {
                problems.push(format!(
                    "en/{part}.json: the key `{key}` is not `{part}.` and lowercase words joined by `_` and `.`"
                ));
            }
            if text.trim().is_empty() {
                problems.push(format!("en/{part}.json: `{key}` is empty"));
            }
            en.push((key, text));
        }
    }
    // ---- The diagnostics' messages (issue 33): core/i18n/messages.LANG.json as the part
    // `diag` (keys `diag.KEY`), after every part of the page so that `K::diag_*` are in
    // `plc_core::diagnostics::Msg` order (key order) from `DIAG_START` on: the page finds a
    // message's translation at `DIAG_START + Msg::index`. ----
    let core_i18n = manifest_dir().join("../core/i18n");
    let diag_file = |lang: &str| core_i18n.join(format!("messages.{lang}.json"));
    if parts.iter().any(|p| p == "diag") {
        problems.push("en/diag.json: the part `diag` is the diagnostics' (core/i18n/)".into());
    }
    let diag_start = en.len();
    println!("cargo:rerun-if-changed={}", diag_file("en").display());
    match catalogue(&diag_file("en")) {
        Ok(mut texts) => {
            texts.sort();
            en.extend(texts.into_iter().map(|(k, v)| (format!("diag.{k}"), v)))
        }
        Err(e) => problems.push(e),
    }
    // ---- end of the diagnostics' hunk ----
    let _ = std::fs::create_dir_all(out_dir.join("i18n"));
    for lang in ["pl", "cs"] {
        let lang_dir = dir.join(lang);
        println!("cargo:rerun-if-changed={}", lang_dir.display());
        let mut tr: Vec<(String, String)> = Vec::new();
        for part in part_files(&lang_dir) {
            if !parts.contains(&part) {
                problems.push(format!("{lang}/{part}.json: there is no en/{part}.json"));
            }
        }
        for part in &parts {
            let file = lang_dir.join(format!("{part}.json"));
            println!("cargo:rerun-if-changed={}", file.display());
            match catalogue(&file) {
                Ok(texts) => tr.extend(texts),
                Err(e) => problems.push(e),
            }
        }
        // The diagnostics' messages in this language (see above).
        println!("cargo:rerun-if-changed={}", diag_file(lang).display());
        match catalogue(&diag_file(lang)) {
            Ok(texts) => tr.extend(texts.into_iter().map(|(k, v)| (format!("diag.{k}"), v))),
            Err(e) => problems.push(e),
        }
        let lookup: std::collections::BTreeMap<&str, &str> =
            tr.iter().map(|(k, v)| (k.as_str(), v.as_str())).collect();
        for (key, _) in &tr {
            if !en.iter().any(|(k, _)| k == key) {
                problems.push(format!("{lang}: `{key}` is not in English"));
            }
        }
        let mut array = Vec::new();
        for (key, text) in &en {
            match lookup.get(key.as_str()) {
                None => problems.push(format!("{lang}: `{key}` is missing")),
                Some(t) if t.trim().is_empty() => {
                    problems.push(format!("{lang}: `{key}` is empty"))
                }
                Some(t) if placeholders(t) != placeholders(text) => problems.push(format!(
                    "{lang}: `{key}` has the placeholders {:?}, English {:?}",
                    placeholders(t),
                    placeholders(text)
                )),
                Some(t) => array.push(serde_json::Value::String(t.to_string())),
            }
        }
        let json = serde_json::to_string(&array).unwrap_or_default();
        let _ = std::fs::write(out_dir.join("i18n").join(format!("{lang}.json")), json);
    }
    let mut seen = std::collections::BTreeSet::new();
    for (key, _) in &en {
        if !seen.insert(key.as_str()) {
            problems.push(format!("`{key}` is in English twice"));
        }
    }
    if !problems.is_empty() {
        panic!("the page's words (web/i18n/) are not complete:\n{}", problems.join("\n"));
    }
    let variant = |key: &str| key.replace('.', "_");
    // Each key is a constant holding its place and its English text, so the English of a
    // part shown only in a lazily loaded view is data of that view's chunk, not of the
    // first load (wasm-split moves data with the code that alone uses it).
    let mut out = String::from(
        "/// One text of the page: its place in a translation file and its English.\n\
         #[derive(Debug, PartialEq, Eq)]\npub struct Entry {\n    index: u16,\n    en: &'static str,\n}\n\n\
         /// A text of the page: one per entry of `web/i18n/en/*.json` (dots become `_`).\n\
         #[derive(Debug, Clone, Copy, PartialEq, Eq)]\npub struct K(&'static Entry);\n\n\
         #[allow(non_upper_case_globals)]\nimpl K {\n",
    );
    for (i, (key, text)) in en.iter().enumerate() {
        if i == diag_start {
            // The diagnostics' messages: the page shows them by `Msg` (`message_text`);
            // only a few are named (`K::diag_did_you_mean`).
            out.push_str("}\n\n#[allow(non_upper_case_globals, dead_code)]\nimpl K {\n");
        }
        let _ = writeln!(
            out,
            "    /// {}\n    pub const {}: K = K(&Entry {{ index: {i}, en: {:?} }});",
            text.replace('\n', " "),
            variant(key),
            text
        );
    }
    out.push_str(
        "\n    /// The English text.\n    pub fn en(self) -> &'static str {\n        self.0.en\n    }\n\n\
         /// Its place in a translation file.\n    pub fn index(self) -> usize {\n        usize::from(self.0.index)\n    }\n}\n\n\
         /// How many texts the page has (a translation file holds as many).\npub const COUNT: usize = ",
    );
    let _ = writeln!(out, "{};", en.len());
    // The diagnostics' part: their keys from DIAG_START on, in `Msg` order.
    let _ = writeln!(
        out,
        "\n/// The place of the first diagnostic's message (`diag.*`, in `Msg` order).\npub const DIAG_START: usize = {diag_start};"
    );
    let _ = std::fs::write(out_dir.join("i18n.rs"), out);
}

fn main() {
    let out_dir = std::env::var("OUT_DIR").unwrap_or_else(|_| ".".into());
    exercises(Path::new(&out_dir));
    i18n(Path::new(&out_dir));
    let dir = manifest_dir().join("../examples");
    println!("cargo:rerun-if-changed={}", dir.display());
    let files: Vec<String> = std::fs::read_dir(&dir)
        .map(|entries| {
            entries
                .filter_map(|e| e.ok()?.file_name().into_string().ok())
                .filter(|n| n.ends_with(".st") || n.ends_with(".plcproj.json"))
                .collect()
        })
        .unwrap_or_default();
    let mut list: Vec<(String, String, u8)> = Vec::new();
    for f in files {
        let path = dir.join(&f);
        println!("cargo:rerun-if-changed={}", path.display());
        let text = std::fs::read_to_string(&path).unwrap_or_default();
        let facts = project_facts(&text);
        let (title, rank) =
            naming::describe(&f, facts.as_ref().map(|(n, l, p)| (n.as_str(), *l, *p)));
        list.push((f, title, rank));
    }
    list.sort_by(|a, b| a.2.cmp(&b.2).then_with(|| a.1.cmp(&b.1)));
    // Each example's title is a text of the page's catalogue (`examples.STEM`, translated
    // like every other), whose English is the title the file gives; its description is
    // `examples.STEM_about`.
    let titles = catalogue(&manifest_dir().join("i18n/en/examples.json")).unwrap_or_default();
    let mut problems = Vec::new();
    let mut out = String::from(
        "/// The shipped examples in menu order: (file name, English title, rank, title's key,\n/// description's key).\npub const EXAMPLES: &[(&str, &str, u8, crate::i18n::K, crate::i18n::K)] = &[\n",
    );
    for (f, title, rank) in &list {
        let key = format!("examples.{}", naming::stem(f).replace('-', "_"));
        match titles.iter().find(|(k, _)| *k == key) {
            Some((_, en)) if en == title => {}
            Some((_, en)) => problems.push(format!(
                "web/i18n/en/examples.json: `{key}` is “{en}”, the example {f} is titled “{title}”"
            )),
            None => problems.push(format!(
                "web/i18n/en/examples.json: no `{key}` (“{title}”) for the example {f}"
            )),
        }
        // Its description (`examples.STEM_about`): the menu entry's tooltip.
        let about = format!("{key}_about");
        if !titles.iter().any(|(k, _)| *k == about) {
            problems.push(format!(
                "web/i18n/en/examples.json: no `{about}` (a one-line description) for the example {f}"
            ));
        }
        let _ = writeln!(
            out,
            "    ({f:?}, {title:?}, {rank}, crate::i18n::K::{}, crate::i18n::K::{}),",
            key.replace('.', "_"),
            about.replace('.', "_")
        );
    }
    for (key, _) in &titles {
        let stem = key.strip_suffix("_about").unwrap_or(key);
        if !list
            .iter()
            .any(|(f, _, _)| format!("examples.{}", naming::stem(f).replace('-', "_")) == stem)
        {
            problems.push(format!("web/i18n/en/examples.json: `{key}` belongs to no example"));
        }
    }
    if !problems.is_empty() {
        panic!("the examples' titles:\n{}", problems.join("\n"));
    }
    out.push_str("];\n");
    let target =
        Path::new(&std::env::var("OUT_DIR").unwrap_or_else(|_| ".".into())).join("examples.rs");
    if let Err(e) = std::fs::write(&target, out) {
        panic!("cannot write {}: {e}", target.display());
    }
}
