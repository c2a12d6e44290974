#!/usr/bin/env bash
# Soak test: wrk drives a mix of every endpoint of cutcalc on loopback for a long time while the
# server's resident memory (VmRSS in /proc/PID/status) is sampled every --interval seconds.
# Goals: RSS growth under 5 % and zero errors (non-2xx answers or socket errors).
#
# usage: bench/soak.sh [--cutcalc PATH] [--duration S] [--conns N] [--threads N]
#                      [--interval S] [--reference DIR] [--strict]
#   env: CUTCALC_BIN, SOAK_DURATION, SOAK_CONNS, SOAK_THREADS, SOAK_INTERVAL,
#        CUTCALC_REFERENCE_DIR (flags win)
#   --cutcalc    default build/release/service/cutcalc (built with `cmake --preset release &&
#                cmake --build --preset release --target cutcalc` if missing), started as
#                cutcalc --host 127.0.0.1 --port P --threads N --log-level warn
#   --duration   seconds of load, default 1800 (30 min)
#   --conns      wrk connections, default 64 (wrk runs 2 threads)
#   --threads    cutcalc's --threads (event-loop threads), default the core count
#   --interval   RSS sampling period in seconds, default 10
#   --reference  reference cases, default ../shared/reference beside the repo: every case that
#                expects 200 becomes a request of the mix (the polygon endpoint once as JSON and
#                once with Accept: text/plain), plus GET /healthz, /readyz and /version
#   --strict     exit 3 if a goal fails
# Growth is measured from the first sample taken under load (t = interval) to the mean of the
# last three samples; the idle RSS before the load (t = 0) is reported too.
# Output: a summary on stdout; rss.csv (t_s,rss_kb,threads,fds), the request mix, wrk's output,
# the server log and /metrics at the end under bench/results/soak-<timestamp>/ (gitignored).
# Every process is started and stopped here; nothing is left running, also on Ctrl-C.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CUTCALC_BIN="${CUTCALC_BIN:-$ROOT/build/release/service/cutcalc}"
DURATION="${SOAK_DURATION:-1800}"
CONNS="${SOAK_CONNS:-64}"
THREADS="${SOAK_THREADS:-$(nproc)}"
INTERVAL="${SOAK_INTERVAL:-10}"
REFERENCE="${CUTCALC_REFERENCE_DIR:-$ROOT/../shared/reference}"
STRICT=0
WRK_THREADS=2

die() { echo "soak: $*" >&2; exit 2; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --cutcalc) CUTCALC_BIN="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    --conns) CONNS="$2"; shift 2 ;;
    --threads) THREADS="$2"; shift 2 ;;
    --interval) INTERVAL="$2"; shift 2 ;;
    --reference) REFERENCE="$2"; shift 2 ;;
    --strict) STRICT=1; shift ;;
    -h|--help) sed -n '2,25p' "$0"; exit 0 ;;
    *) die "unknown argument: $1 (see --help)" ;;
  esac
done

[[ "$DURATION" =~ ^[0-9]+$ && "$DURATION" -ge 10 && "$DURATION" -le 86400 ]] || die "--duration must be 10..86400 s"
[[ "$CONNS" =~ ^[0-9]+$ && "$CONNS" -ge 1 && "$CONNS" -le 1000 ]] || die "--conns must be 1..1000"
[[ "$THREADS" =~ ^[0-9]+$ && "$THREADS" -ge 1 ]] || die "--threads must be a positive integer"
[[ "$INTERVAL" =~ ^[0-9]+$ && "$INTERVAL" -ge 1 && "$INTERVAL" -le 600 ]] || die "--interval must be 1..600 s"
[[ -d "$REFERENCE" ]] || die "reference cases not found: $REFERENCE (--reference DIR)"
for tool in wrk curl python3; do
  command -v "$tool" >/dev/null || die "$tool is required (Debian: apt-get install $tool)"
done
if [[ ! -x "$CUTCALC_BIN" && "$CUTCALC_BIN" == "$ROOT/build/release/service/cutcalc" ]]; then
  echo "soak: building $CUTCALC_BIN" >&2
  (cd "$ROOT" && cmake --preset release >/dev/null && cmake --build --preset release --target cutcalc -j2 >/dev/null)
fi
[[ -x "$CUTCALC_BIN" ]] || die "cutcalc binary not found: $CUTCALC_BIN"

STAMP="$(date -u +%Y%m%dT%H%M%SZ)"
RESULTS="$ROOT/bench/results/soak-$STAMP"
mkdir -p "$RESULTS"
RUNDIR="$(mktemp -d /tmp/soak.XXXXXX)"
SERVER_PID=""
WRK_PID=""

stop_pid() {  # TERM, wait up to 10 s, then KILL
  local pid="$1" i
  kill -0 "$pid" 2>/dev/null || { wait "$pid" 2>/dev/null || true; return 0; }
  kill -TERM "$pid" 2>/dev/null || true
  for ((i = 0; i < 100; i++)); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$pid" 2>/dev/null; then
    echo "soak: pid $pid ignored SIGTERM; killing it" >&2
    kill -KILL "$pid" 2>/dev/null || true
  fi
  wait "$pid" 2>/dev/null || true
}

cleanup() {
  local status=$?
  trap - EXIT INT TERM
  [[ -n "$WRK_PID" ]] && stop_pid "$WRK_PID"
  [[ -n "$SERVER_PID" ]] && stop_pid "$SERVER_PID"
  cp "$RUNDIR/server.log" "$RESULTS/server.log" 2>/dev/null || true
  rm -rf "$RUNDIR"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# --- the request mix ---------------------------------------------------------------------------
"$CUTCALC_BIN" --routes >"$RESULTS/routes.json" || die "$CUTCALC_BIN --routes failed"
python3 - "$REFERENCE" "$RESULTS/routes.json" >"$RESULTS/requests.tsv" <<'PY'
import glob, json, os, sys

lines = []
# reference/*.json plus the next/ files the route table (cutcalc --routes) lists
files = sorted(glob.glob(os.path.join(sys.argv[1], "*.json"))) + sorted(
    os.path.join(sys.argv[1], f) for r in json.load(open(sys.argv[2])) for f in r["next_reference_files"])
for path in files:
    doc = json.load(open(path))
    endpoint = doc["endpoint"]
    for case in doc["cases"]:
        if case.get("expect", {}).get("status") != 200:
            continue
        body = json.dumps(case["request"], separators=(",", ":"))
        lines.append(f"POST\t{endpoint}\t-\t{body}")
        if endpoint == "/v1/polygon-hole/gcode":
            lines.append(f"POST\t{endpoint}\ttext/plain\t{body}")
if not lines:
    sys.exit("soak: no 200 cases found in " + sys.argv[1])
for path in ("/healthz", "/readyz", "/version"):
    lines.append(f"GET\t{path}\t-\t")
print("\n".join(lines))
PY
N_REQUESTS="$(wc -l <"$RESULTS/requests.tsv")"

# --- server ------------------------------------------------------------------------------------
PORT="$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()')"
"$CUTCALC_BIN" --host 127.0.0.1 --port "$PORT" --threads "$THREADS" --log-level warn \
  >"$RUNDIR/server.log" 2>&1 &
SERVER_PID=$!
ready=0
for ((i = 0; i < 150; i++)); do
  kill -0 "$SERVER_PID" 2>/dev/null || { cat "$RUNDIR/server.log" >&2; die "cutcalc exited at start"; }
  if [[ "$(curl -s -o /dev/null -w '%{http_code}' --max-time 1 "http://127.0.0.1:$PORT/healthz" || true)" == 200 ]]; then
    ready=1
    break
  fi
  sleep 0.1
done
[[ $ready -eq 1 ]] || die "cutcalc did not answer /healthz within 15 s"

# Every request of the mix must answer 2xx before the soak starts (else the error count is moot).
python3 - "$RESULTS/requests.tsv" "$PORT" <<'PY' || die "a request of the mix does not answer 2xx"
import http.client, sys
port = int(sys.argv[2])
bad = 0
for line in open(sys.argv[1]):
    method, path, accept, body = line.rstrip("\n").split("\t", 3)
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    headers = {"Content-Type": "application/json"} if method == "POST" else {}
    if accept != "-":
        headers["Accept"] = accept
    conn.request(method, path, body=body.encode() if method == "POST" else None, headers=headers)
    resp = conn.getresponse()
    resp.read()
    if not 200 <= resp.status < 300:
        print(f"soak: {method} {path} -> {resp.status}: {body[:120]}", file=sys.stderr)
        bad += 1
    conn.close()
sys.exit(1 if bad else 0)
PY

{
  echo "date: $STAMP"
  echo "host: $(uname -srm), $(nproc) cores, load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "git: $(git -C "$ROOT" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)$(git -C "$ROOT" diff --quiet 2>/dev/null || echo ' (dirty)')"
  echo "cutcalc: $CUTCALC_BIN --threads $THREADS (built $(date -u -r "$CUTCALC_BIN" +%FT%TZ)), pid $SERVER_PID"
  echo "wrk: $WRK_THREADS threads, $CONNS connections, ${DURATION} s; mix of $N_REQUESTS requests from $REFERENCE"
} >"$RESULTS/meta.txt"
cat "$RESULTS/meta.txt" >&2

# --- load and sampling -------------------------------------------------------------------------
sample() {  # t -> one CSV line
  local t="$1" rss threads fds
  rss="$(awk '/^VmRSS:/ {print $2}' "/proc/$SERVER_PID/status" 2>/dev/null || echo)"
  threads="$(awk '/^Threads:/ {print $2}' "/proc/$SERVER_PID/status" 2>/dev/null || echo)"
  fds="$(ls "/proc/$SERVER_PID/fd" 2>/dev/null | wc -l)"
  echo "$t,$rss,$threads,$fds" >>"$RESULTS/rss.csv"
}
echo "t_s,rss_kb,threads,fds" >"$RESULTS/rss.csv"
sample 0

timeout $((DURATION + 60)) wrk -t"$WRK_THREADS" -c"$CONNS" -d"${DURATION}s" --timeout 5s --latency \
  -s "$ROOT/bench/requests.lua" "http://127.0.0.1:$PORT" -- "$RESULTS/requests.tsv" \
  >"$RESULTS/wrk.txt" 2>&1 &
WRK_PID=$!
START=$(date +%s)
next=$INTERVAL
while kill -0 "$WRK_PID" 2>/dev/null; do
  now=$(( $(date +%s) - START ))
  if [[ $now -ge $next ]]; then
    kill -0 "$SERVER_PID" 2>/dev/null || break
    sample "$now"
    if (( next % 300 == 0 )); then
      echo "soak: ${now} s, RSS $(tail -1 "$RESULTS/rss.csv" | cut -d, -f2) kB" >&2
    fi
    next=$(( next + INTERVAL ))
  fi
  sleep 0.5
done
wrk_status=0
wait "$WRK_PID" || wrk_status=$?
WRK_PID=""
kill -0 "$SERVER_PID" 2>/dev/null || die "cutcalc died during the soak (see $RESULTS/server.log)"
sample "$(( $(date +%s) - START ))"
curl -s --max-time 5 "http://127.0.0.1:$PORT/metrics" >"$RESULTS/metrics.txt" || true
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$RESULTS/meta.txt"
[[ $wrk_status -eq 0 ]] || echo "soak: wrk exited with $wrk_status" >&2

# --- report ------------------------------------------------------------------------------------
set +e
python3 - "$RESULTS" "$DURATION" <<'PY'
import csv, json, os, sys

results, duration = sys.argv[1], int(sys.argv[2])
rows = [r for r in csv.DictReader(open(os.path.join(results, "rss.csv"))) if r["rss_kb"]]
rss = [(int(r["t_s"]), int(r["rss_kb"])) for r in rows]
wrk = None
for line in open(os.path.join(results, "wrk.txt")):
    if line.startswith("WRK_RESULT "):
        wrk = json.loads(line.split(" ", 1)[1])
out = []
ok = True
idle = rss[0][1]
loaded = [kb for t, kb in rss if t > 0]
if len(loaded) >= 2:
    first = loaded[0]
    last = sum(loaded[-3:]) / len(loaded[-3:])
    growth = 100.0 * (last - first) / first
    out.append(f"RSS kB: idle {idle}, first under load {first}, last {loaded[-1]} "
               f"(mean of last 3: {last:.0f}), max {max(loaded)}, min {min(loaded)}; "
               f"{len(rss)} samples")
    out.append(f"RSS growth (first under load -> mean of last 3): {growth:+.2f} %")
    g_ok = growth < 5.0
    out.append(("PASS " if g_ok else "FAIL ") + "RSS growth under 5 %")
    ok &= g_ok
else:
    out.append("FAIL too few RSS samples")
    ok = False
threads = [int(r["threads"]) for r in rows if r["threads"]]
fds = [int(r["fds"]) for r in rows if r["fds"]]
if threads and fds:
    out.append(f"threads: first {threads[0]}, last {threads[-1]}, max {max(threads)}; "
               f"open fds: first {fds[0]}, last {fds[-1]}, max {max(fds)}")
if wrk is None:
    out.append("FAIL wrk printed no result (see wrk.txt)")
    ok = False
else:
    errors = wrk["non2xx"] + wrk["connect"] + wrk["read"] + wrk["write"] + wrk["timeout"]
    out.append(f"requests: {wrk['requests']:,} in {wrk['duration_us'] / 1e6:.0f} s "
               f"({wrk['rps']:,.0f} req/s), p50 {wrk['p50_us'] / 1000:.3f} ms, "
               f"p99 {wrk['p99_us'] / 1000:.3f} ms, max {wrk['max_us'] / 1000:.1f} ms")
    out.append(f"errors: {errors} (non-2xx {wrk['non2xx']}, socket connect/read/write/timeout "
               f"{wrk['connect']}/{wrk['read']}/{wrk['write']}/{wrk['timeout']})")
    e_ok = errors == 0 and wrk["requests"] > 0
    out.append(("PASS " if e_ok else "FAIL ") + "zero errors")
    ok &= e_ok
out.append(f"{'SOAK PASS' if ok else 'SOAK FAIL'}; raw data in {results}")
text = "\n".join(out)
meta = open(os.path.join(results, "meta.txt")).read()
with open(os.path.join(results, "summary.md"), "w") as f:
    f.write("# Soak\n\n```\n" + meta + "```\n\n" + text + "\n")
print("```\n" + meta + "```\n")
print(text)
sys.exit(0 if ok else 3)
PY
report_status=$?
set -e
if [[ $report_status -ne 0 && $report_status -ne 3 ]]; then
  die "report failed"
fi
if [[ $STRICT -eq 1 && $report_status -eq 3 ]]; then
  exit 3
fi
exit 0
