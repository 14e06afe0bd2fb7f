#!/usr/bin/env bash
# B5, B6, B7 and B8 in headless Chromium: builds core/examples/bench_wasm.rs for wasm32 (release,
# as the web app), binds it with wasm-bindgen, and times it in a page driven by
# playwright-core (scripts/bench-browser.mjs). Prints one JSON object; see BENCHMARKS.md.
# Needs what scripts/setup.sh installs: the wasm32 target, the wasm-bindgen CLI, Debian's
# Chromium and the npm packages (npm ci).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
out=target/bench-browser
cargo build -q -p plc-core --example bench_wasm --target wasm32-unknown-unknown --release
wasm-bindgen --target web --no-typescript --out-dir "$out" \
  target/wasm32-unknown-unknown/release/examples/bench_wasm.wasm
[ -d node_modules/playwright-core ] || npm ci --no-audit --no-fund
node scripts/bench-browser.mjs "$out" "$@"
