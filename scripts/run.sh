#!/usr/bin/env bash
# Sets up, builds the release binary and runs the service (default http://127.0.0.1:8080).
# Extra arguments go to cutcalc, e.g. scripts/run.sh --port 9000 --log-format json
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release --target cutcalc
exec build/release/service/cutcalc "$@"
