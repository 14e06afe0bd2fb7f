//! A short fuzzing run in every `cargo test`: each target of `plc_tests::fuzz` gets the
//! seed corpus (`fuzz/seeds/TARGET/`, and whatever a long run left in `fuzz/corpus/`),
//! each seed cut and flipped at a few places, and a fixed number of proptest-generated
//! inputs. No input may panic. The long runs (libFuzzer, `cargo fuzz run TARGET`) and
//! their figures are in `docs/reliability.md`.
#![cfg(not(target_arch = "wasm32"))]

use std::path::PathBuf;

use plc_tests::fuzz::TARGETS;
use proptest::prelude::*;

fn corpus(target: &str) -> Vec<Vec<u8>> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../fuzz");
    let mut out = Vec::new();
    for dir in ["seeds", "corpus"] {
        let Ok(entries) = std::fs::read_dir(root.join(dir).join(target)) else { continue };
        let mut files: Vec<PathBuf> = entries.flatten().map(|e| e.path()).collect();
        files.sort();
        out.extend(files.iter().filter_map(|f| std::fs::read(f).ok()));
    }
    out
}

/// The seeds, and each seed damaged the way files and links get damaged: cut short,
/// one byte changed, a slice doubled.
fn seeds_and_mutants(target: &str) -> Vec<Vec<u8>> {
    let mut out = Vec::new();
    for seed in corpus(target) {
        let n = seed.len();
        for k in [n / 3, n / 2, n.saturating_sub(1)] {
            out.push(seed[..k].to_vec());
            let mut flipped = seed.clone();
            if let Some(b) = flipped.get_mut(k) {
                *b ^= 0x5a;
            }
            out.push(flipped);
        }
        let mut doubled = seed[..n / 2].to_vec();
        doubled.extend_from_slice(&seed[n / 4..]);
        out.push(doubled);
        out.push(seed);
    }
    out
}

#[test]
fn every_target_has_seeds_and_survives_them() {
    for (name, target) in TARGETS {
        let inputs = seeds_and_mutants(name);
        assert!(!inputs.is_empty(), "fuzz/seeds/{name}/ has no seed");
        for input in inputs {
            target(&input);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn random_bytes_never_panic(data in proptest::collection::vec(any::<u8>(), 0..400)) {
        for (_, target) in TARGETS {
            target(&data);
        }
    }

    #[test]
    fn random_st_like_text_never_panics(text in "[A-Za-z0-9_:=;.,()\\[\\]#%'+*/<>& \n-]{0,300}") {
        plc_tests::fuzz::st_text(text.as_bytes());
    }

    #[test]
    fn grammar_programs_check_and_run(data in proptest::collection::vec(any::<u8>(), 0..200)) {
        plc_tests::fuzz::st_program(&data);
    }
}
