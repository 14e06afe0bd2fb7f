#!/usr/bin/env bash
# Runs every test: formatting, lints, unit tests, the conformance suite natively, and the
# same suite in the wasm32 build (under Node) compared against the native results, and the
# web app's end-to-end tests in headless Chromium against the release build.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

echo "== cargo fmt --check"
cargo fmt --all -- --check

echo "== cargo clippy (native crates, then the web app for wasm32)"
cargo clippy --workspace --exclude plc-web --all-targets -- -D warnings
cargo clippy -p plc-web --target wasm32-unknown-unknown -- -D warnings

echo "== cargo test (native: unit tests incl. the web app's pure helpers, conformance suite, CLI tests)"
cargo test --workspace

echo "== conformance suite in wasm32 (Node), compared with the native results"
PLC_NATIVE_RESULTS="$PWD/target/conformance/native.json" \
  cargo test -p plc-tests --target wasm32-unknown-unknown --test wasm_conformance

echo "== release build of the web app"
bash scripts/build-web.sh

echo "== end-to-end tests in headless Chromium (node --test)"
node --test tests/e2e/

echo "== all tests passed"
