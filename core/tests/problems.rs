//! Every problem code has its explanation with a wrong and a right example, the ST examples
//! really give (and the right ones really avoid) their code, and `docs/problems.md` and
//! `web/problems.html` are what `plc explain --markdown` / `--html` print; every code's
//! title and explanation is translated into Polish and Czech with its program text intact,
//! and the translated pages are current too.

use plc_core::diagnostics::{
    parse_translation, problems_html, problems_html_in, problems_markdown, problems_page_name,
    Code, Example, ProblemTexts, EXPLANATIONS, TRANSLATIONS,
};
use plc_core::i18n::{code_spans, Lang};
use plc_core::run::{run_source, RunOptions};

#[test]
fn every_code_has_an_explanation_and_examples() {
    let missing: Vec<&str> =
        Code::all().iter().filter(|c| c.explanation().is_none()).map(|c| c.as_str()).collect();
    assert!(
        missing.is_empty(),
        "codes without an explanation in core/src/diagnostics/explain.rs: {missing:?}"
    );
    assert_eq!(EXPLANATIONS.len(), Code::all().len(), "one explanation per code, no more");
}

/// The codes an ST example gives when run as `plc run` runs it.
fn codes_of(example: &Example) -> Option<Vec<String>> {
    let Example::St { source, program, set } = example else { return None };
    let options = RunOptions {
        program: program.map(str::to_string),
        cycles: 1,
        set: set.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect(),
        ..Default::default()
    };
    Some(run_source(source, &options).diagnostics.into_iter().map(|d| d.code).collect())
}

#[test]
fn wrong_examples_give_their_code_and_right_ones_do_not() {
    let mut failures = Vec::new();
    for e in EXPLANATIONS {
        let code = e.code.as_str().to_string();
        if let Some(got) = codes_of(&e.wrong) {
            if !got.contains(&code) {
                failures.push(format!("{code}: the wrong example gives {got:?}"));
            }
        }
        if let Some(got) = codes_of(&e.right) {
            if got.contains(&code) {
                failures.push(format!("{code}: the right example still gives it"));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn generated_file_is_current(path: &str, want: &str, flag: &str) {
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(path);
    let have = std::fs::read_to_string(&file).unwrap_or_default();
    assert!(
        have == want,
        "{path} is not current: run `cargo run -p plc-core --bin plc -- explain {flag} > {path}`"
    );
}

#[test]
fn the_problem_pages_are_current() {
    generated_file_is_current("docs/problems.md", &problems_markdown(), "--markdown");
    generated_file_is_current("web/problems.html", &problems_html(), "--html");
    generated_file_is_current(
        "core/i18n/problems.en.json",
        &ProblemTexts::english().to_json(),
        "--json",
    );
    for lang in [Lang::Pl, Lang::Cs] {
        generated_file_is_current(
            &format!("web/{}", problems_page_name(lang)),
            &problems_html_in(lang),
            &format!("--html --lang {lang}"),
        );
    }
}

/// What is wrong with one translated text against its English: empty, left in English, or
/// with program text (the spans between backticks) changed.
fn text_problems(place: &str, en: &str, translated: &str, out: &mut Vec<String>) {
    if translated.trim().is_empty() {
        out.push(format!("{place}: empty"));
        return;
    }
    let words =
        |t: &str| t.split('`').step_by(2).collect::<String>().chars().any(char::is_alphabetic);
    if translated == en && words(en) {
        out.push(format!("{place}: still English"));
    }
    if code_spans(en) != code_spans(translated) {
        out.push(format!(
            "{place}: program text between backticks differs: English {:?}, translation {:?}",
            code_spans(en),
            code_spans(translated)
        ));
    }
}

#[test]
fn every_code_is_translated_into_polish_and_czech_with_its_program_text_intact() {
    let english = ProblemTexts::english();
    let mut problems = Vec::new();
    for (lang, json) in [Lang::Pl, Lang::Cs].into_iter().zip(TRANSLATIONS) {
        let file = format!("core/i18n/problems.{lang}.json");
        let t = match parse_translation(json) {
            Ok(t) => t,
            Err(e) => {
                problems.push(format!("{file}: {e}"));
                continue;
            }
        };
        let (p, e) = (&t.page, &english.page);
        for (field, tr, en) in [
            ("title", &p.title, &e.title),
            ("intro", &p.intro, &e.intro),
            ("wrong", &p.wrong, &e.wrong),
            ("right", &p.right, &e.right),
            ("language", &p.language, &e.language),
        ] {
            text_problems(&format!("{file} page.{field}"), en, tr, &mut problems);
        }
        for extra in t.codes.keys().filter(|c| !english.codes.contains_key(*c)) {
            problems.push(format!("{file}: {extra} is no problem code"));
        }
        for (code, en) in &english.codes {
            let Some(tr) = t.codes.get(code) else {
                problems.push(format!("{file}: {code} is missing"));
                continue;
            };
            text_problems(&format!("{file} {code}.title"), &en.title, &tr.title, &mut problems);
            text_problems(&format!("{file} {code}.text"), &en.text, &tr.text, &mut problems);
            for (field, en, tr) in
                [("wrong", &en.wrong, &tr.wrong), ("right", &en.right, &tr.right)]
            {
                match (en, tr) {
                    (Some(en), Some(tr)) => {
                        text_problems(&format!("{file} {code}.{field}"), en, tr, &mut problems)
                    }
                    (Some(_), None) => {
                        problems.push(format!("{file} {code}.{field}: the drawing's description is missing"))
                    }
                    (None, Some(_)) => problems.push(format!(
                        "{file} {code}.{field}: the example is ST program text, which is never translated"
                    )),
                    (None, None) => {}
                }
            }
        }
    }
    assert!(problems.is_empty(), "{} problems:\n{}", problems.len(), problems.join("\n"));
}

#[test]
fn a_translated_page_is_in_its_language_and_keeps_the_examples() {
    let pl = problems_html_in(Lang::Pl);
    assert!(pl.contains("<html lang=\"pl\">"));
    assert!(pl.contains("<a href=\"problems.html\" hreflang=\"en\" lang=\"en\">English</a>"));
    let example = EXPLANATIONS.iter().find(|e| e.code == Code::TypeMismatch).map(|e| e.wrong);
    let Some(Example::St { source, .. }) = example else { panic!("E0150 has an ST example") };
    assert!(pl.contains(&source.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")));
}
