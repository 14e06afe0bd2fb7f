//! The conformance suite in wasm32 under Node: every case must pass there too, and its
//! report must be the same JSON as the native run's (reals compared exactly: the engine is
//! deterministic). Run the native suite first; it writes the reports this test reads.
//!
//! ```text
//! cargo test -p plc-tests --test conformance
//! PLC_NATIVE_RESULTS="$PWD/target/conformance/native.json" \
//!     cargo test -p plc-tests --target wasm32-unknown-unknown --test wasm_conformance
//! (the workspace's .cargo/config.toml makes wasm-bindgen-test-runner the runner)
//! ```
#![cfg(target_arch = "wasm32")]

use serde_json::Value;
use wasm_bindgen::prelude::*;
use wasm_bindgen_test::wasm_bindgen_test;

#[wasm_bindgen(module = "fs")]
extern "C" {
    #[wasm_bindgen(js_name = readFileSync, catch)]
    fn read_file_sync(path: &str, encoding: &str) -> Result<String, JsValue>;
}

/// `$PLC_NATIVE_RESULTS` as it was at compile time, else the native suite's default path.
fn native_results_path() -> String {
    match option_env!("PLC_NATIVE_RESULTS") {
        Some(p) if !p.is_empty() => p.to_string(),
        _ => format!("{}/../target/conformance/native.json", env!("CARGO_MANIFEST_DIR")),
    }
}

/// Serialises and parses again, so both sides went through the same float text parsing.
fn round_trip(v: &Value) -> Value {
    serde_json::from_str(&v.to_string()).unwrap_or(Value::Null)
}

#[wasm_bindgen_test]
fn conformance_cases_match_native() {
    let path = native_results_path();
    let text = read_file_sync(&path, "utf8").unwrap_or_else(|_| {
        panic!(
            "cannot read the native reports at {path}: run the native suite first \
             (cargo test -p plc-tests --test conformance)"
        )
    });
    let native: Value = serde_json::from_str(&text)
        .unwrap_or_else(|e| panic!("{path} is not JSON ({e}); run the native suite again"));
    let native = native.as_object().cloned().unwrap_or_default();

    let (results, mut failures) = plc_tests::run_all();
    for (name, report) in &results {
        match native.get(name) {
            None => failures
                .push(format!("[{name}] no native report in {path}; run the native suite again")),
            Some(n) if *n != round_trip(report) => failures.push(format!(
                "[{name}] wasm report differs from native at {}",
                plc_tests::path::first_difference(n, &round_trip(report))
            )),
            Some(_) => {}
        }
    }
    for name in native.keys().filter(|n| !results.contains_key(*n)) {
        failures.push(format!("[{name}] in the native reports but not run in wasm"));
    }
    assert!(
        failures.is_empty(),
        "{} problem(s) in the wasm conformance run of {} cases:\n\n{}\n",
        failures.len(),
        results.len(),
        failures.join("\n\n")
    );
}

/// The inputs that once crashed or hung the engine, on wasm's own 1 MiB stack.
#[wasm_bindgen_test]
fn hostile_inputs_give_located_errors() {
    let failures = plc_tests::hostile::check_all();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
