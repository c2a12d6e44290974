#!/usr/bin/env bash
# Reproduces the measurements behind service/http_tuning.h, with bench/peers/httplib_echo in its
# three modes (untuned = Debian's libcpp-httplib 0.11.4 with its compiled-in defaults; setters =
# runtime setters, the library's own connection loop and fixed pool; tuned = cutcalc's Listener and
# event-loop engine, as cutcalc):
#   1. 43 ms per request on one keep-alive connection: Nagle + delayed ACK (two send()s per
#      response); counted with nstat TcpExtDelayedACKs and strace.
#   2. New connections stall while <threads> idle keep-alive connections are open (fixed pool).
#   3. A burst of connects overflows the listen backlog of 5 (ListenOverflows, SYN retransmits).
#   4. CPU burnt by idle keep-alive connections (library: 10 ms poll + 1 ms sleep loop).
#   5. CPU per request at 64 connections: the library's thread per connection vs event loops.
# usage: bench/http_rootcause.sh [--echo PATH]   (default build/release/bench/peers/httplib_echo)
# Loopback only; every run is bounded (3 s wrk runs, <= 300 connections); takes about 1 minute.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ECHO_BIN="${HTTPLIB_ECHO_BIN:-$ROOT/build/release/bench/peers/httplib_echo}"
[[ "${1:-}" == "--echo" ]] && ECHO_BIN="$2"
[[ -x "$ECHO_BIN" ]] || { echo "httplib_echo not found: $ECHO_BIN" >&2; exit 2; }
LUA="$ROOT/bench/wrk_post.lua"
PROBE="$ROOT/bench/http_probe.py"
URL_PATH=/v1/entry-length
BODY='{"cutter_diameter_mm": 20, "offset_mm": 0, "entry": {"contour": "straight", "width_mm": 60, "angle_deg": 90}}'
SERVER_PID=""
PORT=""

cleanup() {
  if [[ -n "$SERVER_PID" ]] && kill -0 "$SERVER_PID" 2>/dev/null; then
    kill -TERM "$SERVER_PID" 2>/dev/null || true
    wait "$SERVER_PID" 2>/dev/null || true
  fi
  SERVER_PID=""
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

start() {  # echo arguments...
  cleanup
  PORT="$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
  "$ECHO_BIN" --host 127.0.0.1 --port "$PORT" "$@" >/dev/null 2>&1 &
  SERVER_PID=$!
  for _ in $(seq 50); do
    curl -s -o /dev/null --max-time 1 -X POST --data '{}' "http://127.0.0.1:$PORT/" && return 0
    sleep 0.1
  done
  echo "echo did not start: $*" >&2
  exit 1
}

wrk_line() {  # threads conns seconds -> "rps p50 p99 max non2xx+socket-errors requests"
  wrk -t"$1" -c"$2" -d"$3s" -s "$LUA" "http://127.0.0.1:$PORT$URL_PATH" -- "$BODY" 2>/dev/null |
    sed -n 's/^WRK_RESULT //p' | python3 -c '
import json, sys
d = json.loads(sys.stdin.read())
errors = d["non2xx"] + d["connect"] + d["read"] + d["write"] + d["timeout"]
print("%.0f %.2f %.2f %.1f %d %d" % (d["rps"], d["p50_us"] / 1000, d["p99_us"] / 1000,
                                     d["max_us"] / 1000, errors, d["requests"]))'
}

cpu_ms() {  # user+system CPU of the server so far, in ms
  awk -v hz="$(getconf CLK_TCK)" '{print int(($14 + $15) * 1000 / hz)}' "/proc/$SERVER_PID/stat"
}

nstat_value() {  # counter name from a saved `nstat` output
  awk -v n="$2" '$1 == n {print $2; found = 1} END {if (!found) print 0}' "$1"
}

echo "## 1. One keep-alive connection (wrk -c1, 3 s)"
echo "| server | req/s | p50 ms | p99 ms | delayed ACKs per request |"
echo "|---|---:|---:|---:|---:|"
for variant in "untuned:--mode untuned" "untuned + TCP_NODELAY:--mode untuned --nodelay 1" \
               "tuned (cutcalc engine):--mode tuned"; do
  name="${variant%%:*}"
  read -r -a args <<<"${variant#*:}"
  start "${args[@]}"
  nstat -n >/dev/null
  read -r rps p50 p99 _ _ requests <<<"$(wrk_line 1 1 3)"
  nstat >/tmp/http_rootcause.nstat.$$ 2>/dev/null || true
  delayed="$(nstat_value /tmp/http_rootcause.nstat.$$ TcpExtDelayedACKs)"
  rm -f /tmp/http_rootcause.nstat.$$
  echo "| $name | $rps | $p50 | $p99 | $(python3 -c "print(f'{$delayed / max($requests, 1):.2f}')") |"
done
if command -v strace >/dev/null; then
  echo
  echo "send() calls per response (strace, 3 requests on one connection):"
  for mode in untuned tuned; do
    start --mode "$mode"
    # shellcheck disable=SC2046  # one -p per thread
    strace -qq -e trace=sendto,write -o /tmp/http_rootcause.strace.$$ \
      $(ls /proc/"$SERVER_PID"/task | sed 's/^/-p /') &
    tracer=$!
    sleep 0.5
    curl -s -o /dev/null -X POST --data '{"a":1}' "http://127.0.0.1:$PORT/a" \
         -o /dev/null -X POST --data '{"a":1}' "http://127.0.0.1:$PORT/b" \
         -o /dev/null -X POST --data '{"a":1}' "http://127.0.0.1:$PORT/c"
    sleep 0.3
    kill -INT "$tracer" 2>/dev/null || true
    wait "$tracer" 2>/dev/null || true
    sends="$(grep -c 'sendto(' /tmp/http_rootcause.strace.$$ || true)"
    echo "- $mode: $sends sendto() for 3 responses; first ones:"
    grep 'sendto(' /tmp/http_rootcause.strace.$$ | head -2 | sed 's/^/    /' | cut -c1-110
    rm -f /tmp/http_rootcause.strace.$$
  done
fi

echo
echo "## 2. A fresh request while 8 idle keep-alive connections are open"
for variant in "untuned + TCP_NODELAY (fixed pool of max(8, cores-1)):--mode untuned --nodelay 1" \
               "setters (library loop and fixed pool):--mode setters" \
               "tuned (cutcalc engine, event loops):--mode tuned"; do
  name="${variant%%:*}"
  read -r -a args <<<"${variant#*:}"
  start "${args[@]}"
  echo "- $name: $(timeout 60 python3 "$PROBE" hold "$PORT" 8 --fresh 3 | tail -1)"
done

echo
echo "## 3. 256 connections at once (wrk -c256, 3 s)"
echo "| server | listen backlog | req/s | p99 ms | max ms | errors | ListenOverflows | SYN retransmits |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for variant in "untuned + TCP_NODELAY:5:--mode untuned --nodelay 1" \
               "setters, backlog kept at 5:5:--mode setters --backlog 5" \
               "setters:1024:--mode setters" \
               "tuned:1024:--mode tuned"; do
  IFS=: read -r name backlog argstr <<<"$variant"
  read -r -a args <<<"$argstr"
  start "${args[@]}"
  nstat -n >/dev/null
  read -r rps _ p99 max errors _ <<<"$(wrk_line 2 256 3)"
  nstat >/tmp/http_rootcause.nstat.$$ 2>/dev/null || true
  echo "| $name | $backlog | $rps | $p99 | $max | $errors |" \
       "$(nstat_value /tmp/http_rootcause.nstat.$$ TcpExtListenOverflows) |" \
       "$(nstat_value /tmp/http_rootcause.nstat.$$ TcpExtTCPSynRetrans) |"
  rm -f /tmp/http_rootcause.nstat.$$
done

echo
echo "## 4. Server CPU while 300 keep-alive connections sit idle (3 s)"
for variant in "setters (library loop, one thread each):--mode setters" \
               "tuned (event loops):--mode tuned"; do
  name="${variant%%:*}"
  read -r -a args <<<"${variant#*:}"
  start "${args[@]}"
  out="$(mktemp)"
  timeout 60 python3 "$PROBE" hold "$PORT" 300 --idle 4 --fresh 1 >"$out" &
  holder=$!
  for _ in $(seq 100); do grep -q idle "$out" && break; sleep 0.1; done
  sleep 0.5
  c0="$(cpu_ms)"
  sleep 3
  c1="$(cpu_ms)"
  threads="$(ls /proc/"$SERVER_PID"/task | wc -l)"
  wait "$holder" || true
  rm -f "$out"
  echo "- $name: $((c1 - c0)) ms CPU in 3 s, $threads threads"
done

echo
echo "## 5. 64 busy keep-alive connections (wrk -c64, 3 s, 2 runs each)"
echo "| server | req/s | p50 ms | p99 ms | server CPU per request (us) |"
echo "|---|---:|---:|---:|---:|"
for round in 1 2; do
  for variant in "setters (library loop):--mode setters" \
                 "tuned (event loops):--mode tuned"; do
    name="${variant%%:*}"
    read -r -a args <<<"${variant#*:}"
    start "${args[@]}"
    c0="$(cpu_ms)"
    read -r rps p50 p99 _ _ requests <<<"$(wrk_line 2 64 3)"
    c1="$(cpu_ms)"
    echo "| $name | $rps | $p50 | $p99 | $(python3 -c "print(f'{($c1 - $c0) * 1000 / max($requests, 1):.1f}')") |"
  done
done
