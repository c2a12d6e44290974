#!/usr/bin/env bash
# Where cutcalc's CPU goes per request, stage by stage (issue 14): cutcalc on one core with one
# event loop, wrk -t1 on the other, one scenario of bench/scenarios.sh. A first run measures the
# server's CPU per request without a profiler (utime + stime from /proc over the requests
# answered); a second run, under `perf record --call-graph dwarf`, gives each stage's share of
# the server's samples (inclusive: a stage counts the functions it calls). Each stage's
# microseconds per request = its share x the CPU per request of the first run.
#
# usage: bench/http_stages.sh [--cutcalc PATH] [--scenario groove-wall|entry-length]
#                             [--conns N] [--duration S] [--server-cpu N] [--client-cpu N]
#   defaults: build/release/service/cutcalc, groove-wall, 64 connections, 5 s, CPUs 0 and 1.
# Needs perf (Debian: linux-perf) allowed to profile the server (root, or
# kernel.perf_event_paranoid <= 1). Nothing is left running, also on Ctrl-C.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=bench/scenarios.sh
source "$ROOT/bench/scenarios.sh"
CUTCALC_BIN="$ROOT/build/release/service/cutcalc"
SCENARIO=groove-wall
CONNS=64
DURATION=5
SERVER_CPU=0
CLIENT_CPU=1

die() { echo "http_stages: $*" >&2; exit 2; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --cutcalc) CUTCALC_BIN="$2"; shift 2 ;;
    --scenario) SCENARIO="$2"; shift 2 ;;
    --conns) CONNS="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    --server-cpu) SERVER_CPU="$2"; shift 2 ;;
    --client-cpu) CLIENT_CPU="$2"; shift 2 ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) die "unknown argument: $1 (see --help)" ;;
  esac
done
[[ -n "${SCENARIO_PATH[$SCENARIO]:-}" ]] || die "--scenario must be one of: ${SCENARIOS[*]}"
[[ "$CONNS" =~ ^[0-9]+$ && "$CONNS" -ge 1 ]] || die "--conns must be a positive integer"
[[ "$DURATION" =~ ^[0-9]+$ && "$DURATION" -ge 1 ]] || die "--duration must be a positive integer"
[[ "$SERVER_CPU" != "$CLIENT_CPU" ]] || die "the server and wrk need different CPUs"
[[ -x "$CUTCALC_BIN" ]] || die "cutcalc not found: $CUTCALC_BIN (cmake --build --preset release)"
for tool in wrk perf taskset curl python3; do
  command -v "$tool" >/dev/null || die "$tool is required"
done
URL_PATH="${SCENARIO_PATH[$SCENARIO]}"
BODY="${SCENARIO_BODY[$SCENARIO]}"
LUA="$ROOT/bench/wrk_post.lua"

WORK="$(mktemp -d /tmp/http_stages.XXXXXX)"
SERVER_PID=""
cleanup() {
  if [[ -n "$SERVER_PID" ]] && kill -0 "$SERVER_PID" 2>/dev/null; then
    kill -TERM "$SERVER_PID" 2>/dev/null || true
    wait "$SERVER_PID" 2>/dev/null || true
  fi
  rm -rf "$WORK"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

PORT="$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
URL="http://127.0.0.1:$PORT$URL_PATH"
taskset -c "$SERVER_CPU" "$CUTCALC_BIN" --host 127.0.0.1 --port "$PORT" --threads 1 \
  --log-level warn >"$WORK/server.log" 2>&1 &
SERVER_PID=$!
for _ in $(seq 100); do
  curl -s -o /dev/null --max-time 1 "http://127.0.0.1:$PORT/healthz" && break
  sleep 0.1
done
kill -0 "$SERVER_PID" 2>/dev/null || { cat "$WORK/server.log" >&2; die "cutcalc did not start"; }

load() {  # seconds -> wrk's WRK_RESULT line
  taskset -c "$CLIENT_CPU" wrk -t1 -c"$CONNS" -d"${1}s" -s "$LUA" "$URL" -- "$BODY" |
    sed -n 's/^WRK_RESULT //p'
}
ticks() { awk '{print $14 + $15}' "/proc/$SERVER_PID/stat"; }

load 1 >/dev/null  # warm-up
before="$(ticks)"
plain="$(load "$DURATION")"
after="$(ticks)"

# The profiled run: perf starts once the load has, and stops before it ends.
load $((DURATION + 2)) >"$WORK/profiled.txt" &
LOAD_PID=$!
sleep 1
perf record -q --call-graph dwarf,16384 -F 1999 -p "$SERVER_PID" -o "$WORK/perf.data" \
  -- sleep "$DURATION" >/dev/null 2>&1 || die "perf record failed (permissions? see --help)"
wait "$LOAD_PID"
perf report -i "$WORK/perf.data" --children --sort symbol -g none --stdio --percent-limit 0 \
  2>/dev/null >"$WORK/report.txt"

python3 - "$WORK/report.txt" "$plain" "$before" "$after" "$(getconf CLK_TCK)" "$SCENARIO" \
  "$URL_PATH" "$CONNS" "$CUTCALC_BIN" <<'PY'
import json, re, sys

report, plain, before, after, hz, scenario, path, conns, binary = sys.argv[1:]
wrk = json.loads(plain)
cpu_us = (int(after) - int(before)) * 1e6 / int(hz) / max(wrk["requests"], 1)

# Inclusive share (% of the server's samples) of every symbol.
inclusive = {}
line_re = re.compile(r"^\s*([\d.]+)%\s+[\d.]+%\s+\[.\]\s+(.*?)(\s+-\s+-)?\s*$")
for line in open(report):
    m = line_re.match(line)
    if m:
        name = m.group(2)
        inclusive[name] = max(inclusive.get(name, 0.0), float(m.group(1)))

def share(*patterns):
    """Largest inclusive share among symbols matching any pattern (the outermost call)."""
    best = 0.0
    for name, pct in inclusive.items():
        if any(re.search(p, name) for p in patterns):
            best = max(best, pct)
    return best

def total(*patterns):
    """Sum over distinct patterns, each its outermost symbol."""
    return sum(share(p) for p in patterns)

handler = {"groove-wall": r"api::roughness::handle_groove_wall\b",
           "entry-length": r"api::entry::handle_entry_length\b"}[scenario]
domain = {"groove-wall": r"domain::roughness::compute_groove_wall_roughness\b",
          "entry-length": r"domain::entry::compute_entry_length\b"}[scenario]
answer = share(r"service::HttpApp::answer\b")
finish = share(r"service::HttpApp::finish\b")
write_response = share(r"service::write_response\b")
kernel_send = share(r"__x64_sys_sendto\b")
kernel_recv = share(r"__x64_sys_recvfrom\b")
kernel_epoll = total(r"__x64_sys_epoll_wait\b", r"__x64_sys_epoll_ctl\b")
framing = total(r"service::classify_request\b", r"service::framed_request\b")
parse = share(r"api::parse_json_body\b")
dump = share(r"detail::serializer<.*>::dump$")
handler_share = share(handler)
domain_share = share(domain)
endpoint = share(r"api::run_json_endpoint\b")
rest_of_endpoint = endpoint - parse - handler_share - dump
middleware = answer - endpoint - finish
accounted = kernel_send + kernel_recv + kernel_epoll + framing + answer + write_response
rows = [
    ("kernel: send() (loopback TCP, including delivery to the client's socket)", kernel_send, 0),
    ("kernel: recv()", kernel_recv, 0),
    ("kernel: epoll_wait() and epoll_ctl()", kernel_epoll, 0),
    ("engine: framing and the one parse (classify_request, framed_request)", framing, 0),
    ("engine: write_response (status line, headers, body)", write_response, 0),
    ("cutcalc: HttpApp::answer in all", answer, 0),
    ("middleware: request id, headers, route lookup, response headers", middleware, 1),
    ("metrics and access log (finish)", finish, 1),
    ("JSON parse (parse_json_body)", parse, 1),
    ("endpoint handler: fields, domain, building the answer", handler_share, 1),
    ("domain calculation alone", domain_share, 2),
    ("JSON dump", dump, 1),
    ("rest of run_json_endpoint (media type, finiteness check, destroying documents)",
     rest_of_endpoint, 1),
    ("engine loop, scheduling, interrupts and everything else", 100.0 - accounted, 0),
]
print(f"POST {path} ({scenario}), {conns} connections, cutcalc on one core with one event loop:")
print(f"{wrk['rps']:,.0f} req/s, server CPU {cpu_us:.2f} us/request (run without the profiler); "
      f"binary {binary}")
print()
print("| stage | share of server CPU | us/request |")
print("|---|---:|---:|")
for label, pct, depth in rows:
    indent = "· " * depth
    print(f"| {indent}{label} | {pct:.1f}% | {pct * cpu_us / 100.0:.2f} |")
PY
