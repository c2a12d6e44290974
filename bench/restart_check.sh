#!/usr/bin/env bash
# Restart check (issue 24): two cutcalc instances behind a reverse proxy (nginx, Debian's
# nginx-light, and/or haproxy) under load, each stopped with SIGTERM and started again in turn,
# the way `docker stop`, a systemd restart or a deployment without a preStop pause does it.
# Per run: wrk (bench/wrk_post.lua, 32 connections, 2 threads) POSTs groove-wall (the body from
# bench/scenarios.sh) through the proxy for --duration seconds; at --a-at (duration/5, 4 s by
# default) instance A gets SIGTERM, the script waits for it to exit (its exit code and how long it
# took) and starts it again on the same port (until /healthz answers 200); at --b-at (3/4 of the
# duration, 15 s) the same for instance B. The two are 11 s apart because nginx disables a server
# that failed a request for fail_timeout (10 s by default): a second restart inside that window
# leaves no live server, and nginx answers every request 502 "no live upstreams" until the window
# ends (a 12 s run with restarts 4 s apart against a service that drops requests at SIGTERM: 160 000
# such 502s), which measures nginx's passive health check, not the restart. While each instance stops, bench/readyz_watch.py polls its /readyz
# directly every 50 ms on fresh connections, from the SIGTERM to its exit: does a health checker
# see 503 before the port refuses connections, and for how long.
# Counted at the client: total requests, non-2xx answers, socket errors (connect, read, write,
# timeout, from wrk's WRK_RESULT line).
# Goal (the issue's "done when"): with the proxies' DEFAULT retry settings, 0 non-2xx answers and
# 0 socket errors in every run (--runs 2: twice in a row) through each proxy, every instance exits
# 0 after SIGTERM, and the watcher sees /readyz 503 before the port closes.
#
# Proxies, configs generated into a temp dir:
#   nginx    upstream of both instances with `keepalive 32`, proxy_http_version 1.1,
#            proxy_set_header Connection "", default proxy_next_upstream (error timeout: a POST
#            is not resent); run as nginx -p DIR -c DIR/nginx.conf -e DIR/error.log (foreground)
#   haproxy  option httpchk GET /readyz, http-check expect status 200, check inter 1s fall 2
#            rise 2, default http-reuse, retries and retry-on; run as haproxy -db -f DIR/haproxy.cfg
#   --lossless-settings adds what the issue names as making restarts lossless (every endpoint is
#            a pure calculation, so a resend is safe): nginx proxy_next_upstream error timeout
#            http_502 http_503 non_idempotent; haproxy retry-on conn-failure empty-response and
#            option redispatch.
#
# usage: bench/restart_check.sh [--binary PATH] [--proxy nginx|haproxy|both] [--duration S]
#                               [--runs N] [--server-args "ARGS"] [--lossless-settings]
#                               [--a-at S] [--b-at S] [--client-cpu N] [--min-503-ms MS]
#                               [--strict]
#   env: CUTCALC_BIN, RESTART_CHECK_DURATION, RESTART_CHECK_RUNS (flags win)
#   --binary       default build/release/service/cutcalc, started as
#                  cutcalc --host 127.0.0.1 --port P --log-level warn ARGS
#   --proxy        default both (nginx, then haproxy)
#   --duration     seconds of load per run, default 20 (10..300)
#   --runs         runs per proxy, default 2
#   --a-at, --b-at seconds into the load at which A, then B, get SIGTERM (default duration/5
#                  and duration*3/4; B at least 1 s after A)
#   --server-args  extra flags for both instances, e.g. "--lame-duck-ms 2500"
#   --client-cpu   run wrk under taskset -c N (default: not pinned)
#   --min-503-ms   the 503 phase (first to last 503 the watcher saw) that counts as "seen",
#                  default 100 (3 probes): one 503 at the instant of SIGTERM is a race that a
#                  service closing its port at once can win by luck, not a lame-duck period
#   --strict       exit 3 unless every run of every proxy had 0 non-2xx and 0 socket errors,
#                  every instance exited 0 and every watcher saw a 503 before the port closed
# Output: a table on stdout and PASS/FAIL lines; wrk's output, the configs, the proxy and server
# logs and the watchers' output under bench/results/restart-<timestamp>/ (gitignored). Every
# process is started and stopped here; nothing is left running, also on Ctrl-C.
# Example: bench/restart_check.sh --strict          (2 proxies x 2 runs x 20 s, about 2 minutes)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BENCH_NAME=restart_check
# shellcheck source=bench/lib/processes.sh
source "$ROOT/bench/lib/processes.sh"
# shellcheck source=bench/scenarios.sh
source "$ROOT/bench/scenarios.sh"

CUTCALC_BIN="${CUTCALC_BIN:-$ROOT/build/release/service/cutcalc}"
DURATION="${RESTART_CHECK_DURATION:-20}"
RUNS="${RESTART_CHECK_RUNS:-2}"
PROXY=both
SERVER_ARGS=""
LOSSLESS=0
CLIENT_CPU=""
A_AT=""
B_AT=""
STRICT=0
CONNS=32
MIN_503_MS=100
SCENARIO=groove-wall

die() { echo "restart_check: $*" >&2; exit 2; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --binary) CUTCALC_BIN="$2"; shift 2 ;;
    --proxy) PROXY="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    --runs) RUNS="$2"; shift 2 ;;
    --server-args) SERVER_ARGS="$2"; shift 2 ;;
    --lossless-settings) LOSSLESS=1; shift ;;
    --client-cpu) CLIENT_CPU="$2"; shift 2 ;;
    --a-at) A_AT="$2"; shift 2 ;;
    --b-at) B_AT="$2"; shift 2 ;;
    --min-503-ms) MIN_503_MS="$2"; shift 2 ;;
    --strict) STRICT=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d'; exit 0 ;;
    *) die "unknown argument: $1 (see --help)" ;;
  esac
done

case "$PROXY" in
  nginx|haproxy) PROXIES=("$PROXY") ;;
  both) PROXIES=(nginx haproxy) ;;
  *) die "--proxy must be nginx, haproxy or both" ;;
esac
[[ "$DURATION" =~ ^[0-9]+$ && "$DURATION" -ge 10 && "$DURATION" -le 300 ]] || die "--duration must be 10..300 s"
[[ "$RUNS" =~ ^[0-9]+$ && "$RUNS" -ge 1 && "$RUNS" -le 20 ]] || die "--runs must be 1..20"
[[ "$MIN_503_MS" =~ ^[0-9]+$ ]] || die "--min-503-ms must be a number of milliseconds"
[[ -z "$CLIENT_CPU" || "$CLIENT_CPU" =~ ^[0-9]+$ ]] || die "--client-cpu must be a CPU number"
A_AT="${A_AT:-$((DURATION / 5))}"
B_AT="${B_AT:-$((DURATION * 3 / 4))}"
[[ "$A_AT" =~ ^[0-9]+$ && "$B_AT" =~ ^[0-9]+$ && "$A_AT" -ge 1 && "$B_AT" -gt "$A_AT" && "$B_AT" -lt "$DURATION" ]] ||
  die "--a-at and --b-at must satisfy 1 <= a-at < b-at < duration"
if ((B_AT - A_AT <= 10)); then
  echo "restart_check: warning: B's restart is within nginx's fail_timeout (10 s) of A's (see --help)" >&2
fi
[[ -x "$CUTCALC_BIN" ]] || die "cutcalc binary not found: $CUTCALC_BIN (--binary PATH)"
for tool in wrk curl python3; do
  command -v "$tool" >/dev/null || die "$tool is required"
done
NGINX_BIN="$(command -v nginx || echo /usr/sbin/nginx)"
HAPROXY_BIN="$(command -v haproxy || echo /usr/sbin/haproxy)"
for p in "${PROXIES[@]}"; do
  if [[ $p == nginx ]]; then [[ -x "$NGINX_BIN" ]] || die "nginx not found (Debian: nginx-light)"; fi
  if [[ $p == haproxy ]]; then [[ -x "$HAPROXY_BIN" ]] || die "haproxy not found (Debian: haproxy)"; fi
done
[[ -z "$CLIENT_CPU" ]] || command -v taskset >/dev/null || die "taskset is required for --client-cpu"
PYTHON=/usr/bin/python3
[[ -x "$PYTHON" ]] || PYTHON="$(command -v python3)"
read -r -a EXTRA_ARGS <<<"$SERVER_ARGS"

PATH_URL="${SCENARIO_PATH[$SCENARIO]}"
BODY="${SCENARIO_BODY[$SCENARIO]}"

STAMP="$(date -u +%Y%m%dT%H%M%SZ)"
RESULTS="$ROOT/bench/results/restart-$STAMP"
mkdir -p "$RESULTS"
RUNDIR="$(mktemp -d /tmp/restart_check.XXXXXX)"
chmod 755 "$RUNDIR"  # nginx workers run as nobody
declare -A INSTANCE_PID=() INSTANCE_PORT=()
PROXY_PID=""
WRK_PID=""
WATCH_PID=""

# shellcheck disable=SC2317 # run from the EXIT trap
cleanup() {
  local status=$? name
  trap - EXIT INT TERM
  [[ -n "$WATCH_PID" ]] && stop_pid "$WATCH_PID"
  [[ -n "$WRK_PID" ]] && stop_pid "$WRK_PID"
  [[ -n "$PROXY_PID" ]] && stop_pid "$PROXY_PID"
  for name in "${!INSTANCE_PID[@]}"; do
    [[ -n "${INSTANCE_PID[$name]}" ]] && stop_pid "${INSTANCE_PID[$name]}"
  done
  rm -rf "$RUNDIR"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

free_port() {
  "$PYTHON" -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'
}

now_ms() { echo $(( $(date +%s%N) / 1000000 )); }

# Waits until URL answers 200 (GET, or POST with the benchmark body when $2 = post); 15 s at most.
wait_200() {
  local url="$1" kind="${2:-get}" i code
  for ((i = 0; i < 150; i++)); do
    if [[ $kind == post ]]; then
      code="$(curl -s -o /dev/null -w '%{http_code}' --max-time 1 -H 'Content-Type: application/json' \
        --data "$BODY" "$url" || true)"
    else
      code="$(curl -s -o /dev/null -w '%{http_code}' --max-time 1 "$url" || true)"
    fi
    [[ "$code" == 200 ]] && return 0
    sleep 0.1
  done
  return 1
}

start_instance() {  # name log -> INSTANCE_PID[name]; the port is INSTANCE_PORT[name]
  local name="$1" log="$2" port="${INSTANCE_PORT[$1]}"
  "$CUTCALC_BIN" --host 127.0.0.1 --port "$port" --log-level warn "${EXTRA_ARGS[@]}" >>"$log" 2>&1 &
  INSTANCE_PID[$name]=$!
  wait_200 "http://127.0.0.1:$port/healthz" || { tail -5 "$log" >&2; die "instance $name did not answer /healthz on port $port"; }
}

write_nginx_conf() {  # dir port
  local dir="$1" port="$2" next="error timeout"
  [[ $LOSSLESS -eq 1 ]] && next="error timeout http_502 http_503 non_idempotent"
  mkdir -p "$dir"
  chmod 755 "$dir"
  cat >"$dir/nginx.conf" <<EOF
daemon off;
master_process on;
worker_processes 1;
pid $dir/nginx.pid;
error_log $dir/error.log warn;
events { worker_connections 4096; }
http {
  access_log off;
  client_body_temp_path $dir/client_body;
  proxy_temp_path $dir/proxy;
  fastcgi_temp_path $dir/fastcgi;
  uwsgi_temp_path $dir/uwsgi;
  scgi_temp_path $dir/scgi;
  upstream cutcalc {
    server 127.0.0.1:${INSTANCE_PORT[A]};
    server 127.0.0.1:${INSTANCE_PORT[B]};
    keepalive 32;
  }
  server {
    listen 127.0.0.1:$port backlog=1024;
    location / {
      proxy_pass http://cutcalc;
      proxy_http_version 1.1;
      proxy_set_header Connection "";
      proxy_next_upstream $next;
    }
  }
}
EOF
}

write_haproxy_cfg() {  # dir port
  local dir="$1" port="$2" extra=""
  [[ $LOSSLESS -eq 1 ]] && extra=$'  retry-on conn-failure empty-response\n  option redispatch'
  mkdir -p "$dir"
  cat >"$dir/haproxy.cfg" <<EOF
global
  maxconn 4096
defaults
  mode http
  timeout connect 5s
  timeout client 30s
  timeout server 30s
frontend fe
  bind 127.0.0.1:$port
  default_backend cutcalc
backend cutcalc
  balance roundrobin
  option httpchk GET /readyz
  http-check expect status 200
$extra
  server a 127.0.0.1:${INSTANCE_PORT[A]} check inter 1s fall 2 rise 2
  server b 127.0.0.1:${INSTANCE_PORT[B]} check inter 1s fall 2 rise 2
EOF
}

# SIGTERM to instance NAME (sent by the watcher, which then polls /readyz until the process has
# exited), its exit code and stop time, then a restart on the same port. Appends to $REPORT_LINE.
restart_instance() {  # name tag
  local name="$1" tag="$2" pid="${INSTANCE_PID[$1]}" port="${INSTANCE_PORT[$1]}" t0 t1 t2 rc=0 watch
  watch="$RESULTS/$tag-watch-$name.txt"
  t0="$(now_ms)"
  "$PYTHON" "$ROOT/bench/readyz_watch.py" "$pid" "$port" >"$watch" 2>&1 &
  WATCH_PID=$!
  wait "$pid" || rc=$?
  t1="$(now_ms)"
  INSTANCE_PID[$name]=""
  wait "$WATCH_PID" || true
  WATCH_PID=""
  t0="$(awk '/^SIGTERM_AT_MS / {print $2; exit}' "$watch")"
  [[ -n "$t0" ]] || die "the /readyz watcher did not send SIGTERM to $name: $(cat "$watch")"
  start_instance "$name" "$RESULTS/$tag-server-$name.log"
  t2="$(now_ms)"
  EXIT_CODE[$name]=$rc
  STOP_MS[$name]=$((t1 - t0))
  BACK_MS[$name]=$((t2 - t1))
}

declare -A EXIT_CODE=() STOP_MS=() BACK_MS=()
SUMMARY="$RESULTS/summary.tsv"
printf 'proxy\trun\trequests\tnon2xx\tconnect\tread\twrite\ttimeout\tA_exit\tA_stop_ms\tA_saw503\tA_503_ms\tB_exit\tB_stop_ms\tB_saw503\tB_503_ms\n' >"$SUMMARY"
{
  echo "date: $STAMP"
  echo "host: $(uname -srm), $(nproc) cores, load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "git: $(git -C "$ROOT" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
  echo "cutcalc: $CUTCALC_BIN (built $(date -u -r "$CUTCALC_BIN" +%FT%TZ)) --log-level warn $SERVER_ARGS"
  echo "proxies: ${PROXIES[*]} ($("$NGINX_BIN" -v 2>&1 | sed 's/^nginx version: //'); $("$HAPROXY_BIN" -v | head -1 | cut -d' ' -f1-3)), $([[ $LOSSLESS -eq 1 ]] && echo "lossless settings (--lossless-settings)" || echo "default retry settings")"
  echo "load: wrk -t2 -c$CONNS -d${DURATION}s POST $PATH_URL$([[ -n "$CLIENT_CPU" ]] && echo " (taskset -c $CLIENT_CPU)"); SIGTERM to A at ${A_AT} s, to B at ${B_AT} s; $RUNS run(s) per proxy"
} | tee "$RESULTS/meta.txt" >&2

WRK_CMD=(wrk)
[[ -n "$CLIENT_CPU" ]] && WRK_CMD=(taskset -c "$CLIENT_CPU" wrk)

for proxy in "${PROXIES[@]}"; do
  for ((run = 1; run <= RUNS; run++)); do
    tag="$proxy-$run"
    INSTANCE_PORT[A]="$(free_port)"
    INSTANCE_PORT[B]="$(free_port)"
    start_instance A "$RESULTS/$tag-server-A.log"
    start_instance B "$RESULTS/$tag-server-B.log"
    port="$(free_port)"
    dir="$RUNDIR/$tag"
    if [[ $proxy == nginx ]]; then
      write_nginx_conf "$dir" "$port"
      cp "$dir/nginx.conf" "$RESULTS/$tag-nginx.conf"
      "$NGINX_BIN" -p "$dir/" -c "$dir/nginx.conf" -e "$dir/error.log" >"$dir/stdout.log" 2>&1 &
    else
      write_haproxy_cfg "$dir" "$port"
      cp "$dir/haproxy.cfg" "$RESULTS/$tag-haproxy.cfg"
      "$HAPROXY_BIN" -db -f "$dir/haproxy.cfg" >"$dir/stdout.log" 2>&1 &
    fi
    PROXY_PID=$!
    wait_200 "http://127.0.0.1:$port$PATH_URL" post || { cat "$dir/stdout.log" "$dir/error.log" >&2 2>/dev/null; die "$proxy did not answer 200 on port $port"; }
    # haproxy: both servers through their first health checks before the load starts
    if [[ $proxy == haproxy ]]; then sleep 2; fi

    echo "restart_check: $tag: load for ${DURATION} s through $proxy on port $port (A :${INSTANCE_PORT[A]}, B :${INSTANCE_PORT[B]})" >&2
    start="$(now_ms)"
    "${WRK_CMD[@]}" -t2 -c"$CONNS" -d"${DURATION}s" --timeout 5s -s "$ROOT/bench/wrk_post.lua" \
      "http://127.0.0.1:$port$PATH_URL" -- "$BODY" >"$RESULTS/$tag-wrk.txt" 2>&1 &
    WRK_PID=$!
    for name in A B; do
      at=$A_AT
      [[ $name == B ]] && at=$B_AT
      delay_ms=$((start + at * 1000 - $(now_ms)))
      if ((delay_ms > 0)); then sleep "$((delay_ms / 1000)).$(printf '%03d' $((delay_ms % 1000)))"; fi
      restart_instance "$name" "$tag"
      echo "restart_check: $tag: $name exited $((EXIT_CODE[$name])) ${STOP_MS[$name]} ms after SIGTERM, back in ${BACK_MS[$name]} ms; /readyz after SIGTERM: $(tail -1 "$RESULTS/$tag-watch-$name.txt")" >&2
    done
    wait "$WRK_PID" || true
    WRK_PID=""
    stop_pid "$PROXY_PID"
    PROXY_PID=""
    if [[ -f "$dir/error.log" ]]; then
      cp "$dir/error.log" "$RESULTS/$tag-proxy-error.log"
      echo "restart_check: $tag: nginx's error log: $(grep -c 'no live upstreams' "$dir/error.log" || true) x 'no live upstreams', $(grep '\[error\]' "$dir/error.log" | grep -vc 'no live upstreams' || true) other errors" >&2
    fi
    cp "$dir/stdout.log" "$RESULTS/$tag-proxy-stdout.log"
    for name in A B; do
      stop_pid "${INSTANCE_PID[$name]}"
      INSTANCE_PID[$name]=""
    done

    "$PYTHON" - "$RESULTS/$tag-wrk.txt" "$RESULTS/$tag-watch-A.txt" "$RESULTS/$tag-watch-B.txt" \
      "$proxy" "$run" "${EXIT_CODE[A]}" "${STOP_MS[A]}" "${EXIT_CODE[B]}" "${STOP_MS[B]}" "$MIN_503_MS" >>"$SUMMARY" <<'PY'
import json, sys
wrk_file, watch_a, watch_b, proxy, run, a_rc, a_ms, b_rc, b_ms, min_503_ms = sys.argv[1:]
min_503_ms = int(min_503_ms)
res = None
for line in open(wrk_file):
    if line.startswith("WRK_RESULT "):
        res = json.loads(line[len("WRK_RESULT "):])
def watch(path):
    for line in open(path):
        if line.startswith("WATCH "):
            w = json.loads(line[len("WATCH "):])
            w["seen"] = w["saw_503_before_refused"] and w["phase_503_ms"] >= min_503_ms
            w["phase"] = "no 503" if w["phase_503_ms"] is None else f'{w["phase_503_ms"]} ms'
            return w
    return {"seen": False, "phase": "no watcher output"}
wa, wb = watch(watch_a), watch(watch_b)
if res is None:
    res = {k: -1 for k in ("requests", "non2xx", "connect", "read", "write", "timeout")}
yn = lambda w: "yes" if w["seen"] else "no"
print("\t".join(str(x) for x in (proxy, run, res["requests"], res["non2xx"], res["connect"], res["read"],
      res["write"], res["timeout"], a_rc, a_ms, yn(wa), wa["phase"], b_rc, b_ms, yn(wb), wb["phase"])))
PY
    tail -1 "$SUMMARY" | awk -F'\t' '{printf "restart_check: %s run %s: %s requests, %s non-2xx, socket errors connect %s read %s write %s timeout %s\n", $1, $2, $3, $4, $5, $6, $7, $8}' >&2
  done
done

# --- report ------------------------------------------------------------------------------------
cat "$RESULTS/meta.txt"
echo
verdict=0
"$PYTHON" - "$SUMMARY" "$MIN_503_MS" <<'PY' >"$RESULTS/summary.md" || verdict=$?
import csv, sys
min_503_ms = int(sys.argv[2])
rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
print("| proxy | run | requests | non-2xx | socket errors (c/r/w/t) | A exit, stop | A /readyz 503 before close (503 phase) | B exit, stop | B /readyz 503 before close (503 phase) |")
print("|---|---|---|---|---|---|---|---|---|")
ok_all = True
by_proxy = {}
for r in rows:
    sock = sum(int(r[k]) for k in ("connect", "read", "write", "timeout"))
    p = by_proxy.setdefault(r["proxy"], {"runs": 0, "clean": 0, "stops": 0, "exit0": 0, "seen": 0})
    p["runs"] += 1
    p["clean"] += int(int(r["requests"]) > 0 and r["non2xx"] == "0" and sock == 0)
    p["stops"] += 2
    p["exit0"] += (r["A_exit"] == "0") + (r["B_exit"] == "0")
    p["seen"] += (r["A_saw503"] == "yes") + (r["B_saw503"] == "yes")
    print(f"| {r['proxy']} | {r['run']} | {r['requests']} | {r['non2xx']} | {sock} "
          f"({r['connect']}/{r['read']}/{r['write']}/{r['timeout']}) | {r['A_exit']}, {r['A_stop_ms']} ms | "
          f"{r['A_saw503']} ({r['A_503_ms']}) | {r['B_exit']}, {r['B_stop_ms']} ms | {r['B_saw503']} ({r['B_503_ms']}) |")
print()
for proxy, p in by_proxy.items():
    ok = p["clean"] == p["runs"] and p["exit0"] == p["stops"] and p["seen"] == p["stops"]
    ok_all &= ok
    print(f"{'PASS' if ok else 'FAIL'}: {proxy}: 0 non-2xx and 0 socket errors in {p['clean']} of {p['runs']} runs; "
          f"exit 0 after SIGTERM in {p['exit0']} of {p['stops']} stops; /readyz 503 for >= {min_503_ms} ms "
          f"before the port closed in {p['seen']} of {p['stops']} stops")
sys.exit(0 if ok_all else 1)
PY
cat "$RESULTS/summary.md"
echo "results: $RESULTS" >&2
if [[ $STRICT -eq 1 && $verdict -ne 0 ]]; then exit 3; fi
exit 0
