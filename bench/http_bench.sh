#!/usr/bin/env bash
# HTTP benchmark: wrk on loopback against POST /v1/entry-length of cutcalc and, alternating in
# the same run, against three peers answering the same request:
#   echo   bench/peers/httplib_echo (bare cpp-httplib echo, cutcalc's flags and HTTP tuning)
#   nginx  bench/peers/nginx.conf.template (fixed JSON, worker_processes = cores)
#   node   bench/peers/node_echo.js (Node.js http echo, one process)
# Each round runs every (connections, target) pair once, for --duration seconds, with the target
# order rotated from round to round; the table reports medians over the rounds.
# --endpoints adds a second table: every endpoint, one request each (the first case expecting 200
# in the reference cases; the polygon endpoint once as JSON and once with Accept: text/plain; the
# GET endpoints too, compared with nginx only, as the echoes answer POST only), at
# --endpoint-conns connections, each request sent to the peers as well (bench/requests.lua).
#
# usage: bench/http_bench.sh [--cutcalc PATH] [--echo PATH] [--rounds N] [--duration S]
#                            [--threads N] [--conns "1 8 64 256"] [--strict]
#                            [--endpoints | --endpoints-only] [--endpoint-conns "64"]
#                            [--reference DIR]
#   env: CUTCALC_BIN, HTTPLIB_ECHO_BIN, HTTP_BENCH_ROUNDS, HTTP_BENCH_DURATION,
#        HTTP_BENCH_THREADS, HTTP_BENCH_CONNS, HTTP_BENCH_ENDPOINT_CONNS, CUTCALC_REFERENCE_DIR
#        (flags win)
#   --cutcalc   default build/release/service/cutcalc, started as
#               cutcalc --host 127.0.0.1 --port P --threads N --log-level warn
#   --echo      default build/release/bench/peers/httplib_echo
#   --threads   cutcalc's and the echo's --threads (event-loop threads), default the core count
#   --strict    exit 3 if a goal fails
#   --endpoints       also the per-endpoint table; --endpoints-only: only that table
#   --endpoint-conns  connections for the per-endpoint table, default 64
#   --reference       reference cases, default ../shared/reference beside the repo
# Output: Markdown tables and PASS/FAIL lines on stdout; raw wrk output, results.jsonl and
# summary.md under bench/results/<timestamp>/ (gitignored). Every server is started and stopped
# here; nothing is left running, also on Ctrl-C.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CUTCALC_BIN="${CUTCALC_BIN:-$ROOT/build/release/service/cutcalc}"
ECHO_BIN="${HTTPLIB_ECHO_BIN:-$ROOT/build/release/bench/peers/httplib_echo}"
ROUNDS="${HTTP_BENCH_ROUNDS:-3}"
DURATION="${HTTP_BENCH_DURATION:-5}"
THREADS="${HTTP_BENCH_THREADS:-$(nproc)}"
CONNS="${HTTP_BENCH_CONNS:-1 8 64 256}"
ENDPOINT_CONNS="${HTTP_BENCH_ENDPOINT_CONNS:-64}"
REFERENCE="${CUTCALC_REFERENCE_DIR:-$ROOT/../shared/reference}"
MAIN_TABLE=1
ENDPOINT_TABLE=0
STRICT=0
WRK_THREADS=2
PATH_UNDER_TEST="/v1/entry-length"
BODY='{"cutter_diameter_mm": 20, "offset_mm": 0, "entry": {"contour": "straight", "width_mm": 60, "angle_deg": 90}}'

die() { echo "http_bench: $*" >&2; exit 2; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --cutcalc) CUTCALC_BIN="$2"; shift 2 ;;
    --echo) ECHO_BIN="$2"; shift 2 ;;
    --rounds) ROUNDS="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    --threads) THREADS="$2"; shift 2 ;;
    --conns) CONNS="$2"; shift 2 ;;
    --strict) STRICT=1; shift ;;
    --endpoints) ENDPOINT_TABLE=1; shift ;;
    --endpoints-only) ENDPOINT_TABLE=1; MAIN_TABLE=0; shift ;;
    --endpoint-conns) ENDPOINT_CONNS="$2"; shift 2 ;;
    --reference) REFERENCE="$2"; shift 2 ;;
    -h|--help) sed -n '2,36p' "$0"; exit 0 ;;
    *) die "unknown argument: $1 (see --help)" ;;
  esac
done

[[ "$ROUNDS" =~ ^[0-9]+$ && "$ROUNDS" -ge 1 && "$ROUNDS" -le 20 ]] || die "--rounds must be 1..20"
[[ "$DURATION" =~ ^[0-9]+$ && "$DURATION" -ge 1 && "$DURATION" -le 60 ]] || die "--duration must be 1..60 s"
[[ "$THREADS" =~ ^[0-9]+$ && "$THREADS" -ge 1 ]] || die "--threads must be a positive integer"
for c in $CONNS $ENDPOINT_CONNS; do
  [[ "$c" =~ ^[0-9]+$ && "$c" -ge 1 && "$c" -le 1000 ]] || die "connection counts must be 1..1000"
done
if [[ $ENDPOINT_TABLE -eq 1 ]]; then
  [[ -d "$REFERENCE" ]] || die "reference cases not found: $REFERENCE (--reference DIR)"
fi
[[ -x "$CUTCALC_BIN" ]] || die "cutcalc binary not found: $CUTCALC_BIN (cmake --preset release && cmake --build --preset release)"
[[ -x "$ECHO_BIN" ]] || die "httplib_echo binary not found: $ECHO_BIN"
for tool in wrk nginx node curl python3; do
  command -v "$tool" >/dev/null || [[ -x "/usr/sbin/$tool" ]] || die "$tool is required (Debian: apt-get install $tool)"
done
NGINX_BIN="$(command -v nginx || echo /usr/sbin/nginx)"
CORES="$(nproc)"

STAMP="$(date -u +%Y%m%dT%H%M%SZ)"
RESULTS="$ROOT/bench/results/$STAMP"
mkdir -p "$RESULTS/raw"
RUNDIR="$(mktemp -d /tmp/http_bench.XXXXXX)"
chmod 755 "$RUNDIR"  # nginx workers run as nobody

declare -A PIDS=()  # target -> server pid
declare -A PORTS=()
WRK_PID=""

descendants() {  # pids of every descendant of $1
  local child
  for child in $(cat /proc/"$1"/task/*/children 2>/dev/null); do
    echo "$child"
    descendants "$child"
  done
}

stop_pid() {  # TERM, wait up to 5 s, then KILL the process and anything it started
  local pid="$1" kids i
  kill -0 "$pid" 2>/dev/null || { wait "$pid" 2>/dev/null || true; return 0; }
  kids="$(descendants "$pid")"
  kill -TERM "$pid" 2>/dev/null || true
  for ((i = 0; i < 50; i++)); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$pid" 2>/dev/null; then
    echo "http_bench: pid $pid ignored SIGTERM; killing it" >&2
    kill -KILL "$pid" 2>/dev/null || true
  fi
  wait "$pid" 2>/dev/null || true
  for i in $kids; do kill -KILL "$i" 2>/dev/null || true; done
}

cleanup() {
  local status=$?
  trap - EXIT INT TERM
  [[ -n "$WRK_PID" ]] && stop_pid "$WRK_PID"
  local target
  for target in "${!PIDS[@]}"; do
    stop_pid "${PIDS[$target]}"
    cp "$RUNDIR/$target.log" "$RESULTS/raw/server_$target.log" 2>/dev/null || true
  done
  [[ -f "$RUNDIR/nginx/error.log" ]] && cp "$RUNDIR/nginx/error.log" "$RESULTS/raw/nginx_error.log"
  rm -rf "$RUNDIR"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'
}

wait_ready() {  # target: until POST answers 200, the process dies, or 15 s pass
  local target="$1" i
  for ((i = 0; i < 150; i++)); do
    kill -0 "${PIDS[$target]}" 2>/dev/null || { cat "$RUNDIR/$target.log" >&2; die "$target exited at start"; }
    if [[ "$(curl -s -o /dev/null -w '%{http_code}' --max-time 1 -X POST -H 'Content-Type: application/json' \
            --data "$BODY" "http://127.0.0.1:${PORTS[$target]}$PATH_UNDER_TEST" || true)" == 200 ]]; then
      return 0
    fi
    sleep 0.1
  done
  cat "$RUNDIR/$target.log" >&2
  die "$target did not answer 200 on port ${PORTS[$target]} within 15 s"
}

start_target() {  # target command... ; the argument @PORT@ is replaced by a free port
  local target="$1" port arg
  shift
  port="$(free_port)"
  local cmd=()
  for arg in "$@"; do cmd+=("${arg//@PORT@/$port}"); done
  PORTS[$target]="$port"
  "${cmd[@]}" >"$RUNDIR/$target.log" 2>&1 &
  PIDS[$target]=$!
  wait_ready "$target"
}

# --- servers ---------------------------------------------------------------------------------
start_target cutcalc "$CUTCALC_BIN" --host 127.0.0.1 --port @PORT@ --threads "$THREADS" --log-level warn
start_target echo "$ECHO_BIN" --host 127.0.0.1 --port @PORT@ --threads "$THREADS"
mkdir -p "$RUNDIR/nginx"
NGINX_PORT="$(free_port)"
sed -e "s|@PORT@|$NGINX_PORT|g" -e "s|@RUNDIR@|$RUNDIR/nginx|g" -e "s|@WORKERS@|$CORES|g" \
  "$ROOT/bench/peers/nginx.conf.template" >"$RUNDIR/nginx/nginx.conf"
PORTS[nginx]="$NGINX_PORT"
"$NGINX_BIN" -p "$RUNDIR/nginx/" -c "$RUNDIR/nginx/nginx.conf" -e "$RUNDIR/nginx/error.log" \
  >"$RUNDIR/nginx.log" 2>&1 &
PIDS[nginx]=$!
wait_ready nginx
start_target node node "$ROOT/bench/peers/node_echo.js" @PORT@ 127.0.0.1

TARGETS=(cutcalc echo nginx node)

# --- per-endpoint requests (--endpoints) -------------------------------------------------------
# $RESULTS/requests/<case>.tsv: one request in bench/requests.lua's format; ENDPOINT_CASES lists
# "<case> <kind>" with kind post (all targets) or get (cutcalc and nginx).
ENDPOINT_CASES=()
if [[ $ENDPOINT_TABLE -eq 1 ]]; then
  mkdir -p "$RESULTS/requests"
  python3 - "$REFERENCE" "$RESULTS/requests" "${PORTS[cutcalc]}" >"$RESULTS/endpoint_cases.txt" <<'PY' \
    || die "could not prepare the per-endpoint requests (see above)"
import glob, http.client, json, os, sys

reference, out_dir, port = sys.argv[1], sys.argv[2], int(sys.argv[3])
cases = []  # (name, kind, method, path, accept, body)
for path in sorted(glob.glob(os.path.join(reference, "*.json"))):
    doc = json.load(open(path))
    endpoint = doc["endpoint"]
    # The pass program is measured on the spec's worked example (2 x 3 passes).
    preferred = {"/v1/main-time/program": "prog-P-WORKED"}.get(endpoint)
    first = next((c for c in doc["cases"] if c.get("expect", {}).get("status") == 200
                  and (preferred is None or c.get("id") == preferred)), None)
    if first is None:
        sys.exit(f"http_bench: no case expecting 200 in {path}")
    body = json.dumps(first["request"], separators=(",", ":"))
    name = endpoint.removeprefix("/v1/").replace("/", "-")
    if endpoint in ("/v1/polygon-hole/gcode", "/v1/main-time/program"):  # a text form too
        cases.append((name + ".json", "post", "POST", endpoint, "-", body))
        cases.append((name + ".text", "post", "POST", endpoint, "text/plain", body))
    else:
        cases.append((name, "post", "POST", endpoint, "-", body))
for endpoint in ("/healthz", "/readyz", "/version", "/metrics", "/openapi.yaml"):
    cases.append(("GET" + endpoint, "get", "GET", endpoint, "-", ""))
bad = 0
for name, kind, method, path, accept, body in cases:
    headers = {"Content-Type": "application/json"} if method == "POST" else {}
    if accept != "-":
        headers["Accept"] = accept
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    conn.request(method, path, body=body.encode() if method == "POST" else None, headers=headers)
    resp = conn.getresponse()
    answer = resp.read()
    conn.close()
    if resp.status != 200:
        print(f"http_bench: cutcalc answered {method} {path} with {resp.status}: {answer[:200]!r}",
              file=sys.stderr)
        bad += 1
    file_name = name.replace("/", "_")
    with open(os.path.join(out_dir, file_name + ".tsv"), "w") as f:
        f.write(f"{method}\t{path}\t{accept}\t{body}\n")
    print(f"{file_name} {kind} {len(body)} {len(answer)}")
sys.exit(1 if bad else 0)
PY
  while read -r case_name kind _; do ENDPOINT_CASES+=("$case_name $kind"); done <"$RESULTS/endpoint_cases.txt"
fi

{
  echo "date: $STAMP"
  echo "host: $(uname -srm), $CORES cores, load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "git: $(git -C "$ROOT" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)$(git -C "$ROOT" diff --quiet 2>/dev/null || echo ' (dirty)')"
  echo "cutcalc: $CUTCALC_BIN --threads $THREADS (built $(date -u -r "$CUTCALC_BIN" +%FT%TZ))"
  echo "echo: $ECHO_BIN --threads $THREADS (built $(date -u -r "$ECHO_BIN" +%FT%TZ))"
  echo "nginx: $("$NGINX_BIN" -v 2>&1 | sed 's/^nginx version: //'), worker_processes $CORES"
  echo "node: $(node --version), one process"
  echo "wrk: $(wrk -v 2>&1 | head -1 | cut -d' ' -f1-2), $WRK_THREADS threads (1 at 1 connection), ${DURATION} s per run"
  echo "rounds: $ROUNDS"
  [[ $MAIN_TABLE -eq 1 ]] && echo "entry-length table: connections $CONNS; body: $BODY"
  if [[ $ENDPOINT_TABLE -eq 1 ]]; then
    echo "per-endpoint table: $ENDPOINT_CONNS connections; requests from $REFERENCE (first case expecting 200)"
    echo "  case kind request_bytes cutcalc_response_bytes:"
    sed 's/^/    /' "$RESULTS/endpoint_cases.txt"
  fi
  true
} >"$RESULTS/meta.txt"

# --- runs ------------------------------------------------------------------------------------
CLK_TCK="$(getconf CLK_TCK)"
server_cpu_ticks() {  # user+system CPU ticks of a server and its children (nginx workers)
  local pid total=0 ticks
  for pid in "$1" $(descendants "$1"); do
    ticks="$(awk '{print $14 + $15}' "/proc/$pid/stat" 2>/dev/null || echo 0)"
    total=$((total + ticks))
  done
  echo "$total"
}

# target conns round [case] -> appends one JSON line to results.jsonl. Without a case: the
# entry-length benchmark body (bench/wrk_post.lua); with one: $RESULTS/requests/<case>.tsv.
run_wrk() {
  local target="$1" conns="$2" round="$3" case_name="${4:-}" threads raw cpu_before cpu_after
  local script_args=()
  threads=$(( conns < WRK_THREADS ? conns : WRK_THREADS ))
  cpu_before="$(server_cpu_ticks "${PIDS[$target]}")"
  if [[ -z "$case_name" ]]; then
    raw="$RESULTS/raw/${target}_c${conns}_r${round}.txt"
    script_args=(-s "$ROOT/bench/wrk_post.lua" "http://127.0.0.1:${PORTS[$target]}$PATH_UNDER_TEST")
  else
    raw="$RESULTS/raw/${case_name}_${target}_c${conns}_r${round}.txt"
    script_args=(-s "$ROOT/bench/requests.lua" "http://127.0.0.1:${PORTS[$target]}/"
                 -- "$RESULTS/requests/$case_name.tsv")
  fi
  timeout $((DURATION + 20)) wrk -t"$threads" -c"$conns" -d"${DURATION}s" --latency \
    "${script_args[@]}" >"$raw" 2>&1 &
  WRK_PID=$!
  wait "$WRK_PID" || true
  WRK_PID=""
  cpu_after="$(server_cpu_ticks "${PIDS[$target]}")"
  local line cpu_ms case_json=""
  cpu_ms=$(( (cpu_after - cpu_before) * 1000 / CLK_TCK ))
  line="$(grep -m1 '^WRK_RESULT ' "$raw" | cut -d' ' -f2- || true)"
  [[ -n "$line" ]] || line='{"failed":1}'
  [[ -n "$case_name" ]] && case_json="\"case\":\"$case_name\","
  echo "{$case_json\"target\":\"$target\",\"conns\":$conns,\"round\":$round,\"server_cpu_ms\":$cpu_ms,\"wrk\":$line}" >>"$RESULTS/results.jsonl"
  kill -0 "${PIDS[$target]}" 2>/dev/null || die "$target died during the run (see $RESULTS/raw)"
}

echo "http_bench: warming up (1 s per target)" >&2
for target in "${TARGETS[@]}"; do
  wrk -t"$WRK_THREADS" -c64 -d1s -s "$ROOT/bench/wrk_post.lua" \
    "http://127.0.0.1:${PORTS[$target]}$PATH_UNDER_TEST" >/dev/null 2>&1 || true
done

: >"$RESULTS/results.jsonl"
n_targets=${#TARGETS[@]}
for ((round = 1; round <= ROUNDS; round++)); do
  if [[ $MAIN_TABLE -eq 1 ]]; then
    for conns in $CONNS; do
      for ((k = 0; k < n_targets; k++)); do
        target="${TARGETS[$(( (k + round - 1) % n_targets ))]}"
        echo "http_bench: round $round/$ROUNDS, $conns connections, $target" >&2
        run_wrk "$target" "$conns" "$round"
        sleep 0.5
      done
    done
  fi
  for entry in ${ENDPOINT_CASES[@]+"${ENDPOINT_CASES[@]}"}; do
    case_name="${entry% *}"
    kind="${entry#* }"
    if [[ "$kind" == get ]]; then case_targets=(cutcalc nginx); else case_targets=("${TARGETS[@]}"); fi
    n_case=${#case_targets[@]}
    for conns in $ENDPOINT_CONNS; do
      for ((k = 0; k < n_case; k++)); do
        target="${case_targets[$(( (k + round - 1) % n_case ))]}"
        echo "http_bench: round $round/$ROUNDS, $case_name, $conns connections, $target" >&2
        run_wrk "$target" "$conns" "$round" "$case_name"
        sleep 0.5
      done
    done
  done
done
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$RESULTS/meta.txt"

# --- report ----------------------------------------------------------------------------------
set +e
python3 - "$RESULTS" <<'PY'
import json, statistics, sys, os

results_dir = sys.argv[1]
rows = [json.loads(l) for l in open(os.path.join(results_dir, "results.jsonl"))]
targets = ["cutcalc", "echo", "nginx", "node"]
main_rows = [r for r in rows if "case" not in r]
case_rows = [r for r in rows if "case" in r]

def agg(rows, target, conns, case=None):
    picked = [r for r in rows if r["target"] == target and r["conns"] == conns
              and r.get("case") == case]
    if not picked:
        return "absent"
    runs = [r["wrk"] for r in picked]
    ok = [w for w in runs if "failed" not in w]
    if not ok:
        return None
    cpu = [r["server_cpu_ms"] * 1000.0 / r["wrk"]["requests"] for r in picked
           if "failed" not in r["wrk"] and r["wrk"]["requests"] > 0]
    return {
        "cpu_us": statistics.median(cpu) if cpu else float("nan"),
        "rps": statistics.median(w["rps"] for w in ok),
        "rps_min": min(w["rps"] for w in ok),
        "rps_max": max(w["rps"] for w in ok),
        "p50": statistics.median(w["p50_us"] for w in ok) / 1000.0,
        "p99": statistics.median(w["p99_us"] for w in ok) / 1000.0,
        "non2xx": sum(w["non2xx"] for w in ok),
        "sock": sum(w["connect"] + w["read"] + w["write"] + w["timeout"] for w in ok),
        "sock_detail": "/".join(str(sum(w[k] for w in ok)) for k in ("connect", "read", "write", "timeout")),
        "runs": len(ok),
        "failed_runs": len(runs) - len(ok),
    }

def cells(a):
    runs = f"{a['runs']}" + (f" (+{a['failed_runs']} failed)" if a["failed_runs"] else "")
    return (f"{a['rps']:,.0f} ({a['rps_min']:,.0f}-{a['rps_max']:,.0f}) | {a['p50']:.3f} | "
            f"{a['p99']:.3f} | {a['cpu_us']:.1f} | {a['non2xx']} | {a['sock_detail']} | {runs} |")

out = []
verdicts = []
def verdict(ok, text):
    verdicts.append(ok)
    out.append(("PASS " if ok else "FAIL ") + text)

cut_aggs = []  # every cutcalc aggregate, for the error verdict
if main_rows:
    conns_list = sorted({r["conns"] for r in main_rows})
    table = {(t, c): agg(main_rows, t, c) for t in targets for c in conns_list}
    out.append("POST /v1/entry-length:")
    out.append("")
    out.append("| target | conns | req/s median (min-max) | p50 ms | p99 ms | server CPU us/req | non-2xx | socket errors c/r/w/t | runs |")
    out.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for c in conns_list:
        for t in targets:
            a = table[(t, c)]
            if a is None:
                out.append(f"| {t} | {c} | wrk failed | | | | | | 0 |")
            elif a != "absent":
                out.append(f"| {t} | {c} | " + cells(a))
    out.append("")
    for c in conns_list:
        cc, ec = table[("cutcalc", c)], table[("echo", c)]
        if cc and ec and cc != "absent" and ec != "absent":
            verdict(cc["rps"] >= 0.9 * ec["rps"],
                    f"throughput >= 90% of the bare echo at {c} conns: cutcalc {cc['rps']:,.0f} vs echo "
                    f"{ec['rps']:,.0f} req/s ({100.0 * cc['rps'] / ec['rps']:.0f}%)")
    if 64 in conns_list:
        cc, nd = table[("cutcalc", 64)], table[("node", 64)]
        if cc and nd and cc != "absent" and nd != "absent":
            verdict(cc["rps"] >= 2.0 * nd["rps"],
                    f"throughput >= 2x Node's at 64 conns: cutcalc {cc['rps']:,.0f} vs node "
                    f"{nd['rps']:,.0f} req/s ({cc['rps'] / nd['rps']:.2f}x)")
    for c in conns_list:
        cc, ng = table[("cutcalc", c)], table[("nginx", c)]
        if cc and ng and cc != "absent" and ng != "absent":
            verdict(cc["p99"] <= 2.0 * ng["p99"],
                    f"p99 within 2x nginx's at {c} conns: cutcalc {cc['p99']:.3f} ms vs nginx "
                    f"{ng['p99']:.3f} ms ({cc['p99'] / ng['p99']:.2f}x)")
    cut_aggs += [table[("cutcalc", c)] for c in conns_list]

if case_rows:
    cases = list(dict.fromkeys(r["case"] for r in case_rows))
    conns_list = sorted({r["conns"] for r in case_rows})
    if out:
        out.append("")
    out.append("Every endpoint (one request each; the peers get the same request: echo and node "
               "echo its body, nginx answers its fixed JSON):")
    out.append("")
    out.append("| endpoint | target | conns | req/s median (min-max) | p50 ms | p99 ms | server CPU us/req | non-2xx | socket errors c/r/w/t | runs |")
    out.append("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    ratios = []
    for case in cases:
        for c in conns_list:
            per = {t: agg(case_rows, t, c, case) for t in targets}
            for t in targets:
                a = per[t]
                if a is None:
                    out.append(f"| {case} | {t} | {c} | wrk failed | | | | | | 0 |")
                elif a != "absent":
                    out.append(f"| {case} | {t} | {c} | " + cells(a))
            cut_aggs.append(per["cutcalc"])
            cc = per["cutcalc"]
            if cc and cc != "absent":
                parts = []
                for t, label in (("echo", "echo"), ("node", "node")):
                    p = per[t]
                    if p and p != "absent":
                        parts.append(f"{100.0 * cc['rps'] / p['rps']:.0f}% of {label}'s req/s")
                ng = per["nginx"]
                if ng and ng != "absent":
                    parts.append(f"p99 {cc['p99'] / ng['p99']:.2f}x nginx's")
                ratios.append(f"- {case} at {c} conns: cutcalc {cc['rps']:,.0f} req/s, "
                              f"{cc['cpu_us']:.1f} us CPU/req; " + ", ".join(parts))
    out.append("")
    out.extend(ratios)
    out.append("")

errors = sum(a["non2xx"] + a["sock"] for a in cut_aggs if a and a != "absent")
failed = (sum(1 for a in cut_aggs if a is None)
          + sum(a["failed_runs"] for a in cut_aggs if a and a != "absent"))
verdict(errors == 0 and failed == 0,
        f"no errors: cutcalc non-2xx + socket errors = {errors} over all runs"
        + (f", {failed} wrk runs failed" if failed else ""))
out.append("")
out.append("Server CPU us/req: user+system CPU of the server process (and its children) during the "
           "run divided by the requests answered; unlike req/s it hardly depends on what else "
           "the machine runs.")
out.append(f"{'ALL GOALS PASS' if all(verdicts) else 'SOME GOALS FAIL'} "
           f"({sum(verdicts)}/{len(verdicts)}); medians over the rounds; raw results in {results_dir}")

text = "\n".join(out)
meta = open(os.path.join(results_dir, "meta.txt")).read()
with open(os.path.join(results_dir, "summary.md"), "w") as f:
    f.write("# HTTP benchmark\n\n```\n" + meta + "```\n\n" + text + "\n")
print("```\n" + meta + "```\n")
print(text)
sys.exit(0 if all(verdicts) else 3)
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
