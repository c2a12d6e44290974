#!/usr/bin/env bash
# Mixed-load benchmark (issue 23): light requests beside heavy ones. cutcalc on 2 CPUs (taskset
# -c 0,1, --threads 2), every client on CPU 1, as in the issue's measurement:
#   light   wrk -t1, --light-conns (16) keep-alive connections, POST /v1/roughness/groove-wall
#           (path and body from bench/scenarios.sh, bench/wrk_post.lua), for --duration seconds:
#           req/s, p50, p99 (and its share of the light load's req/s alone, same server, same round)
#   heavy   K connections (each K of --heavy, default "1 2"; K = 0 is the light load alone) POSTing
#           the largest polygon program the API allows in a loop (POST /v1/polygon-hole/gcode,
#           Accept: text/plain; bench/mixed_load_clients.py heavy): answers 200 counted, 503s (a full
#           pool's valid answer; Retry-After honoured up to 1 s) apart, other statuses and errors too
#   probe   GET /healthz on a fresh connection every --probe-ms (50) ms during the light run
#           (connect + answer, bench/mixed_load_clients.py probe): worst and p99
# The heavy request (override with --heavy-body): 3 faces and d = 1e6 mm (the largest diameter)
# at the finest tolerance (0.1 um) give the most arc blocks per loop (3223); 62 loops per
# layer x 3223 = 199 826 arc blocks, under the limit of 200 000 (one loop more: 422); c_axis adds a
# C word to every block, fanuc with 6 decimals prints the longest words: about 15.8 MB of program,
# 0.4 s of CPU on main. Before timing, the script checks that it answers 200 and prints its size,
# and whether one loop more is refused (422: the request is at the limit).
# Each round: one fresh server per binary; a 1 s warm-up; K = 0 (alone), then each K of --heavy
# (the heavy clients start 1 s before wrk and stop with it). Two binaries: rounds alternate
# A B, B A, ... (as bench/engine_compare.sh) so that drift of a busy machine falls on both. The
# table reports medians over the rounds per (binary, K); then PASS/FAIL lines for the issue's
# goals at K = 2: light keeps >= 35 % of its alone req/s, p99 <= max(10 ms, 3 x alone p99), the
# /healthz worst <= 50 ms (medians of the rounds' figures).
#
# usage: bench/mixed_load.sh (--binary PATH | --baseline PATH --candidate PATH)
#                            [--rounds N] [--duration S] [--heavy "1 2"] [--light-conns N]
#                            [--threads N] [--server-cpus LIST] [--client-cpu N] [--probe-ms MS]
#                            [--heavy-body JSON] [--strict]
#   --binary        one cutcalc binary; or --baseline (A) and --candidate (B): two, alternating
#                   each started as cutcalc --host 127.0.0.1 --port P --threads N --log-level warn
#   --rounds        default 3; --duration: seconds of each light run, default 10
#   --heavy         heavy connection counts, default "1 2" (the goals need 2)
#   --light-conns   default 16; --threads: cutcalc's --threads, default 2
#   --server-cpus   taskset list for the server, default 0,1; --client-cpu: wrk, heavy clients and
#                   probe, default 1
#   --probe-ms      /healthz probe interval, default 50
#   --strict        exit 3 if a goal fails (the candidate's, or the one binary's)
# Output: Markdown table and PASS/FAIL lines on stdout; meta.txt, raw output, results.jsonl and
# summary.md under bench/results/mixed-<timestamp>/ (gitignored). Every run is bounded in time;
# every server and client started here is stopped on exit, also on Ctrl-C.
# Example (the issue's measurement, about 5 minutes):
#   bench/mixed_load.sh --baseline main/cutcalc --candidate build/release/service/cutcalc
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=bench/scenarios.sh
source "$ROOT/bench/scenarios.sh"
PY=/usr/bin/python3
CLIENTS="$ROOT/bench/mixed_load_clients.py"
LUA="$ROOT/bench/wrk_post.lua"
LIGHT_PATH="${SCENARIO_PATH[groove-wall]}"
LIGHT_BODY="${SCENARIO_BODY[groove-wall]}"
HEAVY_PATH=/v1/polygon-hole/gcode
HEAVY_ACCEPT=text/plain
HEAVY_BODY='{"faces":3,"inscribed_diameter_mm":1000000,"depth_mm":1,"step_down_mm":1,"spindle_speed_rpm":30,"tolerance_mm":0.0001,"loops_per_layer":62,"synchronization":"c_axis","program":{"dialect":"fanuc","decimals":6}}'
BINARY=""
BASELINE=""
CANDIDATE=""
ROUNDS=3
DURATION=10
HEAVY="1 2"
LIGHT_CONNS=16
THREADS=2
SERVER_CPUS=0,1
CLIENT_CPU=1
PROBE_MS=50
STRICT=0

die() { echo "mixed_load: $*" >&2; exit 2; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --binary) BINARY="$2"; shift 2 ;;
    --baseline) BASELINE="$2"; shift 2 ;;
    --candidate) CANDIDATE="$2"; shift 2 ;;
    --rounds) ROUNDS="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    --heavy) HEAVY="$2"; shift 2 ;;
    --light-conns) LIGHT_CONNS="$2"; shift 2 ;;
    --threads) THREADS="$2"; shift 2 ;;
    --server-cpus) SERVER_CPUS="$2"; shift 2 ;;
    --client-cpu) CLIENT_CPU="$2"; shift 2 ;;
    --probe-ms) PROBE_MS="$2"; shift 2 ;;
    --heavy-body) HEAVY_BODY="$2"; shift 2 ;;
    --strict) STRICT=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d'; exit 0 ;;
    *) die "unknown argument: $1 (see --help)" ;;
  esac
done

declare -A BIN=()
if [[ -n "$BINARY" ]]; then
  [[ -z "$BASELINE$CANDIDATE" ]] || die "--binary, or --baseline with --candidate, not both"
  BIN[A]="$BINARY"
  LABELS=(A)
else
  [[ -n "$BASELINE" && -n "$CANDIDATE" ]] || die "need --binary PATH, or --baseline PATH and --candidate PATH"
  BIN[A]="$BASELINE"
  BIN[B]="$CANDIDATE"
  LABELS=(A B)
fi
for label in "${LABELS[@]}"; do
  [[ -x "${BIN[$label]}" ]] || die "not an executable: ${BIN[$label]}"
done
[[ "$ROUNDS" =~ ^[0-9]+$ && "$ROUNDS" -ge 1 && "$ROUNDS" -le 20 ]] || die "--rounds must be 1..20"
[[ "$DURATION" =~ ^[0-9]+$ && "$DURATION" -ge 1 && "$DURATION" -le 120 ]] || die "--duration must be 1..120 s"
for k in $HEAVY; do
  [[ "$k" =~ ^[0-9]+$ && "$k" -ge 1 && "$k" -le 64 ]] || die "--heavy: connection counts 1..64"
done
[[ "$LIGHT_CONNS" =~ ^[0-9]+$ && "$LIGHT_CONNS" -ge 1 && "$LIGHT_CONNS" -le 1000 ]] || die "--light-conns must be 1..1000"
[[ "$THREADS" =~ ^[0-9]+$ && "$THREADS" -ge 1 ]] || die "--threads must be a positive integer"
[[ "$PROBE_MS" =~ ^[0-9]+$ && "$PROBE_MS" -ge 5 ]] || die "--probe-ms must be >= 5"
for tool in wrk curl taskset timeout; do
  command -v "$tool" >/dev/null || die "$tool is required (Debian: apt-get install $tool)"
done
[[ -x "$PY" ]] || die "$PY is required (Debian: python3)"
ALLOWED_CPUS="$("$PY" -c 'import os; print(",".join(str(c) for c in sorted(os.sched_getaffinity(0))))')"
for cpu in ${SERVER_CPUS//,/ } "$CLIENT_CPU"; do
  [[ "$cpu" =~ ^[0-9]+$ && ",$ALLOWED_CPUS," == *",$cpu,"* ]] ||
    die "CPU '$cpu' is not one this process may use ($ALLOWED_CPUS); see --server-cpus/--client-cpu"
done
"$PY" -c 'import json, sys; json.loads(sys.argv[1])' "$HEAVY_BODY" 2>/dev/null || die "--heavy-body is not JSON"

STAMP="$(date -u +%Y%m%dT%H%M%SZ)"
RESULTS="$ROOT/bench/results/mixed-$STAMP"
mkdir -p "$RESULTS/raw"
CLIENT=(taskset -c "$CLIENT_CPU")

SERVER_PID=""
CLIENT_PIDS=()

BENCH_NAME=mixed_load
# shellcheck source=bench/lib/processes.sh
source "$ROOT/bench/lib/processes.sh"

# shellcheck disable=SC2317 # run from the EXIT trap
cleanup() {
  local status=$? pid
  trap - EXIT INT TERM
  for pid in ${CLIENT_PIDS[@]+"${CLIENT_PIDS[@]}"}; do stop_pid "$pid"; done
  [[ -n "$SERVER_PID" ]] && stop_pid "$SERVER_PID"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

free_port() {
  "$PY" -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'
}

start_server() {  # label round -> PORT, SERVER_PID
  local label="$1" round="$2" i log
  log="$RESULTS/raw/server_${label}_r${round}.log"
  PORT="$(free_port)"
  taskset -c "$SERVER_CPUS" "${BIN[$label]}" --host 127.0.0.1 --port "$PORT" --threads "$THREADS" \
    --log-level warn >"$log" 2>&1 &
  SERVER_PID=$!
  for ((i = 0; i < 150; i++)); do
    kill -0 "$SERVER_PID" 2>/dev/null || { cat "$log" >&2; die "${BIN[$label]} exited at start"; }
    if [[ "$(curl -s -o /dev/null -w '%{http_code}' --max-time 1 "http://127.0.0.1:$PORT/healthz" || true)" == 200 ]]; then
      return 0
    fi
    sleep 0.1
  done
  cat "$log" >&2
  die "${BIN[$label]} did not answer /healthz within 15 s"
}

stop_server() {
  stop_pid "$SERVER_PID"
  SERVER_PID=""
}

wait_client() {  # pid: wait for it (each client bounds its own time; timeout bounds it too)
  wait "$1" 2>/dev/null || true
}

# label round K: one light run beside K heavy connections; appends a line to results.jsonl.
run_phase() {
  local label="$1" round="$2" k="$3" i raw prefix wrk_pid probe_pid heavy_pids=()
  prefix="$RESULTS/raw/${label}_r${round}_k${k}"
  for ((i = 1; i <= k; i++)); do
    timeout $((DURATION + 150)) "${CLIENT[@]}" "$PY" "$CLIENTS" heavy "$PORT" "$HEAVY_PATH" "$HEAVY_ACCEPT" \
      "$HEAVY_BODY" $((DURATION + 1)) >"${prefix}_heavy$i.json" 2>"${prefix}_heavy$i.err" &
    heavy_pids+=($!)
    CLIENT_PIDS+=($!)
  done
  [[ $k -eq 0 ]] || sleep 1  # the heavy load established before the light one starts
  timeout $((DURATION + 30)) "${CLIENT[@]}" "$PY" "$CLIENTS" probe "$PORT" "$DURATION" "$PROBE_MS" \
    >"${prefix}_probe.json" 2>"${prefix}_probe.err" &
  probe_pid=$!
  CLIENT_PIDS+=("$probe_pid")
  raw="${prefix}_wrk.txt"
  timeout $((DURATION + 30)) "${CLIENT[@]}" wrk -t1 -c"$LIGHT_CONNS" -d"${DURATION}s" --timeout 10s --latency \
    -s "$LUA" "http://127.0.0.1:$PORT$LIGHT_PATH" -- "$LIGHT_BODY" >"$raw" 2>&1 &
  wrk_pid=$!
  CLIENT_PIDS+=("$wrk_pid")
  wait_client "$wrk_pid"
  wait_client "$probe_pid"
  for i in ${heavy_pids[@]+"${heavy_pids[@]}"}; do wait_client "$i"; done
  CLIENT_PIDS=()
  kill -0 "$SERVER_PID" 2>/dev/null || die "${BIN[$label]} died during the run (see $RESULTS/raw)"
  "$PY" - "$label" "$round" "$k" "$raw" "${prefix}_probe.json" "$prefix" >>"$RESULTS/results.jsonl" <<'PY'
import glob, json, sys
label, rnd, k, raw, probe, prefix = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4], sys.argv[5], sys.argv[6]
def first_json(path, marker=""):
    try:
        for line in open(path):
            if line.startswith(marker):
                return json.loads(line[len(marker):])
    except (OSError, ValueError):
        pass
    return {"missing": 1}
heavy = [first_json(p) for p in sorted(glob.glob(prefix + "_heavy*.json"))]
print(json.dumps({"label": label, "round": rnd, "heavy": k, "wrk": first_json(raw, "WRK_RESULT "),
                  "probe": first_json(probe), "heavy_clients": heavy}))
PY
  echo "mixed_load: ${label} round $round, K=$k: $(tail -1 "$RESULTS/results.jsonl" | cut -c1-220)" >&2
}

run_binary() {  # label round
  local label="$1" round="$2" k
  start_server "$label" "$round"
  "${CLIENT[@]}" wrk -t1 -c"$LIGHT_CONNS" -d1s -s "$LUA" "http://127.0.0.1:$PORT$LIGHT_PATH" -- "$LIGHT_BODY" \
    >/dev/null 2>&1 || true  # warm-up
  if [[ $round -eq 1 ]]; then
    timeout 300 "$PY" "$CLIENTS" check "$PORT" "$HEAVY_PATH" "$HEAVY_ACCEPT" "$HEAVY_BODY" \
      >"$RESULTS/heavy_check_$label.json" ||
      die "${BIN[$label]} does not answer the heavy request with 200: $(cat "$RESULTS/heavy_check_$label.json")"
  fi
  for k in 0 $HEAVY; do
    run_phase "$label" "$round" "$k"
    sleep 0.5
  done
  stop_server
}

{
  echo "date: $STAMP"
  echo "host: $(uname -srm), $(nproc --all) CPUs, this process may use: $ALLOWED_CPUS; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "git: $(git -C "$ROOT" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)$(git -C "$ROOT" diff --quiet 2>/dev/null || echo ' (dirty)')"
  for label in "${LABELS[@]}"; do
    echo "$label: ${BIN[$label]} (built $(date -u -r "${BIN[$label]}" +%FT%TZ)), --threads $THREADS, taskset -c $SERVER_CPUS"
  done
  echo "clients on CPU $CLIENT_CPU: wrk $(wrk -v 2>&1 | head -1 | cut -d' ' -f2) -t1 -c$LIGHT_CONNS ${DURATION} s, POST $LIGHT_PATH $LIGHT_BODY"
  echo "heavy: K in {$HEAVY} connections, POST $HEAVY_PATH, Accept: $HEAVY_ACCEPT, body $HEAVY_BODY"
  echo "probe: GET /healthz on a fresh connection every $PROBE_MS ms"
  echo "rounds: $ROUNDS$([[ ${#LABELS[@]} -eq 2 ]] && echo ', alternating A B, B A, ...')"
} >"$RESULTS/meta.txt"

: >"$RESULTS/results.jsonl"
for ((round = 1; round <= ROUNDS; round++)); do
  if [[ ${#LABELS[@]} -eq 1 ]]; then
    order=(A)
  elif ((round % 2)); then
    order=(A B)
  else
    order=(B A)
  fi
  for label in "${order[@]}"; do
    echo "mixed_load: round $round/$ROUNDS, $label (${BIN[$label]})" >&2
    run_binary "$label" "$round"
  done
done
for label in "${LABELS[@]}"; do
  echo "heavy request check, $label: $(cat "$RESULTS/heavy_check_$label.json")" >>"$RESULTS/meta.txt"
done
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$RESULTS/meta.txt"

# --- report ----------------------------------------------------------------------------------
set +e
"$PY" - "$RESULTS" "$ROUNDS" "${LABELS[*]}" <<'PY'
import json, math, os, statistics, sys

results_dir, rounds, labels = sys.argv[1], int(sys.argv[2]), sys.argv[3].split()
rows = [json.loads(line) for line in open(os.path.join(results_dir, "results.jsonl"))]
meta = open(os.path.join(results_dir, "meta.txt")).read()
names = {"A": "A (baseline)" if len(labels) == 2 else "cutcalc", "B": "B (candidate)"}

def med(values):
    values = [v for v in values if v is not None and not (isinstance(v, float) and math.isnan(v))]
    return statistics.median(values) if values else float("nan")

def wrk_ok(r):
    return "missing" not in r["wrk"]

alone = {(r["label"], r["round"]): r["wrk"]["rps"] for r in rows if r["heavy"] == 0 and wrk_ok(r)}
agg = {}
for label in labels:
    for k in sorted({r["heavy"] for r in rows}):
        picked = [r for r in rows if r["label"] == label and r["heavy"] == k]
        ok = [r for r in picked if wrk_ok(r)]
        probes = [r["probe"] for r in picked if "missing" not in r["probe"]]
        heavy = [h for r in picked for h in r["heavy_clients"]]
        def heavy_sum(r, key):
            return sum(h.get(key, 0) for h in r["heavy_clients"])
        agg[(label, k)] = {
            "runs": len(ok), "failed_runs": len(picked) - len(ok),
            "rps": med(r["wrk"]["rps"] for r in ok),
            "share": med(100.0 * r["wrk"]["rps"] / alone[(label, r["round"])] for r in ok
                         if alone.get((label, r["round"]))),
            "p50": med(r["wrk"]["p50_us"] / 1000.0 for r in ok),
            "p99": med(r["wrk"]["p99_us"] / 1000.0 for r in ok),
            "light_errors": sum(r["wrk"][e] for r in ok for e in ("non2xx", "connect", "read", "write", "timeout")),
            "heavy_ok": med(heavy_sum(r, "ok") for r in picked),
            "heavy_rate": med(heavy_sum(r, "ok") / max(max((h.get("seconds", 0) for h in r["heavy_clients"]), default=0), 1e-9)
                              for r in picked) if k else float("nan"),
            "heavy_503": med(heavy_sum(r, "s503") for r in picked),
            "heavy_other": sum(heavy_sum(r, "other") + heavy_sum(r, "errors") for r in picked)
                           + sum(1 for h in heavy if "missing" in h),
            "hz_max": med(p["max_ms"] for p in probes),
            "hz_max_worst": max((p["max_ms"] for p in probes), default=float("nan")),
            "hz_p99": med(p["p99_ms"] for p in probes),
            "hz_failed": sum(p["failed"] for p in probes) + sum(1 for r in picked if "missing" in r["probe"]),
        }

out = ["| binary | heavy conns | light req/s | share of alone | p50 ms | p99 ms | light errors "
       "| heavy 200 (per s) | heavy 503 | heavy other/errors | /healthz max ms (worst round) "
       "| /healthz p99 ms | probe failures | runs |",
       "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
for (label, k), a in agg.items():
    if k == 0:
        heavy = s503 = other = "-"
    else:
        heavy = f"{a['heavy_ok']:.0f} ({a['heavy_rate']:.1f})"
        s503 = f"{a['heavy_503']:.0f}"
        other = str(a["heavy_other"])
    runs = f"{a['runs']}" + (f" (+{a['failed_runs']} failed)" if a["failed_runs"] else "")
    out.append(f"| {names[label]} | {k} | {a['rps']:,.0f} | {a['share']:.1f} % | {a['p50']:.3f} | "
               f"{a['p99']:.3f} | {a['light_errors']} | {heavy} | {s503} | {other} | "
               f"{a['hz_max']:.1f} ({a['hz_max_worst']:.1f}) | {a['hz_p99']:.1f} | {a['hz_failed']} | {runs} |")
out.append("")

verdicts = {}
goal_lines = []
for label in labels:
    base, two = agg.get((label, 0)), agg.get((label, 2))
    who = names[label]
    if two is None or base is None or two["runs"] == 0 or base["runs"] == 0:
        goal_lines.append(f"NOT RUN {who}: the goals need K = 0 and K = 2 (--heavy \"1 2\")")
        verdicts[label] = [False]
        continue
    p99_limit = max(10.0, 3.0 * base["p99"])
    checks = [
        (two["share"] >= 35.0,
         f"light keeps >= 35 % of its alone req/s under 2 heavy connections: {two['share']:.1f} % "
         f"({two['rps']:,.0f} of {base['rps']:,.0f} req/s)"),
        (two["p99"] <= p99_limit,
         f"light p99 <= max(10 ms, 3 x alone {base['p99']:.3f} ms) = {p99_limit:.1f} ms under 2 heavy "
         f"connections: {two['p99']:.3f} ms"),
        (two["hz_max"] <= 50.0 and two["hz_failed"] == 0,
         f"/healthz on a fresh connection within 50 ms under 2 heavy connections: worst {two['hz_max']:.1f} ms "
         f"(median of the rounds; worst round {two['hz_max_worst']:.1f} ms; {two['hz_failed']} probes failed)"),
        (two["light_errors"] == 0,
         f"no light request failed under 2 heavy connections: {two['light_errors']} non-2xx or socket errors"),
    ]
    verdicts[label] = [ok for ok, _ in checks]
    goal_lines += [("PASS " if ok else "FAIL ") + f"{who}: {text}" for ok, text in checks]
out.append("Goals (issue 23), medians over the rounds:")
out.append("")
out += goal_lines
out.append("")
if len(labels) == 2 and all((l, k) in agg for l in labels for k in (0, 2)):
    a, b = agg[("A", 2)], agg[("B", 2)]
    def ratio(x, y):
        return x / y if y else float("inf")
    out.append(f"B/A under 2 heavy connections: light req/s {ratio(b['rps'], a['rps']):.2f}x, "
               f"p99 {ratio(b['p99'], a['p99']):.2f}x, /healthz worst {ratio(b['hz_max'], a['hz_max']):.2f}x, "
               f"heavy answered {ratio(b['heavy_ok'], a['heavy_ok']):.2f}x.")
    out.append("")
if rounds < 3:
    out.append(f"Note: {rounds} round(s); the goals are stated for medians of >= 3 alternating rounds.")
judged = "B" if len(labels) == 2 else "A"
ok = all(verdicts[judged])
out.append(f"{'ALL GOALS PASS' if ok else 'SOME GOALS FAIL'} for {names[judged]}; raw results in {results_dir}")
text = "\n".join(out)
with open(os.path.join(results_dir, "summary.md"), "w") as f:
    f.write("# Mixed-load benchmark\n\n```\n" + meta + "```\n\n" + text + "\n")
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
