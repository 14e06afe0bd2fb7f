#!/usr/bin/env bash
# Builds the release site into dist/ (static files; works from any sub-path), reports its
# transfer size (gzip -9) and fails when the first load is over the budget the README
# states ("size budget: **N KB**"). The first load is what index.html loads: the app's
# wasm and js and the css; the import worker (plc-import*) loads only when a PLCopen XML or
# PNML file is imported, the exercise worker (plc-exercise*) only when an exercise is
# opened or checked; they are reported on their own.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$PWD/node_modules/.bin:$HOME/.cargo/bin:$PATH"
(cd web && trunk build --release)
node scripts/minify-js.mjs dist
node scripts/csp.mjs dist/index.html
# The site's files, for the page's `Export SCORM package` (the exercise worker packs them).
(cd dist && find . -type f ! -name site-files.txt | sed 's|^\./||' | LC_ALL=C sort) > dist/site-files.txt
gz() { gzip -9 -c "$1" | wc -c; }
first=0
lazy=0
exercise=0
for f in dist/*.wasm dist/*.js dist/*.css; do
  [ -f "$f" ] || continue
  size=$(gz "$f")
  case "$(basename "$f")" in
    plc-import*) lazy=$((lazy + size)); when="on import" ;;
    plc-exercise*) exercise=$((exercise + size)); when="on an exercise" ;;
    *) first=$((first + size)); when="first load" ;;
  esac
  printf '  %-40s %8d bytes gzipped (%s)\n' "$(basename "$f")" "$size" "$when"
done
printf '  %-40s %8d bytes gzipped (%d KB)\n' "first load" "$first" "$((first / 1024))"
printf '  %-40s %8d bytes gzipped (%d KB)\n' "import worker, loaded on import" "$lazy" "$((lazy / 1024))"
printf '  %-40s %8d bytes gzipped (%d KB)\n' "exercise worker, loaded on an exercise" "$exercise" "$((exercise / 1024))"
budget_kb=$(grep -oE 'size budget: \*\*[0-9]+ KB\*\*' README.md | grep -oE '[0-9]+' || true)
if [ -z "$budget_kb" ]; then
  echo "error: README.md states no size budget (\"size budget: **N KB**\")" >&2
  exit 1
fi
if [ "$first" -gt $((budget_kb * 1024)) ]; then
  echo "error: the first load is $((first / 1024)) KB gzipped, over the ${budget_kb} KB budget in README.md" >&2
  echo "       (raise the budget only with a line in BENCHMARKS.md saying what paid for it)" >&2
  exit 1
fi
echo "  within the ${budget_kb} KB size budget"
