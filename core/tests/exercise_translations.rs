//! Every shipped exercise (`exercises/ID/ID.toml`) speaks Polish and Czech completely:
//! title, statement, every interface meaning, every scenario's name and hint, with the
//! English names and program text (issue 33).

#![allow(clippy::unwrap_used)]

use plc_core::exercise::{Exercise, TRANSLATED};

#[test]
fn every_shipped_exercise_is_translated_into_polish_and_czech() {
    let root = format!("{}/../exercises", env!("CARGO_MANIFEST_DIR"));
    let mut problems = Vec::new();
    let mut checked = 0;
    for dir in std::fs::read_dir(&root).unwrap().flatten().filter(|d| d.path().is_dir()) {
        let id = dir.file_name().to_string_lossy().into_owned();
        let file = format!("exercises/{id}/{id}.toml");
        let text = std::fs::read_to_string(dir.path().join(format!("{id}.toml"))).unwrap();
        let e = Exercise::from_toml(&text).unwrap();
        for p in e.translation_problems() {
            problems.push(format!("{file}: {p}"));
        }
        for lang in TRANSLATED {
            let missing = e.untranslated(lang);
            if !missing.is_empty() {
                problems.push(format!("{file}: [lang.{lang}] lacks {}", missing.join(", ")));
            }
            let t = e.translation(lang).cloned().unwrap_or_default();
            let texts = [t.title.clone(), t.statement.clone()].into_iter().flatten();
            let texts = texts.chain(t.meaning.values().cloned());
            let texts = texts.chain(
                t.scenario.values().flat_map(|s| [s.name.clone(), s.hint.clone()]).flatten(),
            );
            for text in texts {
                let prose: String = text.split('`').step_by(2).collect();
                let english = [&e.title, &e.statement].iter().any(|en| en.as_str() == text);
                if english && prose.chars().any(char::is_alphabetic) {
                    problems.push(format!("{file}: [lang.{lang}] still English: {text}"));
                }
            }
        }
        checked += 1;
    }
    assert!(checked >= 26, "the shipped exercises ({checked})");
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
