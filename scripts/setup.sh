#!/usr/bin/env bash
# Installs what the build and the tests need, when it is missing. Idempotent: a tool that is
# already installed at the right version is left alone.
set -euo pipefail
cd "$(dirname "$0")/.."

log() { printf '[setup] %s\n' "$*"; }

if ! command -v cargo >/dev/null 2>&1; then
  echo "cargo is missing: install Rust (rustup) first" >&2
  exit 1
fi

if ! rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown; then
  log "adding the wasm32-unknown-unknown target"
  rustup target add wasm32-unknown-unknown
fi
# The site's build compiles the standard library with the app (scripts/wasm-build.sh).
if [ ! -f "$(rustc --print sysroot)/lib/rustlib/src/rust/library/Cargo.lock" ]; then
  log "adding the rust-src component"
  rustup component add rust-src
fi

# The wasm-bindgen CLI must match the wasm-bindgen crate version in Cargo.lock exactly.
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock 2>/dev/null || true)
if [ -z "$want" ]; then
  cargo generate-lockfile >/dev/null 2>&1 || true
  want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
fi
have=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}' || true)
if [ "$have" != "$want" ] || ! command -v wasm-bindgen-test-runner >/dev/null 2>&1; then
  log "installing wasm-bindgen-cli $want (about 7 minutes)"
  cargo install wasm-bindgen-cli --version "$want"
fi

# trunk builds the web app. 0.22 needs a newer rustc; 0.21.14 builds only with --locked.
if [ "$(trunk --version 2>/dev/null | awk '{print $2}')" != "0.21.14" ]; then
  log "installing trunk 0.21.14 (about 17 minutes)"
  cargo install trunk --version 0.21.14 --locked
fi

# wasm-split-cli cuts the app's wasm into the first load and the chunks loaded on first use
# (scripts/build-web.sh, docs/loading.md).
if ! command -v wasm-split-cli >/dev/null 2>&1 \
  || ! cargo install --list | grep -q '^wasm_split_cli_support v0.2.4:'; then
  log "installing wasm-split-cli 0.2.4 (wasm_split_cli_support, about 3 minutes)"
  cargo install --locked wasm_split_cli_support --version 0.2.4 --features build-binary
fi

apt_updated=""
apt_install() {
  if [ -z "$apt_updated" ]; then apt-get update -qq; apt_updated=1; fi
  apt-get install -y -qq "$@"
}
command -v node >/dev/null 2>&1 || { log "installing Node.js"; apt_install nodejs npm; }
command -v npm >/dev/null 2>&1 || { log "installing npm"; apt_install npm; }
# Debian's browsers for the browser tests (never a downloaded browser): Chromium; Firefox
# ESR and WebKitGTK (WebKitWebDriver with its MiniBrowser) for the cross-engine suite, and
# xvfb-run for MiniBrowser, which has no headless mode. (About 4 minutes for the last three.)
command -v chromium >/dev/null 2>&1 || { log "installing Chromium"; apt_install chromium chromium-driver; }
command -v firefox-esr >/dev/null 2>&1 || { log "installing Firefox ESR"; apt_install firefox-esr; }
command -v WebKitWebDriver >/dev/null 2>&1 || { log "installing WebKitGTK's WebDriver and MiniBrowser"; apt_install webkit2gtk-driver; }
command -v xvfb-run >/dev/null 2>&1 || { log "installing xvfb"; apt_install xvfb xauth; }

# playwright-core (drives Chromium), puppeteer-core (drives Firefox over WebDriver BiDi),
# selenium-webdriver (drives WebKitWebDriver), binaryen's wasm-opt 132 (used by trunk),
# terser (minifies the app's JS glue in scripts/build-web.sh) and axe-core (the
# accessibility check of tests/e2e/axe.test.mjs). None downloads a browser.
if [ ! -x node_modules/.bin/wasm-opt ] || [ ! -d node_modules/playwright-core ] || [ ! -d node_modules/terser ] \
  || [ ! -d node_modules/puppeteer-core ] || [ ! -d node_modules/selenium-webdriver ] \
  || [ ! -f node_modules/axe-core/axe.min.js ]; then
  log "installing npm packages"
  npm ci --no-audit --no-fund
fi
log "ready: $(rustc --version), wasm-bindgen $want, trunk $(trunk --version | awk '{print $2}'), wasm-split-cli 0.2.4, node $(node --version)"
