//! libFuzzer target: `plc_tests::fuzz::st_program`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| plc_tests::fuzz::st_program(data));
