//! Runs every conformance case natively, checks it, and writes every report to
//! `<workspace>/target/conformance/native.json` (or `$PLC_NATIVE_RESULTS`) for the wasm
//! suite to compare against. `PLC_CASES=timers/` runs only the cases whose name contains
//! the text (and then writes nothing).

use std::fs;
use std::path::Path;

#[test]
fn conformance_cases() {
    let filter = std::env::var("PLC_CASES").unwrap_or_default();
    let (results, failures) = plc_tests::run_matching(&filter);
    let total = results.len();
    assert!(total > 0, "no case matches PLC_CASES={filter:?}");

    if filter.is_empty() {
        let path = plc_tests::native_results_path();
        if let Some(dir) = Path::new(&path).parent() {
            fs::create_dir_all(dir).unwrap_or_else(|e| panic!("create {}: {e}", dir.display()));
        }
        let text = serde_json::to_string_pretty(&serde_json::Value::Object(results))
            .expect("reports serialise");
        fs::write(&path, text).unwrap_or_else(|e| panic!("write {path}: {e}"));
        println!("wrote {total} reports to {path}");
    }

    if !failures.is_empty() {
        panic!(
            "{} of {total} conformance cases failed:\n\n{}\n",
            failures.len(),
            failures.join("\n\n")
        );
    }
    println!("all {total} conformance cases pass");
}
