//! libFuzzer target: `plc_tests::fuzz::pnml`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| plc_tests::fuzz::pnml(data));
