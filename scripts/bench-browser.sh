#!/usr/bin/env bash
# B5, B6, B7 and B8 in headless Chromium: builds core/examples/bench_wasm.rs for wasm32 exactly
# as the site is built (scripts/wasm-build.sh: the `wasm-release` profile with its
# per-package opt-levels, the same flags, the same wasm-opt pass), binds it with
# wasm-bindgen, times it in a page driven by playwright-core (scripts/bench-browser.mjs),
# which runs the native B5 beside each browser round (`plc bench --only B5`, release build).
# Prints one JSON object with both; see BENCHMARKS.md. Arguments go to bench-browser.mjs
# (`--quick`, `--rounds N`). Needs what scripts/setup.sh installs: the wasm32
# target, the wasm-bindgen CLI, Debian's Chromium and the npm packages (npm ci).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$PWD/node_modules/.bin:$HOME/.cargo/bin:$PATH"
source scripts/wasm-build.sh
out=${BENCH_OUT:-target/bench-browser}
wasm_cargo build -q -p plc-core --example bench_wasm --target wasm32-unknown-unknown --profile "$WASM_PROFILE" "${wasm_cargo_flags[@]}"
wasm-bindgen --target web --no-typescript --out-dir "$out" \
  "${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/$WASM_PROFILE/examples/bench_wasm.wasm"
wasm_opt "$out/bench_wasm_bg.wasm" "$out/bench_wasm_bg.wasm"
# The module's transfer size (gzip -9), to weigh the engine's opt-level against B5.
gz_bytes=$(node -e 'console.log(require("zlib").gzipSync(require("fs").readFileSync(process.argv[1]), { level: 9 }).length)' "$out/bench_wasm_bg.wasm")
[ -d node_modules/playwright-core ] || npm ci --no-audit --no-fund
# The native binary, built without the wasm32 flags, for the native B5 beside each round.
(unset CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS; cargo build -q --release -p plc-core --bin plc)
browser=$(PLC_NATIVE="${CARGO_TARGET_DIR:-target}/release/plc" node scripts/bench-browser.mjs "$out" "$@")
node -e '
  const browser = JSON.parse(process.argv[1]);
  browser.module = { gzip_bytes: Number(process.argv[2]), core_opt_level: process.argv[3] || "profile" };
  console.log(JSON.stringify(browser));
' "$browser" "$gz_bytes" "${WASM_CORE_OPT_LEVEL:-}"
