//! libFuzzer target: `plc_tests::fuzz::plcopen_xml`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| plc_tests::fuzz::plcopen_xml(data));
