//! libFuzzer target: `plc_tests::fuzz::project_json`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| plc_tests::fuzz::project_json(data));
