#!/usr/bin/env bash
# Idle-connection memory (issue 24): what N idle keep-alive connections cost cutcalc.
# Starts cutcalc on a free loopback port, then bench/idle_conns.py (/usr/bin/python3) opens N
# connections (default 10 000) in batches, sends one request on each (GET /healthz, or with
# --request post the groove-wall POST from bench/scenarios.sh) and reads the whole answer, then
# leaves them idle for --idle seconds (default 3, under today's 5 s keep-alive idle timeout).
# Measured: the server's VmRSS (/proc/PID/status) and Pss (/proc/PID/smaps_rollup) before the
# first connection, when all have been answered and after the idle time, in MiB, and per
# connection in KiB ((idle - before) / N); how many connections are still open after the idle
# time (the measurement is of N idle connections only if all are), and with --reuse whether each
# still answers a second request. Kernel socket buffers are not in these figures.
# Goal (the issue's "done when"): with N = 10 000 idle keep-alive connections, all still open,
# VmRSS < 64 MiB (the pod limit is 256 MiB; today's 16 KiB read buffer per idle connection gave
# 254 MiB at 15 000).
# The descriptor limit of both processes is raised to min(65536, the hard limit) with ulimit -n.
#
# usage: bench/idle_memory.sh [--binary PATH] [--conns N] [--idle S] [--request healthz|post]
#                             [--server-args "ARGS"] [--reuse] [--limit-mib M] [--strict]
#   env: CUTCALC_BIN, IDLE_MEMORY_CONNS (flags win)
#   --binary       default build/release/service/cutcalc, started as
#                  cutcalc --host 127.0.0.1 --port P --log-level warn ARGS
#   --conns        idle connections, default 10000
#   --idle         seconds of idleness before the second sample, default 3
#   --request      the one request per connection: healthz (default) or post (groove-wall)
#   --server-args  extra flags for cutcalc, e.g. "--keep-alive-timeout 75"
#   --reuse        after the idle sample, one more request on every open connection
#   --limit-mib    the goal, default 64
#   --strict       exit 3 if the goal fails
# Output: readable lines and a PASS/FAIL line on stdout; the client's output and the server log
# under bench/results/idle-<timestamp>/ (gitignored). The server is started and stopped here;
# nothing is left running, also on Ctrl-C.
# Example: bench/idle_memory.sh --strict                (about 15 s)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BENCH_NAME=idle_memory
# shellcheck source=bench/lib/processes.sh
source "$ROOT/bench/lib/processes.sh"
# shellcheck source=bench/scenarios.sh
source "$ROOT/bench/scenarios.sh"

CUTCALC_BIN="${CUTCALC_BIN:-$ROOT/build/release/service/cutcalc}"
CONNS="${IDLE_MEMORY_CONNS:-10000}"
IDLE=3
REQUEST=healthz
SERVER_ARGS=""
REUSE=0
LIMIT_MIB=64
STRICT=0

die() { echo "idle_memory: $*" >&2; exit 2; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --binary) CUTCALC_BIN="$2"; shift 2 ;;
    --conns) CONNS="$2"; shift 2 ;;
    --idle) IDLE="$2"; shift 2 ;;
    --request) REQUEST="$2"; shift 2 ;;
    --server-args) SERVER_ARGS="$2"; shift 2 ;;
    --reuse) REUSE=1; shift ;;
    --limit-mib) LIMIT_MIB="$2"; shift 2 ;;
    --strict) STRICT=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d'; exit 0 ;;
    *) die "unknown argument: $1 (see --help)" ;;
  esac
done

[[ "$CONNS" =~ ^[0-9]+$ && "$CONNS" -ge 1 && "$CONNS" -le 60000 ]] || die "--conns must be 1..60000"
[[ "$IDLE" =~ ^[0-9]+([.][0-9]+)?$ ]] || die "--idle must be a number of seconds"
[[ "$REQUEST" == healthz || "$REQUEST" == post ]] || die "--request must be healthz or post"
[[ "$LIMIT_MIB" =~ ^[0-9]+$ ]] || die "--limit-mib must be a whole number"
[[ -x "$CUTCALC_BIN" ]] || die "cutcalc binary not found: $CUTCALC_BIN (--binary PATH)"
command -v curl >/dev/null || die "curl is required"
PYTHON=/usr/bin/python3
[[ -x "$PYTHON" ]] || PYTHON="$(command -v python3)"
read -r -a EXTRA_ARGS <<<"$SERVER_ARGS"

# Both the server and the client inherit this limit.
hard="$(ulimit -Hn)"
nofile=65536
[[ "$hard" != unlimited && "$hard" -lt "$nofile" ]] && nofile="$hard"
ulimit -n "$nofile"
((CONNS + 64 <= nofile)) || die "$CONNS connections need more descriptors than the limit $nofile"

STAMP="$(date -u +%Y%m%dT%H%M%SZ)"
RESULTS="$ROOT/bench/results/idle-$STAMP"
mkdir -p "$RESULTS"
SERVER_PID=""
CLIENT_PID=""

# shellcheck disable=SC2317 # run from the EXIT trap
cleanup() {
  local status=$?
  trap - EXIT INT TERM
  [[ -n "$CLIENT_PID" ]] && stop_pid "$CLIENT_PID"
  [[ -n "$SERVER_PID" ]] && stop_pid "$SERVER_PID"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

PORT="$("$PYTHON" -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()')"
"$CUTCALC_BIN" --host 127.0.0.1 --port "$PORT" --log-level warn "${EXTRA_ARGS[@]}" >"$RESULTS/server.log" 2>&1 &
SERVER_PID=$!
ready=0
for ((i = 0; i < 150; i++)); do
  kill -0 "$SERVER_PID" 2>/dev/null || { cat "$RESULTS/server.log" >&2; die "cutcalc exited at start"; }
  if [[ "$(curl -s -o /dev/null -w '%{http_code}' --max-time 1 "http://127.0.0.1:$PORT/healthz" || true)" == 200 ]]; then
    ready=1
    break
  fi
  sleep 0.1
done
[[ $ready -eq 1 ]] || die "cutcalc did not answer /healthz within 15 s"

{
  echo "date: $STAMP"
  echo "host: $(uname -srm), $(nproc) cores, load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "git: $(git -C "$ROOT" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
  echo "cutcalc: $CUTCALC_BIN (built $(date -u -r "$CUTCALC_BIN" +%FT%TZ)) --log-level warn $SERVER_ARGS, pid $SERVER_PID, RLIMIT_NOFILE $nofile"
  echo "client: $CONNS keep-alive connections, one $([[ $REQUEST == post ]] && echo "POST ${SCENARIO_PATH[groove-wall]}" || echo "GET /healthz") each, then ${IDLE} s idle$([[ $REUSE -eq 1 ]] && echo ", then one more request each")"
} | tee "$RESULTS/meta.txt"

CLIENT_ARGS=("$SERVER_PID" "$PORT" --n "$CONNS" --idle "$IDLE" --request "$REQUEST"
  --path "${SCENARIO_PATH[groove-wall]}" --body "${SCENARIO_BODY[groove-wall]}")
[[ $REUSE -eq 1 ]] && CLIENT_ARGS+=(--reuse)
"$PYTHON" "$ROOT/bench/idle_conns.py" "${CLIENT_ARGS[@]}" >"$RESULTS/client.txt" 2>&1 &
CLIENT_PID=$!
client_rc=0
wait "$CLIENT_PID" || client_rc=$?
CLIENT_PID=""
grep -v '^IDLE_RESULT ' "$RESULTS/client.txt" || true
[[ $client_rc -eq 0 ]] || die "the client failed (exit $client_rc): see $RESULTS/client.txt"
kill -0 "$SERVER_PID" 2>/dev/null || die "cutcalc exited during the measurement: see $RESULTS/server.log"

verdict=0
"$PYTHON" - "$RESULTS/client.txt" "$LIMIT_MIB" >"$RESULTS/summary.txt" <<'PY' || verdict=$?
import json, sys
res = None
for line in open(sys.argv[1]):
    if line.startswith("IDLE_RESULT "):
        res = json.loads(line[len("IDLE_RESULT "):])
limit = int(sys.argv[2])
n = res["n"]
rss, pss = res["rss_kib"], res["pss_kib"]
mib = lambda k: k / 1024
print(f"{n} idle connections: VmRSS {mib(rss['idle']):.1f} MiB (before {mib(rss['base']):.1f} MiB, "
      f"{res['kib_per_conn_rss']:.2f} KiB per connection); Pss {mib(pss['idle']):.1f} MiB "
      f"({res['kib_per_conn_pss']:.2f} KiB per connection)")
all_open = res["open_after_idle"] == n and res["answered_200"] == n
ok = all_open and mib(rss["idle"]) < limit
reason = "" if all_open else (f" (only {res['answered_200']} answered 200 and {res['open_after_idle']} of {n} "
                              f"still open after {res['idle_seconds']:g} s: not a measurement of {n} idle connections)")
print(f"{'PASS' if ok else 'FAIL'}: VmRSS with {n} idle keep-alive connections "
      f"{mib(rss['idle']):.1f} MiB < {limit} MiB{reason}")
sys.exit(0 if ok else 1)
PY
cat "$RESULTS/summary.txt"
echo "results: $RESULTS" >&2
if [[ $STRICT -eq 1 && $verdict -ne 0 ]]; then exit 3; fi
exit 0
