//! Diagnostics are data (issue 33): every message is a key of `core/i18n/messages.en.json`
//! with named arguments, translated in `messages.pl.json` and `messages.cs.json` with the
//! same placeholders and the same program text between backticks; every key is used, and
//! the codes still worded in English only are a list that may only shrink.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;
use std::process::Command;

use plc_core::diagnostics::{
    catalogue_source, english_catalogue, placeholders, Code, Msg, MSG_COUNT,
};
use plc_core::i18n::{code_spans, Lang};
use plc_core::semantic::analyze;

/// The codes whose diagnostics are all still made from an English `format!` (shown in
/// English in every language). Convert a code's sites to `msg!` and remove it here.
const ENGLISH_ONLY: &[&str] = include!("messages_remaining.txt");

fn translation(lang: Lang) -> BTreeMap<String, String> {
    let text = catalogue_source(lang).expect("a translation");
    serde_json::from_str(text).unwrap_or_else(|e| panic!("messages.{lang}.json: {e}"))
}

#[test]
fn every_template_is_translated_with_the_same_placeholders_and_program_text() {
    let en = english_catalogue();
    assert_eq!(en.len(), MSG_COUNT);
    let mut problems = Vec::new();
    for lang in [Lang::Pl, Lang::Cs] {
        let tr = translation(lang);
        for key in tr.keys() {
            if !en.contains_key(key.as_str()) {
                problems.push(format!("{lang}: `{key}` is not in English"));
            }
        }
        for (key, english) in &en {
            let Some(text) = tr.get(*key) else {
                problems.push(format!("{lang}: `{key}` is missing"));
                continue;
            };
            if text.trim().is_empty() {
                problems.push(format!("{lang}: `{key}` is empty"));
            }
            if placeholders(text) != placeholders(english) {
                problems.push(format!(
                    "{lang}: `{key}` has the placeholders {:?}, English {:?}",
                    placeholders(text),
                    placeholders(english)
                ));
            }
            let (mut a, mut b) = (code_spans(text), code_spans(english));
            a.sort_unstable();
            b.sort_unstable();
            if a != b {
                problems.push(format!("{lang}: `{key}` has the program text {a:?}, English {b:?}"));
            }
            // A sentence left in English (a phrase of program text alone may equal it).
            let words: String = english
                .split('`')
                .step_by(2)
                .flat_map(|s| s.split('{').map(|p| p.split_once('}').map_or(p, |(_, r)| r)))
                .collect();
            if text == english && words.chars().any(char::is_lowercase) {
                problems.push(format!("{lang}: `{key}` is still English"));
            }
        }
    }
    assert!(problems.is_empty(), "core/i18n/messages.*.json:\n{}", problems.join("\n"));
}

/// Every Rust source file under `dir`.
fn sources(dir: &Path, out: &mut Vec<(String, String)>) {
    for entry in std::fs::read_dir(dir).expect("a folder").flatten() {
        let path = entry.path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let text = std::fs::read_to_string(&path).expect("a source file");
            out.push((path.display().to_string(), text));
        }
    }
}

fn variant(key: &str) -> String {
    key.split(['_', '.'])
        .map(|w| {
            let mut c = w.chars();
            c.next().map(|f| f.to_ascii_uppercase().to_string() + c.as_str()).unwrap_or_default()
        })
        .collect()
}

#[test]
fn every_key_is_used_and_only_the_listed_codes_are_english_only() {
    let mut files = Vec::new();
    sources(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"), &mut files);
    let engine: Vec<&(String, String)> = files
        .iter()
        .filter(|(p, _)| !p.ends_with("tests.rs") && !p.contains("/tests/") && !p.contains("/bin/"))
        .collect();
    let all: String =
        engine.iter().flat_map(|(_, t)| t.chars()).filter(|c| !c.is_whitespace()).collect();
    let unused: Vec<&str> = Msg::ALL
        .iter()
        .map(|m| m.key())
        .filter(|k| {
            let v = variant(k);
            !["msg!(", "phrase!(", "Msg::"].iter().any(|p| all.contains(&format!("{p}{v}")))
        })
        .collect();
    assert!(unused.is_empty(), "message keys no diagnostic uses: {unused:?}");

    // A code has a message when some statement naming it, or the one before (`let msg =
    // msg!(…);`), makes one with `msg!`, or carries one made with `msg!` where the problem
    // was found (`msg: Some(Box::new(e.msg.clone()))`, a network's `NetError`).
    let mut worded = BTreeSet::new();
    let mut named = BTreeSet::new();
    for (_, text) in &engine {
        let statements: Vec<&str> = text.split(';').collect();
        for (i, statement) in statements.iter().enumerate() {
            let before = if i > 0 { statements[i - 1] } else { "" };
            for part in statement.split("Code::").skip(1) {
                let name: String = part.chars().take_while(|c| c.is_ascii_alphanumeric()).collect();
                named.insert(name.clone());
                if statement.contains("msg!(")
                    || before.contains("msg!(")
                    || statement.contains(".msg.clone()))")
                {
                    worded.insert(name);
                }
            }
        }
    }
    let english_only: BTreeSet<String> = Code::all()
        .iter()
        .map(|c| format!("{c:?}"))
        .filter(|c| named.contains(c) && !worded.contains(c))
        .collect();
    let listed: BTreeSet<String> = ENGLISH_ONLY.iter().map(|s| s.to_string()).collect();
    let new: Vec<&String> = english_only.difference(&listed).collect();
    let done: Vec<&String> = listed.difference(&english_only).collect();
    assert!(new.is_empty(), "codes worded in English only (use msg!): {new:?}");
    assert!(done.is_empty(), "now worded as data, remove from messages_remaining.txt: {done:?}");
}

fn first(src: &str, code: &str) -> plc_core::diagnostics::Diagnostic {
    analyze(src)
        .diagnostics
        .into_iter()
        .find(|d| d.code.as_str() == code)
        .unwrap_or_else(|| panic!("no {code} in {src}"))
}

#[test]
fn an_undeclared_name_with_its_hint_in_polish_and_czech() {
    let src = "PROGRAM Main\nVAR Motor : BOOL; END_VAR\nMotr := TRUE;\nEND_PROGRAM\n";
    let d = first(src, "E0100");
    assert_eq!(d.message, "`Motr` is not declared; did you mean Motor?");
    assert_eq!(d.render(Lang::En), d.message);
    assert_eq!(d.render(Lang::Pl), "`Motr` nie jest zadeklarowane; czy chodziło o Motor?");
    assert_eq!(d.render(Lang::Cs), "`Motr` není deklarováno; neměli jste na mysli Motor?");
}

#[test]
fn a_type_mismatch_in_polish_and_czech() {
    let src = "PROGRAM Main\nVAR n : INT; s : STRING; END_VAR\nn := s;\nEND_PROGRAM\n";
    let d = first(src, "E0150");
    assert_eq!(d.message, "expected a value of type INT, found STRING[80]");
    assert_eq!(d.render(Lang::Pl), "oczekiwano wartości typu INT, znaleziono STRING[80]");
    assert_eq!(d.render(Lang::Cs), "očekávána hodnota typu INT, nalezeno STRING[80]");
}

#[test]
fn a_parser_error_translates_its_expected_phrase() {
    let src = "PROGRAM Main\nVAR x : INT; END_VAR\nx := ;\nEND_PROGRAM\n";
    let d = first(src, "E0006");
    assert_eq!(d.message, "expected an expression, found `;`");
    assert_eq!(d.render(Lang::Pl), "oczekiwano: wyrażenie; znaleziono: `;`");
    assert_eq!(d.render(Lang::Cs), "očekáváno: výraz; nalezeno: `;`");
}

#[test]
fn plc_check_prints_the_messages_in_the_language_asked_for() {
    let dir = std::env::temp_dir().join(format!("plc-messages-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let file = dir.join("motor.st");
    std::fs::write(&file, "PROGRAM Main\nVAR Motor : BOOL; END_VAR\nMotr := TRUE;\nEND_PROGRAM\n")
        .expect("written");
    let run = |args: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_plc"))
            .arg("check")
            .args(args)
            .arg(&file)
            .output()
            .expect("plc runs");
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let english = run(&[]);
    assert!(
        english.contains("error[E0100]: `Motr` is not declared; did you mean Motor?"),
        "{english}"
    );
    assert_eq!(run(&["--lang", "en"]), english);
    let polish = run(&["--lang", "pl"]);
    assert!(
        polish.contains(":3:1: error[E0100]: `Motr` nie jest zadeklarowane; czy chodziło o Motor?"),
        "{polish}"
    );
    let czech = run(&["--lang", "cs"]);
    assert!(czech.contains("`Motr` není deklarováno; neměli jste na mysli Motor?"), "{czech}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_sfc_condition_and_a_wrapped_checker_message_in_polish_and_czech() {
    let src = "PROGRAM Main\nVAR n : INT; END_VAR\nINITIAL_STEP A : END_STEP\nTRANSITION FROM A TO B := n; END_TRANSITION\nSTEP B : END_STEP\nEND_PROGRAM\n";
    let d = first(src, "E0558");
    assert_eq!(d.message, "the condition of transition `FROM A TO B` must be BOOL, not INT");
    assert_eq!(d.render(Lang::En), d.message);
    assert_eq!(d.render(Lang::Pl), "warunek przejścia `FROM A TO B` musi być typu BOOL, a nie INT");
    assert_eq!(d.render(Lang::Cs), "podmínka přechodu `FROM A TO B` musí být typu BOOL, ne INT");

    // A boolean action that is not a BOOL variable: the SFC sentence with the checker's own
    // words in parentheses, both translated.
    let src = "PROGRAM Main\nVAR n : INT; END_VAR\nINITIAL_STEP A : n(N); END_STEP\nEND_PROGRAM\n";
    let d = analyze(src)
        .diagnostics
        .into_iter()
        .find(|d| d.message.starts_with("`n` cannot be a boolean action"))
        .expect("a boolean action that is not BOOL");
    assert_eq!(d.render(Lang::En), d.message);
    let (outer, inner) = d.message.split_once(" (").expect("the checker's words in parentheses");
    assert_eq!(outer, "`n` cannot be a boolean action: it is not a BOOL variable");
    let polish = d.render(Lang::Pl);
    assert!(polish.starts_with("`n` nie może być akcją logiczną: nie jest zmienną typu BOOL ("));
    assert!(!polish.contains(inner.trim_end_matches(')')), "{polish}");
}
