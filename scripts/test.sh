#!/usr/bin/env bash
# Runs every test: formatting, lints, unit tests, the conformance suite natively, and the
# same suite in the wasm32 build (under Node) compared against the native results.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

echo "== cargo fmt --check"
cargo fmt --all -- --check

echo "== cargo clippy"
cargo clippy --workspace --all-targets -- -D warnings

echo "== cargo test (native: unit tests, conformance suite, CLI tests)"
cargo test --workspace

echo "== conformance suite in wasm32 (Node), compared with the native results"
PLC_NATIVE_RESULTS="$PWD/target/conformance/native.json" \
  cargo test -p plc-tests --target wasm32-unknown-unknown --test wasm_conformance

echo "== all tests passed"
