# shellcheck shell=bash
# Sourced by the CI steps that drive a live cutcalc (ci-contract.sh, ci-e2e.sh), from the repository
# root, after they define die().
#
# start_cutcalc BIN LOG STEP: builds the release binary when BIN is missing, starts it on a free
# loopback port with its log in LOG, and waits (up to 20 s) for its "listening on" line.
# Sets CUTCALC_BIN, CUTCALC_PID and CUTCALC_PORT; the caller stops CUTCALC_PID.
start_cutcalc() {
  local bin=$1 log=$2 step=$3
  if [[ ! -x "$bin" ]]; then
    echo "=== $step: building cutcalc (release)"
    cmake --preset release
    cmake --build --preset release --target cutcalc -j 2
    bin=$PWD/build/release/service/cutcalc
  fi
  "$bin" --host 127.0.0.1 --port 0 --threads 2 --log-level info --log-format text >"$log" 2>&1 &
  CUTCALC_PID=$!
  # shellcheck disable=SC2034 # read by the caller
  CUTCALC_BIN=$bin
  CUTCALC_PORT=
  for _ in $(seq 1 200); do
    CUTCALC_PORT=$(sed -n 's/.*listening on http:\/\/127\.0\.0\.1:\([0-9][0-9]*\).*/\1/p' "$log" | head -n 1)
    [[ -n "$CUTCALC_PORT" ]] && return 0
    kill -0 "$CUTCALC_PID" 2>/dev/null || { cat "$log" >&2; die "cutcalc exited at start"; }
    sleep 0.1
  done
  cat "$log" >&2
  die "cutcalc did not report its port within 20 s"
}
