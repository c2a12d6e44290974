#!/usr/bin/env bash
# Sets up, builds the release binary and runs the service (default http://127.0.0.1:8080).
# Extra arguments go to cutcalc, e.g. scripts/run.sh --port 9000 --log-format json
set -euo pipefail
cd "$(dirname "$0")/.."
# Only what the service needs: no test packages, no Node.js (the tests' setup is scripts/test.sh).
scripts/setup.sh --service
cmake --preset service >/dev/null
cmake --build --preset service --target cutcalc
exec build/service/service/cutcalc "$@"
