#!/usr/bin/env bash
# The main job: build the web app (installing what is missing) and serve it on
# http://127.0.0.1:8080. Stop with Ctrl+C.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build-web.sh
echo "== serving the PLC trainer on http://127.0.0.1:8080/"
exec python3 -m http.server 8080 --bind 127.0.0.1 --directory dist
