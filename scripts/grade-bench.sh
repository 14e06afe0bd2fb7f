#!/usr/bin/env bash
# Grading a class (issue 15): `plc grade` on a folder of 200 generated submissions of the
# reversing-motor exercise (the heaviest shipped one per submission: a right answer runs
# all 200 random runs) — 50 right, 50 wrong (no interlock), 50 that do not build and 50
# that cannot be read (truncated project files) — writing CSV. Prints the wall time and
# checks there is one row per submission. The figure goes in BENCHMARKS.md (goal < 10 s).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release -q -p plc-core --bin plc
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
dir="$work/submissions"
mkdir "$dir"
ex=exercises/reversing
for i in $(seq -w 1 50); do
  cp "$ex/reference.st" "$dir/right-$i.st"
  cp "$ex/mutants/no-interlock.st" "$dir/wrong-$i.st"
  sed 's/MotorFwd := .*/MotorFwd := (Fwd OR ;/' "$ex/reference.st" > "$dir/broken-$i.st"
  printf '{"schema": 1, "name": "truncated' > "$dir/unreadable-$i.plcproj.json"
done
start=$(date +%s.%N)
target/release/plc grade "$ex/reversing.toml" "$dir" --format csv > "$work/grades.csv"
end=$(date +%s.%N)
rows=$(($(wc -l < "$work/grades.csv") - 1))
right=$(grep -c '^[^,]*right-[0-9]*\.st,2,2,' "$work/grades.csv" || true)
printf 'graded %d submissions (%d right with full marks) in %.2f s on %d cores\n' \
  "$rows" "$right" "$(echo "$end - $start" | bc)" "$(nproc)"
[ "$rows" -eq 200 ] && [ "$right" -eq 50 ]
