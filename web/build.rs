//! Lists the shipped examples (`../examples/*.st` and `*.plcproj.json`) for the app's
//! "Open example" menu: writes `$OUT_DIR/examples.rs` with each file's name, menu title and
//! rank, in menu order. The files themselves are copied next to the page by Trunk and
//! fetched when chosen, so they cost the first load nothing.

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

fn main() {
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
