#!/usr/bin/env bash
# Runs every test: formatting, lints, unit tests, the conformance suite natively, and the
# same suite in the wasm32 build (under Node) compared against the native results, and the
# web app's end-to-end tests against the release build in headless Chromium, then in Firefox
# and WebKit (tests/e2e-engines/).
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

# The flows a student needs, in the two other engines students use (tests/e2e-engines/):
# Firefox ESR through puppeteer-core over WebDriver BiDi, and WebKitGTK's MiniBrowser
# through WebKitWebDriver, under a virtual X display (it has no headless mode). Each
# engine's suite takes a few minutes (the README says how long).
engine_flows=(driver student ladder petri exercise offline language)
# A test that hangs (an engine that stops answering its driver) fails after 5 minutes
# instead of holding CI until its own limit.
engine_timeout=--test-timeout=300000
engine_tests=()
for f in "${engine_flows[@]}"; do engine_tests+=("tests/e2e-engines/$f.test.mjs"); done

echo "== end-to-end tests in Firefox ESR (node --test, ENGINE=firefox)"
start=$SECONDS
ENGINE=firefox node --test "$engine_timeout" "${engine_tests[@]}"
echo "== Firefox ESR suite: $((SECONDS - start)) s"

echo "== end-to-end tests in WebKitGTK MiniBrowser (node --test under xvfb-run, ENGINE=webkit)"
start=$SECONDS
ENGINE=webkit xvfb-run -a -s "-screen 0 1920x1200x24" node --test "$engine_timeout" "${engine_tests[@]}"
echo "== WebKitGTK suite: $((SECONDS - start)) s"

echo "== all tests passed"
