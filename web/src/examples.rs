//! The shipped examples (`examples/*.st` and `*.plcproj.json`, embedded at build time by
//! `build.rs`): their menu titles, and opening one as a new project.

use plc_core::open::open_text;
use plc_core::project::Project;

mod files {
    include!(concat!(env!("OUT_DIR"), "/examples.rs"));
}

/// One example of the menu.
#[derive(Debug, Clone, PartialEq)]
pub struct Example {
    /// Its file name in `examples/`.
    pub file: &'static str,
    /// What the menu shows.
    pub title: String,
    /// Ladder projects first, then ST, then Petri nets.
    rank: u8,
}

/// The file name without `.plcproj.json` or `.st`.
fn stem(file: &str) -> &str {
    file.strip_suffix(".plcproj.json").or_else(|| file.strip_suffix(".st")).unwrap_or(file)
}

/// A file stem as words: `sfc-weighing` → `SFC weighing`.
fn humanise(stem: &str) -> String {
    let words: Vec<String> = stem
        .split(['-', '_'])
        .filter(|w| !w.is_empty())
        .enumerate()
        .map(|(i, w)| match w.to_ascii_lowercase().as_str() {
            "sfc" | "st" | "ld" | "plc" => w.to_ascii_uppercase(),
            _ if i == 0 => {
                let mut c = w.chars();
                c.next().map(|f| f.to_uppercase().chain(c).collect()).unwrap_or_default()
            }
            _ => w.to_string(),
        })
        .collect();
    words.join(" ")
}

/// The menu title and rank of an example file.
pub fn describe(file: &'static str, text: &str) -> Example {
    match Project::from_file(text) {
        Ok(p) if file.ends_with(".json") => {
            let rank = if !p.ladder.is_empty() {
                0
            } else if !p.petri.is_empty() {
                2
            } else {
                1
            };
            Example { file, title: p.name, rank }
        }
        _ => Example { file, title: format!("{} (ST)", humanise(stem(file))), rank: 1 },
    }
}

/// Every shipped example, in menu order.
pub fn examples() -> Vec<Example> {
    let mut list: Vec<Example> = files::FILES.iter().map(|(f, t)| describe(f, t)).collect();
    list.sort_by(|a, b| a.rank.cmp(&b.rank).then_with(|| a.title.cmp(&b.title)));
    list
}

/// The example `file` as a new project.
pub fn open(file: &str) -> Result<Project, String> {
    let (name, text) = files::FILES
        .iter()
        .find(|(f, _)| *f == file)
        .ok_or_else(|| format!("there is no example {file}"))?;
    let mut project = open_text(&humanise(stem(name)), text).map_err(|e| e.to_string())?.project;
    if project.name.trim().is_empty() {
        project.name = humanise(stem(name));
    }
    Ok(project)
}

#[cfg(test)]
mod tests;
