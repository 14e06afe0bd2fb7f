//! libFuzzer target: `plc_tests::fuzz::share_link`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| plc_tests::fuzz::share_link(data));
