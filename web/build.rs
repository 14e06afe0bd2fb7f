//! Lists the shipped examples (`../examples/*.st` and `*.plcproj.json`) for the app's
//! "Open example" menu: writes `$OUT_DIR/examples.rs` with each file's name, menu title and
//! rank, in menu order. The files themselves are copied next to the page by Trunk and
//! fetched when chosen, so they cost the first load nothing.
//!
//! Lists the shipped exercises (`../exercises/ID/ID.toml`) too: `$OUT_DIR/exercises.rs`
//! holds the catalogue (id, title, level, languages: all the page needs before one is
//! opened) and `$OUT_DIR/exercise_files.rs` each exercise file and its starter, which only
//! the exercise worker includes (the reference solutions and mutants are never built in).

use std::fmt::Write as _;
use std::path::Path;

mod naming {
    include!("src/examples/naming.rs");
}

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
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../exercises");
    println!("cargo:rerun-if-changed={}", dir.display());
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
    let mut files = String::from(
        "/// A starter file: (name, text).\npub type Starter = (&'static str, &'static str);\n/// The shipped exercises' files: (id, exercise file, the starter files it names).\npub const FILES: &[(&str, &str, &[Starter])] = &[\n",
    );
    for (e, folder) in &entries {
        let _ = writeln!(
            catalogue,
            "    ({:?}, {:?}, {}, &{:?}),",
            e.id, e.title, e.level, e.languages
        );
        let file = folder.join(format!("{}.toml", e.id));
        let starters: Vec<String> = e
            .starter_files()
            .into_iter()
            .map(|name| {
                let path = folder.join(name);
                println!("cargo:rerun-if-changed={}", path.display());
                format!("({name:?}, include_str!({:?}))", path.display().to_string())
            })
            .collect();
        let starter = format!("&[{}]", starters.join(", "));
        let _ = writeln!(
            files,
            "    ({:?}, include_str!({:?}), {starter}),",
            e.id,
            file.display().to_string()
        );
    }
    catalogue.push_str("];\n");
    files.push_str("];\n");
    for (name, text) in [("exercises.rs", catalogue), ("exercise_files.rs", files)] {
        if let Err(e) = std::fs::write(out.join(name), text) {
            panic!("cannot write {name}: {e}");
        }
    }
}

fn main() {
    let out_dir = std::env::var("OUT_DIR").unwrap_or_else(|_| ".".into());
    exercises(Path::new(&out_dir));
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples");
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
    let mut out = String::from(
        "/// The shipped examples in menu order: (file name, title, rank).\npub const EXAMPLES: &[(&str, &str, u8)] = &[\n",
    );
    for (f, title, rank) in &list {
        let _ = writeln!(out, "    ({f:?}, {title:?}, {rank}),");
    }
    out.push_str("];\n");
    let target =
        Path::new(&std::env::var("OUT_DIR").unwrap_or_else(|_| ".".into())).join("examples.rs");
    if let Err(e) = std::fs::write(&target, out) {
        panic!("cannot write {}: {e}", target.display());
    }
}
