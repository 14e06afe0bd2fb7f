//! libFuzzer target: `plc_tests::fuzz::st_text`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| plc_tests::fuzz::st_text(data));
