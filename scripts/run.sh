#!/usr/bin/env bash
# The main job until the web app lands: build `plc` and run the shipped weighing example for
# a few seconds of virtual time, printing its variables. Pass other `plc run` flags to
# override, e.g. `bash scripts/run.sh --cycles 10 --json`.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v cargo >/dev/null || { echo "cargo is missing: install Rust (rustup) first" >&2; exit 1; }
cargo build --release --quiet -p plc-core --bin plc
example=examples/weighing.st
echo "== plc check $example"
./target/release/plc check "$example"
echo "== plc run $example (5 s of virtual time at 10 ms per scan)"
if [ "$#" -gt 0 ]; then
  ./target/release/plc run "$example" "$@"
else
  ./target/release/plc run "$example" --cycles 500 --cycle-ms 10 --set Start=TRUE --set Weight=1000 --set Setpoint=500
fi
