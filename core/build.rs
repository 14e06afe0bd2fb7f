//! Turns the diagnostics' message catalogue (`i18n/messages.en.json`: key → English
//! template with `{name}` placeholders) into the enum `Msg` (one variant per key, in key
//! order), its English table, and the macro `msg_en!` that gives one key's English template
//! as a literal, so a diagnostic made in a lazily loaded part of the engine carries only its
//! own English text. A key the catalogue lacks does not compile.

use std::fmt::Write as _;
use std::path::Path;

/// The package's folder, as cargo gives it when the script runs (not when it was compiled:
/// a build script compiled once may serve another checkout of the same package).
fn manifest_dir() -> std::path::PathBuf {
    std::path::PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").unwrap_or_default())
}

/// `undeclared_name` → `UndeclaredName`, `expect.type_name` → `ExpectTypeName`.
fn variant(key: &str) -> String {
    key.split(['_', '.'])
        .map(|w| {
            let mut c = w.chars();
            c.next().map(|f| f.to_ascii_uppercase().to_string() + c.as_str()).unwrap_or_default()
        })
        .collect()
}

fn main() {
    let file = manifest_dir().join("i18n/messages.en.json");
    println!("cargo:rerun-if-changed={}", file.display());
    let text = std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
    let map: serde_json::Map<String, serde_json::Value> =
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
    let mut problems = Vec::new();
    let mut rows: Vec<(String, String, String)> = Vec::new();
    for (key, value) in map {
        let Some(template) = value.as_str() else {
            problems.push(format!("`{key}` is not a text"));
            continue;
        };
        if key.is_empty()
            || !key
                .chars()
                .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_' || c == '.')
        {
            problems.push(format!("the key `{key}` is not lowercase words joined by `_` and `.`"));
        }
        if template.trim().is_empty() {
            problems.push(format!("`{key}` is empty"));
        }
        let v = variant(&key);
        if rows.iter().any(|(_, w, _)| *w == v) {
            problems.push(format!("`{key}` makes the variant `{v}` twice"));
        }
        rows.push((key, v, template.to_string()));
    }
    // Key order, whatever order the map keeps (the page's translation arrays follow it).
    rows.sort();
    if !problems.is_empty() {
        panic!("core/i18n/messages.en.json:\n{}", problems.join("\n"));
    }
    let mut out = String::from(
        "/// A diagnostic's message: one per key of `core/i18n/messages.en.json`, in key order.\n\
         #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]\n#[non_exhaustive]\npub enum Msg {\n",
    );
    for (key, v, template) in &rows {
        let _ = writeln!(out, "    /// `{key}`: {}\n    {v},", template.replace('\n', " "));
    }
    let _ = writeln!(
        out,
        "}}\n\n/// How many messages there are.\npub const MSG_COUNT: usize = {};\n",
        rows.len()
    );
    out.push_str("impl Msg {\n    /// Every message, in key order (the order of the translations' arrays).\n    pub const ALL: [Msg; MSG_COUNT] = [\n");
    for (_, v, _) in &rows {
        let _ = writeln!(out, "        Msg::{v},");
    }
    out.push_str("    ];\n\n    /// The catalogue key (`undeclared_name`).\n    pub fn key(self) -> &'static str {\n        KEYS[self as usize]\n    }\n\n    /// The English template.\n    pub fn en(self) -> &'static str {\n        EN[self as usize]\n    }\n\n    /// Its place in key order (`ALL[m.index()] == m`).\n    pub fn index(self) -> usize {\n        self as usize\n    }\n}\n\n");
    out.push_str("static KEYS: [&str; MSG_COUNT] = [\n");
    for (key, _, _) in &rows {
        let _ = writeln!(out, "    {key:?},");
    }
    out.push_str("];\n\nstatic EN: [&str; MSG_COUNT] = [\n");
    for (_, _, t) in &rows {
        let _ = writeln!(out, "    {t:?},");
    }
    out.push_str("];\n\n/// One message's English template as a literal: `msg_en!(UndeclaredName)`.\nmacro_rules! msg_en {\n");
    for (_, v, t) in &rows {
        let _ = writeln!(out, "    ({v}) => {{ {t:?} }};");
    }
    out.push_str("}\n");
    let out_dir = std::env::var("OUT_DIR").unwrap_or_else(|_| ".".into());
    let target = Path::new(&out_dir).join("messages.rs");
    if let Err(e) = std::fs::write(&target, out) {
        panic!("cannot write {}: {e}", target.display());
    }
}
