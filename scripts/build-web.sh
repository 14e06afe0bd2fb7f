#!/usr/bin/env bash
# Builds the release site into dist/ (static files; works from any sub-path) and reports
# its transfer size (gzip of wasm + js + css).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$PWD/node_modules/.bin:$HOME/.cargo/bin:$PATH"
(cd web && trunk build --release)
node scripts/csp.mjs dist/index.html
total=0
for f in dist/*.wasm dist/*.js dist/*.css; do
  [ -f "$f" ] || continue
  size=$(gzip -9 -c "$f" | wc -c)
  total=$((total + size))
  printf '  %-40s %8d bytes gzipped\n' "$(basename "$f")" "$size"
done
printf '  %-40s %8d bytes gzipped (%d KB)\n' "total transfer" "$total" "$((total / 1024))"
