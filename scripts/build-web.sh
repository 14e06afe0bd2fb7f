#!/usr/bin/env bash
# Builds the release site into dist/ (static files with relative URLs; works from any
# sub-path), reports each part's transfer size (gzip -9) and fails when the first load is
# over the budget the README states ("size budget: **N KB**"), when a part loaded on first
# use is over 200 KB, when opening an exercise adds over 150 KB, or when the first load
# holds ladder-editor, Petri-editor or exporter code (scripts/site.mjs). See
# docs/loading.md.
#
#   1. Trunk builds the page and its CSS and copies the static files (no Rust).
#   2. cargo builds the app (web/, `wasm-release` profile) keeping its relocations, with the
#      standard library built for size along with it (scripts/wasm-build.sh).
#   3. wasm-split cuts it at the `#[wasm_split]` functions (web/src/lazy.rs,
#      web/src/workers/mod.rs): the main module (the first load) and the chunks fetched on
#      first use, with the JS that links them (`__wasm_split.js`).
#   4. wasm-bindgen binds the main module; wasm-opt -Oz shrinks it and each chunk; the main
#      module's imports get short names (scripts/minify-imports.mjs); the engine's files go
#      into one (scripts/pack.mjs); terser minifies the JS.
#   5. scripts/site.mjs puts it all into dist/app-<hash>/, starts it from index.html, writes
#      the service worker dist/sw.js with the build's file list and id, and checks sizes.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$PWD/node_modules/.bin:$HOME/.cargo/bin:$PATH"

(cd web && trunk build --release)

work=target/site
rm -rf "$work"
mkdir -p "$work/split" "$work/app"

source scripts/wasm-build.sh
# The JSON messages name the build script's output folder, where web/build.rs writes the
# shipped exercises in their built form (exercises/ID.json, fetched by the exercise worker).
wasm_cargo build --profile "$WASM_PROFILE" "${wasm_cargo_flags[@]}" --target wasm32-unknown-unknown -p plc-web --bin plc-web \
  --message-format=json-render-diagnostics >"$work/cargo.json"
out_dir=$(node -e '
  for (const line of require("fs").readFileSync(process.argv[1], "utf8").split("\n")) {
    if (!line.startsWith("{")) continue;
    const m = JSON.parse(line);
    if (m.reason === "build-script-executed" && /(^|[/#])plc-web[#@ ]/.test(m.package_id)) { console.log(m.out_dir); break; }
  }' "$work/cargo.json")
[ -d "$out_dir/exercises" ] || { echo "no built exercises in '$out_dir'" >&2; exit 1; }
wasm-split-cli "target/wasm32-unknown-unknown/$WASM_PROFILE/plc-web.wasm" "$work/split" --out-name plc-web
# The main module before wasm-opt, names kept, for the check of what the first load holds.
cp "$work/split/plc-web.wasm" "$work/main-names.wasm"
wasm-bindgen --target web --no-typescript --keep-lld-exports --no-demangle \
  --out-dir "$work/app" --out-name plc-web "$work/split/plc-web.wasm"
# The main module (the longest) beside the chunks, one after another.
wasm_opt "$work/app/plc-web_bg.wasm" "$work/app/plc-web_bg.wasm" &
main_opt=$!
for f in "$work"/split/split_*.wasm "$work"/split/chunk_*.wasm; do
  [ -f "$f" ] || continue
  wasm_opt "$f" "$work/app/$(basename "$f")"
done
wait "$main_opt"
# The main module's imports from its glue, by short names in both (scripts/minify-imports.mjs).
node scripts/minify-imports.mjs "$work/app/plc-web_bg.wasm" "$work/app/plc-web.js"
cp "$work/split/__wasm_split.js" web/boot.js web/worker.js "$work/app/"
# The engine, fetched as the page starts, in one file rather than its 74 (scripts/pack.mjs).
# The diagram models' readers (a stored ladder project opens with them) do not wait for it.
node scripts/pack.mjs "$work" engine --apart project_reader
# The diagrams' and the exercises' style sheets come with their views (web/src/lazy.rs).
cp public/views.css public/exercises.css "$work/app/"
cp -r "$out_dir/exercises" "$work/app/exercises"
# The translations of the page's words (i18n/pl.json, i18n/cs.json), fetched when chosen.
cp -r "$out_dir/i18n" "$work/app/i18n"
node scripts/minify-js.mjs "$work/app"
node scripts/site.mjs assemble dist "$work"
node scripts/csp.mjs dist/index.html
# The site's files, for the page's `Export SCORM package` (the exercise worker packs them):
# all of dist/ with the sw.js that `finish` writes (before its size checks).
{ (cd dist && find . -type f ! -name site-files.txt ! -name sw.js | sed 's|^\./||'); echo sw.js; } \
  | LC_ALL=C sort > dist/site-files.txt
node scripts/site.mjs finish dist "$work"
