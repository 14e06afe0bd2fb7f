//! Every problem code has its explanation with a wrong and a right example, the ST examples
//! really give (and the right ones really avoid) their code, and `docs/problems.md` and
//! `web/problems.html` are what `plc explain --markdown` / `--html` print.

use plc_core::diagnostics::{problems_html, problems_markdown, Code, Example, EXPLANATIONS};
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
}
