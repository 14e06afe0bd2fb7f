#![cfg(not(target_arch = "wasm32"))]
//! The repository stands on its own: no file of it names a path outside it. A clone with
//! nothing beside it must pass its own tests, and the project's sources are cited by name
//! (`docs/semantics.md`, `docs/weighing.md`, `tests/samples/`), never by a folder that
//! happened to stand next to a working copy. This file looks for those paths without
//! spelling them, so it holds itself to the same rule.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The folder beside a working copy that held material not part of the repository. Its
/// name and the paths into it are put together here rather than spelt out, so that this
/// file, too, names no path outside the repository.
const FOLDER: &str = "shared";

/// Paths that lead out of the repository to material that is not part of it.
fn outside() -> Vec<String> {
    let mut paths = vec![format!("../{FOLDER}")];
    for inner in ["samples", "WEIGHING", "seeds", "SEMANTICS"] {
        paths.push(format!("{FOLDER}/{inner}"));
    }
    paths
}

/// What a directory walk leaves out: build output, installed packages, git's own data (a
/// folder, or in a worktree a file).
const SKIPPED: &[&str] = &["target", "node_modules", "dist", ".git"];

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The repository's files, relative to its root: what git tracks when this is a git
/// checkout, else every file below the root except [`SKIPPED`].
fn repo_files(root: &Path) -> Vec<PathBuf> {
    let tracked = Command::new("git").arg("-C").arg(root).args(["ls-files", "-z"]).output();
    if let Ok(out) = tracked {
        if out.status.success() && !out.stdout.is_empty() {
            return out
                .stdout
                .split(|&b| b == 0)
                .filter(|name| !name.is_empty())
                .map(|name| PathBuf::from(String::from_utf8_lossy(name).into_owned()))
                .collect();
        }
    }
    let mut files = Vec::new();
    walk(root, Path::new(""), &mut files);
    files
}

fn walk(root: &Path, dir: &Path, files: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(root.join(dir)) else { return };
    for entry in entries.flatten() {
        let name = entry.file_name();
        if SKIPPED.iter().any(|s| name == *s) {
            continue;
        }
        let rel = dir.join(&name);
        match entry.file_type() {
            Ok(t) if t.is_dir() => walk(root, &rel, files),
            Ok(t) if t.is_file() => files.push(rel),
            _ => {}
        }
    }
}

/// `file:line: text` for every line of `text` that names one of [`outside`].
fn outside_references(file: &Path, text: &str) -> Vec<String> {
    let outside = outside();
    text.lines()
        .enumerate()
        .filter(|(_, line)| outside.iter().any(|p| line.contains(p.as_str())))
        .map(|(k, line)| format!("{}:{}: {}", file.display(), k + 1, line.trim()))
        .collect()
}

#[test]
fn no_file_names_a_path_outside_the_repository() {
    let root = repo_root();
    let files = repo_files(&root);
    assert!(
        files.iter().any(|f| f == Path::new("Cargo.toml"))
            && files.iter().any(|f| f == Path::new("core/src/lib.rs")),
        "the listing of {} misses the workspace's own files: {} files",
        root.display(),
        files.len()
    );
    let mut found = Vec::new();
    for file in &files {
        // Deleted but still tracked, or unreadable: nothing to look at.
        let Ok(bytes) = std::fs::read(root.join(file)) else { continue };
        found.extend(outside_references(file, &String::from_utf8_lossy(&bytes)));
    }
    assert!(
        found.is_empty(),
        "these lines name a path outside the repository; cite the source by name or keep \
         the material in the repository (docs/, tests/samples/):\n{}",
        found.join("\n")
    );
}

#[test]
fn the_check_sees_each_kind_of_outside_path() {
    for p in outside() {
        let text = format!("first line\nsee {p}/x for more\n");
        assert_eq!(
            outside_references(Path::new("a.md"), &text),
            [format!("a.md:2: see {p}/x for more")]
        );
    }
    assert!(outside_references(Path::new("a.md"), "docs/semantics.md, tests/samples/").is_empty());
}

#[test]
fn the_walk_finds_files_when_git_is_not_there() {
    let mut files = Vec::new();
    walk(&repo_root(), Path::new(""), &mut files);
    assert!(files.iter().any(|f| f == Path::new("tests/tests/self_contained.rs")));
    assert!(files.iter().all(|f| !f.starts_with("target") && !f.starts_with(".git")));
}
