// Example naming, shared by `build.rs` (which lists the examples at build time) and the
// app (`include!`d in both, so the rules live once).

/// The file name without `.plcproj.json` or `.st`.
pub fn stem(file: &str) -> &str {
    file.strip_suffix(".plcproj.json").or_else(|| file.strip_suffix(".st")).unwrap_or(file)
}

/// A file stem as words: `sfc-weighing` → `SFC weighing`.
pub fn humanise(stem: &str) -> String {
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

/// The menu title and rank (ladder projects 0, ST 1, Petri nets 2) of an example file,
/// from its project name and whether it has ladder or Petri net POUs.
pub fn describe(file: &str, project: Option<(&str, bool, bool)>) -> (String, u8) {
    match project {
        Some((name, ladder, petri)) if file.ends_with(".json") => {
            let rank = if ladder {
                0
            } else if petri {
                2
            } else {
                1
            };
            (name.to_string(), rank)
        }
        _ => (format!("{} (ST)", humanise(stem(file))), 1),
    }
}
