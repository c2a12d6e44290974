#!/usr/bin/env bash
# Side-by-side HTTP benchmark of two cutcalc binaries (e.g. main's and a change's), one endpoint:
# each server pinned to core 0 (taskset), wrk pinned to core 1, rounds alternating A B B A ... so
# that drift of a noisy machine falls on both. Reports per round and as medians: requests/s,
# p50/p99 latency, the server's CPU per request (user + system, from /proc), and the B/A ratios.
#
# usage: bench/engine_compare.sh --baseline PATH --candidate PATH
#                                [--scenario groove-wall|entry-length | --path P --body JSON]
#                                [--conns N] [--duration S] [--rounds N]
#   defaults: the groove-wall scenario of bench/scenarios.sh, 64 connections, 10 s, 6 rounds.
# Loopback only; each run is bounded by --duration; servers are stopped on exit.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BASELINE=""
CANDIDATE=""
# shellcheck source=bench/scenarios.sh
source "$ROOT/bench/scenarios.sh"
URL_PATH="${SCENARIO_PATH[groove-wall]}"
BODY="${SCENARIO_BODY[groove-wall]}"
CONNS=64
DURATION=10
ROUNDS=6
while [[ $# -gt 0 ]]; do
  case "$1" in
    --baseline) BASELINE="$2"; shift 2 ;;
    --candidate) CANDIDATE="$2"; shift 2 ;;
    --scenario)
      [[ -n "${SCENARIO_PATH[$2]:-}" ]] || { echo "engine_compare: --scenario: one of ${SCENARIOS[*]}" >&2; exit 2; }
      URL_PATH="${SCENARIO_PATH[$2]}"; BODY="${SCENARIO_BODY[$2]}"; shift 2 ;;
    --path) URL_PATH="$2"; shift 2 ;;
    --body) BODY="$2"; shift 2 ;;
    --conns) CONNS="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    --rounds) ROUNDS="$2"; shift 2 ;;
    *) echo "engine_compare: unknown argument $1" >&2; exit 2 ;;
  esac
done
[[ -x "$BASELINE" && -x "$CANDIDATE" ]] || { echo "need --baseline and --candidate binaries" >&2; exit 2; }
command -v wrk >/dev/null || { echo "wrk not found (apt-get install wrk)" >&2; exit 2; }
[[ $(nproc) -ge 2 ]] || { echo "needs two cores (server and load generator apart)" >&2; exit 2; }

LUA="$ROOT/bench/wrk_post.lua"  # POSTs the body given after --
RESULTS="$(mktemp)"
SERVER_PID=""
cleanup() {
  if [[ -n "$SERVER_PID" ]] && kill -0 "$SERVER_PID" 2>/dev/null; then
    kill -TERM "$SERVER_PID" 2>/dev/null || true
    wait "$SERVER_PID" 2>/dev/null || true
  fi
  rm -f "$RESULTS"
}
trap cleanup EXIT

cpu_ticks() { awk '{print $14 + $15}' "/proc/$SERVER_PID/stat"; }

run() {  # label binary
  local port
  port="$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
  taskset -c 0 "$2" --host 127.0.0.1 --port "$port" --log-level warn >/dev/null 2>&1 &
  SERVER_PID=$!
  for _ in $(seq 50); do
    curl -s -o /dev/null --max-time 1 "http://127.0.0.1:$port/healthz" && break
    sleep 0.1
  done
  taskset -c 1 wrk -t2 -c"$CONNS" -d1s -s "$LUA" "http://127.0.0.1:$port$URL_PATH" -- "$BODY" >/dev/null  # warm-up
  local c0 c1 line
  c0="$(cpu_ticks)"
  line="$(taskset -c 1 wrk -t2 -c"$CONNS" -d"${DURATION}s" -s "$LUA" \
            "http://127.0.0.1:$port$URL_PATH" -- "$BODY" | sed -n 's/^WRK_RESULT //p')"
  c1="$(cpu_ticks)"
  kill -TERM "$SERVER_PID"
  wait "$SERVER_PID" 2>/dev/null || true
  SERVER_PID=""
  python3 - "$1" "$line" "$c0" "$c1" "$(getconf CLK_TCK)" >>"$RESULTS" <<'PY'
import json, sys
label, line, c0, c1, hz = sys.argv[1], json.loads(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
errors = line["non2xx"] + line["connect"] + line["read"] + line["write"] + line["timeout"]
cpu_us = (c1 - c0) * 1e6 / hz / max(line["requests"], 1)
print(json.dumps({"label": label, "rps": line["rps"], "p50_ms": line["p50_us"] / 1000,
                  "p99_ms": line["p99_us"] / 1000, "cpu_us": cpu_us, "errors": errors}))
PY
}

echo "POST $URL_PATH, $CONNS connections, ${DURATION} s per run, $ROUNDS rounds;"
echo "server on core 0 (taskset), wrk -t2 on core 1; A = $BASELINE, B = $CANDIDATE"
for round in $(seq "$ROUNDS"); do
  if (( round % 2 )); then run A "$BASELINE"; run B "$CANDIDATE"; else run B "$CANDIDATE"; run A "$BASELINE"; fi
done
python3 - "$RESULTS" <<'PY'
import json, statistics, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
print("\n| run | server | req/s | p50 ms | p99 ms | CPU us/request | errors |")
print("|---:|---|---:|---:|---:|---:|---:|")
for i, r in enumerate(rows):
    print(f"| {i // 2 + 1} | {r['label']} | {r['rps']:.0f} | {r['p50_ms']:.2f} | {r['p99_ms']:.2f} | {r['cpu_us']:.1f} | {r['errors']} |")
med = {l: {k: statistics.median(r[k] for r in rows if r["label"] == l) for k in ("rps", "p50_ms", "p99_ms", "cpu_us")} for l in "AB"}
print("\n| median | req/s | p50 ms | p99 ms | CPU us/request |")
print("|---|---:|---:|---:|---:|")
for l in "AB":
    m = med[l]
    print(f"| {l} | {m['rps']:.0f} | {m['p50_ms']:.2f} | {m['p99_ms']:.2f} | {m['cpu_us']:.1f} |")
print(f"| B/A | {med['B']['rps'] / med['A']['rps']:.3f} | {med['B']['p50_ms'] / med['A']['p50_ms']:.3f} | "
      f"{med['B']['p99_ms'] / med['A']['p99_ms']:.3f} | {med['B']['cpu_us'] / med['A']['cpu_us']:.3f} |")
PY
