//! Dependencies inside `core` run one way (issue 12, `core/README.md` "Floors").
//!
//! Reads every `crate::…`, `super::…` and `self::…` path in `core/src` (test-only code left
//! out: `#[cfg(test)]` items and modules) and fails when
//! - a top-level module uses a module of a higher floor than its own (the floors are the
//!   fenced `floors` block of `core/README.md`, highest first), or a module is on no floor;
//! - two modules that share a parent use each other, directly or round a longer circle
//!   (at the top level and inside every module: `syntax/ast.rs` ↔ `syntax/sfc_ast.rs` is
//!   as much a circle as `vm` ↔ `compile`). A file may use its own parent (`super::X` in a
//!   child of `mod.rs`) and its own children: that is the module's front door, not a circle.
//!
//! The checker is tested on small fixtures below, with an upward import and with two
//! modules using each other, so that a change that silences it fails here.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A module path from the crate root (`["vm", "arith"]`); the root is empty.
type ModPath = Vec<String>;

/// One use of another module: where it is written and what it names.
#[derive(Debug, Clone)]
struct Use {
    file: String,
    line: usize,
    from: ModPath,
    to: ModPath,
}

/// The crate's source: file path (relative, `/`-separated) → text.
type Sources = BTreeMap<String, String>;

// ---------------------------------------------------------------------------------------
// Reading the source
// ---------------------------------------------------------------------------------------

/// The source with comments, string and char literals blanked (same length, newlines kept),
/// so that paths are only found in code and offsets still give line numbers.
fn blank_non_code(src: &str) -> String {
    let b = src.as_bytes();
    let mut out = b.to_vec();
    let mut i = 0;
    let blank = |out: &mut Vec<u8>, from: usize, to: usize| {
        for c in out.iter_mut().take(to).skip(from) {
            if *c != b'\n' {
                *c = b' ';
            }
        }
    };
    while i < b.len() {
        match b[i] {
            b'/' if b.get(i + 1) == Some(&b'/') => {
                let end = src[i..].find('\n').map_or(b.len(), |k| i + k);
                blank(&mut out, i, end);
                i = end;
            }
            b'/' if b.get(i + 1) == Some(&b'*') => {
                let (mut depth, mut j) = (0usize, i);
                while j < b.len() {
                    if b[j] == b'/' && b.get(j + 1) == Some(&b'*') {
                        depth += 1;
                        j += 2;
                    } else if b[j] == b'*' && b.get(j + 1) == Some(&b'/') {
                        depth -= 1;
                        j += 2;
                        if depth == 0 {
                            break;
                        }
                    } else {
                        j += 1;
                    }
                }
                blank(&mut out, i, j);
                i = j;
            }
            b'r' if matches!(b.get(i + 1), Some(b'#') | Some(b'"'))
                && (i == 0 || !is_ident(b[i - 1])) =>
            {
                let hashes = b[i + 1..].iter().take_while(|&&c| c == b'#').count();
                if b.get(i + 1 + hashes) != Some(&b'"') {
                    i += 1;
                    continue;
                }
                let close = format!("\"{}", "#".repeat(hashes));
                let start = i + 2 + hashes;
                let end = src[start..].find(&close).map_or(b.len(), |k| start + k + close.len());
                blank(&mut out, i, end);
                i = end;
            }
            b'"' => {
                let mut j = i + 1;
                while j < b.len() && b[j] != b'"' {
                    j += if b[j] == b'\\' { 2 } else { 1 };
                }
                blank(&mut out, i, (j + 1).min(b.len()));
                i = j + 1;
            }
            b'\'' => {
                // A char literal ('x', '\n', '\u{..}'), not a lifetime ('a).
                let end = if b.get(i + 1) == Some(&b'\\') {
                    src[i + 2..].find('\'').map(|k| i + 2 + k)
                } else if b.get(i + 2) == Some(&b'\'') {
                    Some(i + 2)
                } else {
                    src[i + 1..].chars().next().and_then(|c| {
                        let k = i + 1 + c.len_utf8();
                        (b.get(k) == Some(&b'\'')).then_some(k)
                    })
                };
                match end {
                    Some(e) => {
                        blank(&mut out, i, e + 1);
                        i = e + 1;
                    }
                    None => i += 1,
                }
            }
            _ => i += 1,
        }
    }
    String::from_utf8(out).unwrap_or_default()
}

fn is_ident(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

/// The index just past the brace that closes the one at `open`.
fn matching_brace(b: &[u8], open: usize) -> usize {
    let mut depth = 0usize;
    for (k, &c) in b.iter().enumerate().skip(open) {
        match c {
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                if depth == 0 {
                    return k + 1;
                }
            }
            _ => {}
        }
    }
    b.len()
}

/// Blanks every `#[cfg(test)]` item of `code` (already stripped of comments) and returns
/// the names of the child modules declared test-only by `#[cfg(test)] mod name;`.
fn blank_test_items(code: &mut String) -> Vec<String> {
    let mut test_children = Vec::new();
    let mut from = 0;
    while let Some(k) = code[from..].find("#[cfg(test)]") {
        let start = from + k;
        let b = code.as_bytes();
        let mut j = start + "#[cfg(test)]".len();
        // The item ends at the first `;` or at the brace closing its first `{`.
        let mut end = b.len();
        while j < b.len() {
            match b[j] {
                b';' => {
                    end = j + 1;
                    break;
                }
                b'{' => {
                    end = matching_brace(b, j);
                    break;
                }
                _ => j += 1,
            }
        }
        let item = code[start..end].to_string();
        let words: Vec<&str> = item
            .split(|c: char| !(c.is_alphanumeric() || c == '_' || c == ';'))
            .filter(|w| !w.is_empty())
            .collect();
        if let Some(p) = words.iter().position(|w| *w == "mod") {
            if let Some(name) = words.get(p + 1) {
                if let Some(name) = name.strip_suffix(';') {
                    test_children.push(name.to_string());
                }
            }
        }
        let blanked: String = item.chars().map(|c| if c == '\n' { '\n' } else { ' ' }).collect();
        code.replace_range(start..end, &blanked);
        from = end;
    }
    test_children
}

/// Every path written from `crate::`, `super::` or `self::` in `code`, expanded from use
/// trees (`crate::{a::B, c::{d, e}}`), with the byte offset where it starts.
fn paths(code: &str) -> Vec<(usize, Vec<String>)> {
    let b = code.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let rest = &code[i..];
        let head = ["crate::", "super::", "self::"].into_iter().find(|h| rest.starts_with(h));
        let boundary = i == 0 || !(is_ident(b[i - 1]) || b[i - 1] == b':');
        match head {
            Some(h) if boundary => {
                let first = h.trim_end_matches(':').to_string();
                let mut j = i + h.len();
                tree(code, &mut j, vec![first], &mut |p| out.push((i, p)));
                i = j.max(i + 1);
            }
            _ => i += 1,
        }
    }
    out
}

/// Reads one use tree at `*j` (after `prefix::`), calling `emit` with each full path.
fn tree(code: &str, j: &mut usize, prefix: Vec<String>, emit: &mut dyn FnMut(Vec<String>)) {
    let b = code.as_bytes();
    let skip_ws = |j: &mut usize| {
        while *j < b.len() && b[*j].is_ascii_whitespace() {
            *j += 1;
        }
    };
    let mut path = prefix;
    loop {
        skip_ws(j);
        if *j < b.len() && b[*j] == b'{' {
            *j += 1;
            loop {
                skip_ws(j);
                if *j >= b.len() || b[*j] == b'}' {
                    *j += 1;
                    return;
                }
                tree(code, j, path.clone(), emit);
                skip_ws(j);
                if *j < b.len() && b[*j] == b',' {
                    *j += 1;
                }
            }
        }
        let start = *j;
        while *j < b.len() && (is_ident(b[*j]) || b[*j] == b'*') {
            *j += 1;
        }
        if *j > start {
            path.push(code[start..*j].to_string());
        }
        skip_ws(j);
        if code[*j..].starts_with("::") {
            *j += 2;
            continue;
        }
        emit(path);
        return;
    }
}

// ---------------------------------------------------------------------------------------
// Resolving and checking
// ---------------------------------------------------------------------------------------

/// The module path of a source file (`vm/mod.rs` → `vm`, `vm/arith.rs` → `vm::arith`).
fn module_of(file: &str) -> ModPath {
    let stem = file.trim_end_matches(".rs");
    let mut parts: Vec<String> = stem.split('/').map(str::to_string).collect();
    if matches!(parts.last().map(String::as_str), Some("mod") | Some("lib")) {
        parts.pop();
    }
    parts
}

/// Turns a written path into the module it names: `super`/`self` resolved against `from`,
/// then cut to the longest prefix that is a module of the crate.
fn target(from: &ModPath, written: &[String], modules: &BTreeSet<ModPath>) -> Option<ModPath> {
    let mut abs: ModPath = Vec::new();
    let mut rest = written;
    match written.first().map(String::as_str) {
        Some("crate") => rest = &written[1..],
        Some("self") => {
            abs = from.clone();
            rest = &written[1..];
        }
        Some("super") => {
            abs = from.clone();
            while rest.first().map(String::as_str) == Some("super") {
                abs.pop()?;
                rest = &rest[1..];
            }
        }
        _ => return None,
    }
    for seg in rest {
        let mut next = abs.clone();
        next.push(seg.clone());
        if !modules.contains(&next) {
            break;
        }
        abs = next;
    }
    Some(abs)
}

/// Every use of one module by another in `sources`, test-only code left out.
fn uses(sources: &Sources) -> Vec<Use> {
    let mut texts = BTreeMap::new();
    let mut test_only: BTreeSet<ModPath> = BTreeSet::new();
    for (file, src) in sources {
        let mut code = blank_non_code(src);
        let module = module_of(file);
        for child in blank_test_items(&mut code) {
            let mut m = module.clone();
            m.push(child);
            test_only.insert(m);
        }
        texts.insert(file.clone(), code);
    }
    let modules: BTreeSet<ModPath> = sources.keys().map(|f| module_of(f)).collect();
    let mut out = Vec::new();
    for (file, code) in &texts {
        let from = module_of(file);
        if test_only.iter().any(|t| from.starts_with(t)) {
            continue;
        }
        for (at, written) in paths(code) {
            let Some(to) = target(&from, &written, &modules) else { continue };
            if to != from {
                let line = code[..at].matches('\n').count() + 1;
                out.push(Use { file: file.clone(), line, from: from.clone(), to });
            }
        }
    }
    out
}

/// The floors of `core/README.md`: the fenced block after "```floors", one floor per line
/// (`name: module module …`), highest first. Returns module → floor number (0 = lowest).
fn floors(readme: &str) -> Result<BTreeMap<String, usize>, String> {
    let block = readme
        .split("```floors")
        .nth(1)
        .and_then(|b| b.split("```").next())
        .ok_or("core/README.md has no ```floors block")?;
    let lines: Vec<&str> = block.lines().filter(|l| !l.trim().is_empty()).collect();
    let mut out = BTreeMap::new();
    for (k, line) in lines.iter().enumerate() {
        let (_, mods) = line.split_once(':').ok_or(format!("floor line without ':': {line}"))?;
        for m in mods.split_whitespace() {
            out.insert(m.to_string(), lines.len() - 1 - k);
        }
    }
    Ok(out)
}

/// The circles among the children of one parent: sets of two or more siblings that reach
/// each other, each with one use that closes it.
fn circles(edges: &BTreeMap<String, BTreeMap<String, Use>>) -> Vec<Vec<Use>> {
    let nodes: BTreeSet<&String> =
        edges.keys().chain(edges.values().flat_map(|m| m.keys())).collect();
    let reach = |from: &String| -> BTreeSet<String> {
        let mut seen = BTreeSet::new();
        let mut todo = vec![from.clone()];
        while let Some(n) = todo.pop() {
            for next in edges.get(&n).into_iter().flat_map(|m| m.keys()) {
                if seen.insert(next.clone()) {
                    todo.push(next.clone());
                }
            }
        }
        seen
    };
    let mut done: BTreeSet<String> = BTreeSet::new();
    let mut out = Vec::new();
    for n in nodes {
        if done.contains(n) {
            continue;
        }
        let fwd = reach(n);
        if !fwd.contains(n) {
            continue;
        }
        let members: BTreeSet<String> =
            fwd.into_iter().filter(|m| m == n || reach(m).contains(n)).collect();
        let mut witness = Vec::new();
        for a in &members {
            for (b, u) in edges.get(a).into_iter().flatten() {
                if members.contains(b) {
                    witness.push(u.clone());
                }
            }
        }
        done.extend(members);
        out.push(witness);
    }
    out
}

/// Every broken rule, as lines a person can act on.
fn problems(sources: &Sources, readme: &str) -> Vec<String> {
    let floor = match floors(readme) {
        Ok(f) => f,
        Err(e) => return vec![e],
    };
    let mut out = Vec::new();
    let mut siblings: BTreeMap<ModPath, BTreeMap<String, BTreeMap<String, Use>>> = BTreeMap::new();
    let tops: BTreeSet<String> =
        sources.keys().filter_map(|f| module_of(f).first().cloned()).collect();
    for m in &tops {
        if !floor.contains_key(m) {
            out.push(format!("module `{m}` is on no floor of core/README.md"));
        }
    }
    for u in uses(sources) {
        // The two children of the closest common parent.
        let common = u.from.iter().zip(&u.to).take_while(|(a, b)| a == b).count();
        let (Some(a), Some(b)) = (u.from.get(common), u.to.get(common)) else { continue };
        if common == 0 {
            if let (Some(fa), Some(fb)) = (floor.get(a), floor.get(b)) {
                let message = format!(
                    "core/src/{}:{}: `{}` uses `{}`, which is on a higher floor",
                    u.file,
                    u.line,
                    a,
                    u.to.join("::")
                );
                if fb > fa && !out.contains(&message) {
                    out.push(message);
                }
            }
        }
        let parent = u.from[..common].to_vec();
        siblings
            .entry(parent)
            .or_default()
            .entry(a.clone())
            .or_default()
            .entry(b.clone())
            .or_insert(u.clone());
    }
    for (parent, edges) in &siblings {
        for circle in circles(edges) {
            let within = if parent.is_empty() { "crate".to_string() } else { parent.join("::") };
            let how: Vec<String> = circle
                .iter()
                .map(|u| format!("core/src/{}:{} uses {}", u.file, u.line, u.to.join("::")))
                .collect();
            out.push(format!("modules of `{within}` use each other: {}", how.join("; ")));
        }
    }
    out
}

fn read_tree(dir: &Path, root: &Path, out: &mut Sources) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            read_tree(&p, root, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            let rel = p.strip_prefix(root).map(|r| r.to_string_lossy().replace('\\', "/"));
            if let (Ok(rel), Ok(text)) = (rel, std::fs::read_to_string(&p)) {
                out.insert(rel, text);
            }
        }
    }
}

#[test]
fn core_imports_run_one_way() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let src = root.join("src");
    let mut sources = Sources::new();
    read_tree(&src, &src, &mut sources);
    // The binaries are crates of their own: they see the library from outside.
    sources.retain(|f, _| !f.starts_with("bin/"));
    let readme = std::fs::read_to_string(root.join("README.md")).expect("core/README.md");
    let found = problems(&sources, &readme);
    assert!(
        found.is_empty(),
        "imports against the floors of core/README.md:\n{}",
        found.join("\n")
    );
}

// ---------------------------------------------------------------------------------------
// The checker on fixtures
// ---------------------------------------------------------------------------------------

const FIXTURE_README: &str = "```floors\nhigh: run\nmid: vm\nlow: syntax\n```\n";

fn fixture(files: &[(&str, &str)]) -> Sources {
    files.iter().map(|(f, s)| (f.to_string(), s.to_string())).collect()
}

#[test]
fn an_upward_import_is_reported_with_its_line() {
    let s = fixture(&[
        ("lib.rs", "pub mod run; pub mod vm; pub mod syntax;"),
        ("run.rs", "use crate::vm::Machine;"),
        ("vm/mod.rs", "use crate::syntax::parse;\n\nfn f() { crate::run::go(); }"),
        ("syntax/mod.rs", ""),
    ]);
    let p = problems(&s, FIXTURE_README);
    assert_eq!(p.len(), 2, "{p:?}"); // the upward use, and the circle run ↔ vm it closes
    assert!(p[0].starts_with("core/src/vm/mod.rs:3: `vm` uses `run`"), "{p:?}");
    assert!(p[1].starts_with("modules of `crate` use each other"), "{p:?}");
}

#[test]
fn files_of_one_module_using_each_other_are_a_circle() {
    let s = fixture(&[
        ("lib.rs", "pub mod syntax;"),
        ("syntax/mod.rs", "mod ast; mod sfc_ast; pub use ast::File;"),
        ("syntax/ast.rs", "pub struct File { sfc: Option<super::sfc_ast::Body> }"),
        ("syntax/sfc_ast.rs", "use super::{ast::{Expr, Ident}, Span};"),
    ]);
    let p = problems(&s, "```floors\nlow: syntax\n```");
    assert_eq!(p.len(), 1, "{p:?}");
    assert!(p[0].contains("modules of `syntax` use each other"), "{p:?}");
    assert!(p[0].contains("core/src/syntax/ast.rs:1 uses syntax::sfc_ast"), "{p:?}");
    assert!(p[0].contains("core/src/syntax/sfc_ast.rs:1 uses syntax::ast"), "{p:?}");
}

#[test]
fn front_doors_comments_strings_and_test_code_do_not_count() {
    let s = fixture(&[
        ("lib.rs", "pub mod vm; pub mod syntax;"),
        // A child using its parent, and the parent re-exporting the child: a front door.
        ("vm/mod.rs", "mod arith; pub use arith::add; pub struct Fault;"),
        (
            "vm/arith.rs",
            "use super::Fault; // crate::run::x\nconst S: &str = \"crate::run\";\n\
             #[cfg(test)]\nmod tests { use crate::run::Thing; }\n",
        ),
        ("syntax/mod.rs", "#[cfg(test)]\nmod tests;\n/* crate::vm */"),
        ("syntax/tests.rs", "use crate::vm::Machine;"),
    ]);
    assert_eq!(problems(&s, FIXTURE_README), Vec::<String>::new());
}

#[test]
fn a_module_on_no_floor_is_reported() {
    let s = fixture(&[("lib.rs", "pub mod extra;"), ("extra.rs", "")]);
    assert_eq!(
        problems(&s, FIXTURE_README),
        vec!["module `extra` is on no floor of core/README.md"]
    );
}
