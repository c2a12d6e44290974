#!/usr/bin/env bash
# HTTP benchmark (issue 14): wrk on loopback against cutcalc and, alternating in the same run,
# against four peers answering the same requests, each server on one core:
#   echo     bench/peers/httplib_echo (the engine's bare echo: cutcalc's HTTP engine and tuning)
#   nginx    bench/peers/nginx.conf.template (cutcalc's answer as a fixed JSON)
#   node     bench/peers/node_peer.js (Node.js http, one process, computes the same answers)
#   go       bench/peers/go_peer/ (Go net/http and encoding/json, the standard library only; a port
#            of node_peer.js computing the same answers; built here by Debian's golang-go with
#            GOPROXY=off, GOTOOLCHAIN=local and GOCACHE/GOPATH under build/go_peer/; GOMAXPROCS=1
#            pinned, the CPU count with --no-pin)
#   fastapi  bench/peers/fastapi_peer.py (FastAPI/uvicorn, one worker, computes the same answers;
#            Debian's python3-fastapi and python3-uvicorn, run with /usr/bin/python3)
# Scenarios, stated once here (path and body) and handed to bench/wrk_post.lua:
#   groove-wall   POST /v1/roughness/groove-wall at --conns connections (default 8 64 256)
#   entry-length  POST /v1/entry-length at --entry-conns connections (default 64)
# Pinning (default): every server under taskset -c <server CPU> (cutcalc and the echo with
# --threads 1, nginx worker_processes 1, one Node process, Go with GOMAXPROCS=1, one uvicorn
# worker), wrk -t1 under taskset -c <client CPU>. Before timing, every target's answer to every
# body must be 200, and cutcalc's, nginx's, node's, go's and fastapi's answers must agree
# numerically (1e-12 relative).
# Each round runs every (scenario, connections, target) once, for --duration seconds, with the
# target order rotated from round to round (after a 1 s warm-up per target per scenario); the
# tables report medians over the rounds: req/s, p50, p99, the server's CPU microseconds per
# request (utime + stime of the server process and its children during the run, from /proc,
# divided by the requests answered: the figure that stays stable on a shared machine), non-2xx
# and socket errors; then the ratios and PASS/FAIL lines for the issue's goals.
# --endpoints adds a second table: every endpoint, one request each (the first case expecting 200
# in the reference cases; the polygon and program endpoints once as JSON and once with Accept:
# text/plain; the GET endpoints too, compared with nginx only), at --endpoint-conns connections,
# each request sent to the peers as well (bench/requests.lua): echo answers the body, nginx its
# fixed JSON, node, go and fastapi compute groove-wall and entry-length and echo the rest.
#
# usage: bench/http_bench.sh [--cutcalc PATH] [--echo PATH] [--rounds N] [--duration S]
#                            [--conns "8 64 256"] [--entry-conns "64"]
#                            [--server-cpu N] [--client-cpu N] [--no-pin] [--threads N]
#                            [--fastapi-python PATH] [--go PATH] [--strict]
#                            [--endpoints | --endpoints-only] [--endpoint-conns "64"]
#                            [--reference DIR]
#   env: CUTCALC_BIN, HTTPLIB_ECHO_BIN, HTTP_BENCH_ROUNDS, HTTP_BENCH_DURATION, HTTP_BENCH_CONNS,
#        HTTP_BENCH_ENTRY_CONNS, HTTP_BENCH_SERVER_CPU, HTTP_BENCH_CLIENT_CPU, HTTP_BENCH_THREADS,
#        HTTP_BENCH_ENDPOINT_CONNS, FASTAPI_PYTHON, GO, CUTCALC_REFERENCE_DIR (flags win)
#   --cutcalc     default build/release/service/cutcalc, started as
#                 cutcalc --host 127.0.0.1 --port P --threads N --log-level warn
#   --echo        default build/release/bench/peers/httplib_echo
#   --rounds      default 3 (the goals are judged on medians of >= 3 rounds); --duration default 5
#   --server-cpu  CPU for every server, default 0; --client-cpu: CPU for wrk, default 1
#                 (needs >= 2 CPUs; the two must differ)
#   --no-pin      no taskset: servers may use every CPU (cutcalc's and the echo's --threads and
#                 nginx's workers default to the CPU count), wrk -t2
#   --threads     cutcalc's and the echo's --threads, default 1 (pinned) or the CPU count
#   --fastapi-python  interpreter with fastapi and uvicorn, default /usr/bin/python3
#   --go          the Go toolchain that builds the Go peer, default go on PATH (Debian: golang-go)
#   --strict      exit 3 if a goal fails
#   --endpoints       also the per-endpoint table; --endpoints-only: only that table
#   --endpoint-conns  connections for the per-endpoint table, default 64
#   --reference       reference cases, default ../shared/reference beside the repo
# Output: Markdown tables and PASS/FAIL lines on stdout; meta.txt, raw wrk output, results.jsonl
# and summary.md under bench/results/<timestamp>/ (gitignored). Every server is started and
# stopped here; nothing is left running, also on Ctrl-C.
# Example (the issue's run, about 6 minutes): bench/http_bench.sh --strict
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CUTCALC_BIN="${CUTCALC_BIN:-$ROOT/build/release/service/cutcalc}"
ECHO_BIN="${HTTPLIB_ECHO_BIN:-$ROOT/build/release/bench/peers/httplib_echo}"
ROUNDS="${HTTP_BENCH_ROUNDS:-3}"
DURATION="${HTTP_BENCH_DURATION:-5}"
CONNS="${HTTP_BENCH_CONNS:-8 64 256}"
ENTRY_CONNS="${HTTP_BENCH_ENTRY_CONNS:-64}"
SERVER_CPU="${HTTP_BENCH_SERVER_CPU:-0}"
CLIENT_CPU="${HTTP_BENCH_CLIENT_CPU:-1}"
THREADS="${HTTP_BENCH_THREADS:-}"
ENDPOINT_CONNS="${HTTP_BENCH_ENDPOINT_CONNS:-64}"
FASTAPI_PYTHON="${FASTAPI_PYTHON:-/usr/bin/python3}"
GO="${GO:-go}"
REFERENCE="${CUTCALC_REFERENCE_DIR:-$ROOT/../shared/reference}"
PIN=1
MAIN_TABLE=1
ENDPOINT_TABLE=0
STRICT=0

# The scenarios: name, path, body (wrk_post.lua sends the body; the peers compute the same answer).
# shellcheck source=bench/scenarios.sh
source "$ROOT/bench/scenarios.sh"
TARGETS=(cutcalc echo nginx node go fastapi)

die() { echo "http_bench: $*" >&2; exit 2; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --cutcalc) CUTCALC_BIN="$2"; shift 2 ;;
    --echo) ECHO_BIN="$2"; shift 2 ;;
    --rounds) ROUNDS="$2"; shift 2 ;;
    --duration) DURATION="$2"; shift 2 ;;
    --conns) CONNS="$2"; shift 2 ;;
    --entry-conns) ENTRY_CONNS="$2"; shift 2 ;;
    --server-cpu) SERVER_CPU="$2"; shift 2 ;;
    --client-cpu) CLIENT_CPU="$2"; shift 2 ;;
    --no-pin) PIN=0; shift ;;
    --threads) THREADS="$2"; shift 2 ;;
    --fastapi-python) FASTAPI_PYTHON="$2"; shift 2 ;;
    --go) GO="$2"; shift 2 ;;
    --strict) STRICT=1; shift ;;
    --endpoints) ENDPOINT_TABLE=1; shift ;;
    --endpoints-only) ENDPOINT_TABLE=1; MAIN_TABLE=0; shift ;;
    --endpoint-conns) ENDPOINT_CONNS="$2"; shift 2 ;;
    --reference) REFERENCE="$2"; shift 2 ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d'; exit 0 ;;
    *) die "unknown argument: $1 (see --help)" ;;
  esac
done

[[ "$ROUNDS" =~ ^[0-9]+$ && "$ROUNDS" -ge 1 && "$ROUNDS" -le 20 ]] || die "--rounds must be 1..20"
[[ "$DURATION" =~ ^[0-9]+$ && "$DURATION" -ge 1 && "$DURATION" -le 60 ]] || die "--duration must be 1..60 s"
for c in $CONNS $ENTRY_CONNS $ENDPOINT_CONNS; do
  [[ "$c" =~ ^[0-9]+$ && "$c" -ge 1 && "$c" -le 1000 ]] || die "connection counts must be 1..1000"
done
[[ -n "$CONNS$ENTRY_CONNS" || $MAIN_TABLE -eq 0 ]] || die "--conns and --entry-conns are both empty"
if [[ $ENDPOINT_TABLE -eq 1 ]]; then
  [[ -d "$REFERENCE" ]] || die "reference cases not found: $REFERENCE (--reference DIR)"
fi
[[ -x "$CUTCALC_BIN" ]] || die "cutcalc binary not found: $CUTCALC_BIN (cmake --preset release && cmake --build --preset release)"
[[ -x "$ECHO_BIN" ]] || die "httplib_echo binary not found: $ECHO_BIN"
for tool in wrk nginx node curl python3 taskset; do
  command -v "$tool" >/dev/null || [[ -x "/usr/sbin/$tool" ]] || die "$tool is required (Debian: apt-get install $tool)"
done
NGINX_BIN="$(command -v nginx || echo /usr/sbin/nginx)"
[[ -x "$FASTAPI_PYTHON" ]] || die "no interpreter at $FASTAPI_PYTHON (--fastapi-python PATH); Debian: apt-get install python3-fastapi python3-uvicorn"
"$FASTAPI_PYTHON" -c 'import fastapi, uvicorn, pydantic' 2>/dev/null ||
  die "$FASTAPI_PYTHON cannot import fastapi and uvicorn: apt-get install python3-fastapi python3-uvicorn"
command -v "$GO" >/dev/null || die "no Go toolchain '$GO' (--go PATH); Debian: apt-get install golang-go"

# The CPUs this process may run on (affinity mask), e.g. "0 1".
ALLOWED_CPUS="$(python3 -c 'import os; print(" ".join(str(c) for c in sorted(os.sched_getaffinity(0))))')"
N_CPUS="$(wc -w <<<"$ALLOWED_CPUS")"
if [[ $PIN -eq 1 ]]; then
  [[ "$N_CPUS" -ge 2 ]] ||
    die "needs at least 2 CPUs (the servers on one, wrk on another); this process may use $N_CPUS ($ALLOWED_CPUS)"
  for cpu in "$SERVER_CPU" "$CLIENT_CPU"; do
    [[ "$cpu" =~ ^[0-9]+$ && " $ALLOWED_CPUS " == *" $cpu "* ]] ||
      die "CPU '$cpu' is not one this process may use ($ALLOWED_CPUS); see --server-cpu/--client-cpu"
  done
  [[ "$SERVER_CPU" != "$CLIENT_CPU" ]] || die "--server-cpu and --client-cpu must differ"
  PIN_SERVER=(taskset -c "$SERVER_CPU")
  PIN_CLIENT=(taskset -c "$CLIENT_CPU")
  WRK_THREADS=1
  SERVER_PROCS=1  # nginx worker_processes
  THREADS="${THREADS:-1}"
else
  PIN_SERVER=()
  PIN_CLIENT=()
  WRK_THREADS=2
  SERVER_PROCS="$N_CPUS"
  THREADS="${THREADS:-$N_CPUS}"
fi
[[ "$THREADS" =~ ^[0-9]+$ && "$THREADS" -ge 1 ]] || die "--threads must be a positive integer"

STAMP="$(date -u +%Y%m%dT%H%M%SZ)"
RESULTS="$ROOT/bench/results/$STAMP"
mkdir -p "$RESULTS/raw"
RUNDIR="$(mktemp -d /tmp/http_bench.XXXXXX)"
chmod 755 "$RUNDIR"  # nginx workers run as nobody

declare -A PIDS=()  # target -> server pid
declare -A PORTS=()
WRK_PID=""

BENCH_NAME=http_bench
# shellcheck source=bench/lib/processes.sh
source "$ROOT/bench/lib/processes.sh"

# shellcheck disable=SC2317 # run from the EXIT trap
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

wait_ready() {  # target: until the groove-wall POST answers 200, the process dies, or 15 s pass
  local target="$1" i
  for ((i = 0; i < 150; i++)); do
    kill -0 "${PIDS[$target]}" 2>/dev/null || { cat "$RUNDIR/$target.log" >&2; die "$target exited at start"; }
    if [[ "$(curl -s -o /dev/null -w '%{http_code}' --max-time 1 -X POST -H 'Content-Type: application/json' \
            --data "${SCENARIO_BODY[groove-wall]}" \
            "http://127.0.0.1:${PORTS[$target]}${SCENARIO_PATH[groove-wall]}" || true)" == 200 ]]; then
      return 0
    fi
    sleep 0.1
  done
  cat "$RUNDIR/$target.log" >&2
  die "$target did not answer 200 on port ${PORTS[$target]} within 15 s"
}

start_target() {  # target command... ; @PORT@ is replaced by PORTS[target], else a free port
  local target="$1" port arg
  shift
  port="${PORTS[$target]:-$(free_port)}"
  local cmd=()
  for arg in "$@"; do cmd+=("${arg//@PORT@/$port}"); done
  PORTS[$target]="$port"
  ${PIN_SERVER[@]+"${PIN_SERVER[@]}"} "${cmd[@]}" >"$RUNDIR/$target.log" 2>&1 &
  PIDS[$target]=$!
  wait_ready "$target"
}

# --- the Go peer: built offline (the standard library only, no module download) ---------------
GO_BUILD="$ROOT/build/go_peer"  # the binary, GOCACHE and GOPATH: rebuilt only when main.go changes
GO_PEER_BIN="$GO_BUILD/go_peer"
mkdir -p "$GO_BUILD"
echo "http_bench: building the Go peer with $("$GO" version)" >&2
(cd "$ROOT/bench/peers/go_peer" &&
  env GOCACHE="$GO_BUILD/cache" GOPATH="$GO_BUILD/gopath" GOTOOLCHAIN=local GOPROXY=off GOFLAGS= \
    GOWORK=off GO111MODULE=on GOENV=off CGO_ENABLED=0 \
    timeout 600 "$GO" build -trimpath -o "$GO_PEER_BIN" .) >"$RESULTS/raw/go_build.log" 2>&1 ||
  { cat "$RESULTS/raw/go_build.log" >&2; die "building the Go peer failed (bench/peers/go_peer)"; }

# --- servers (taskset execs the server: the pid is the server's) ------------------------------
start_target cutcalc "$CUTCALC_BIN" --host 127.0.0.1 --port @PORT@ --threads "$THREADS" --log-level warn
start_target echo "$ECHO_BIN" --host 127.0.0.1 --port @PORT@ --threads "$THREADS"
mkdir -p "$RUNDIR/nginx"
PORTS[nginx]="$(free_port)"
sed -e "s|@PORT@|${PORTS[nginx]}|g" -e "s|@RUNDIR@|$RUNDIR/nginx|g" -e "s|@WORKERS@|$SERVER_PROCS|g" \
  "$ROOT/bench/peers/nginx.conf.template" >"$RUNDIR/nginx/nginx.conf"
start_target nginx "$NGINX_BIN" -p "$RUNDIR/nginx/" -c "$RUNDIR/nginx/nginx.conf" -e "$RUNDIR/nginx/error.log"
start_target node node "$ROOT/bench/peers/node_peer.js" @PORT@ 127.0.0.1
start_target go env GOMAXPROCS="$SERVER_PROCS" "$GO_PEER_BIN" @PORT@ 127.0.0.1
start_target fastapi "$FASTAPI_PYTHON" "$ROOT/bench/peers/fastapi_peer.py" @PORT@ 127.0.0.1

# The CPUs each server (and its children: nginx's workers) may use, as the kernel sees them.
affinity_of() {
  local pid out=""
  for pid in "$1" $(descendants "$1"); do
    out+="$(awk '/^Cpus_allowed_list:/ {print $2}' "/proc/$pid/status" 2>/dev/null) "
  done
  echo "$out" | tr ' ' '\n' | sed '/^$/d' | sort -u | paste -sd' '
}
if [[ $PIN -eq 1 ]]; then
  for target in "${TARGETS[@]}"; do
    [[ "$(affinity_of "${PIDS[$target]}")" == "$SERVER_CPU" ]] ||
      die "$target is not pinned to CPU $SERVER_CPU (Cpus_allowed_list: $(affinity_of "${PIDS[$target]}"))"
  done
fi

# --- every target's answer to every benchmark body, before timing ------------------------------
{
  for target in "${TARGETS[@]}"; do printf 'port\t%s\t%s\n' "$target" "${PORTS[$target]}"; done
  for scenario in "${SCENARIOS[@]}"; do
    printf 'scenario\t%s\t%s\t%s\n' "$scenario" "${SCENARIO_PATH[$scenario]}" "${SCENARIO_BODY[$scenario]}"
  done
} >"$RESULTS/answer_check.tsv"
python3 - "$RESULTS/answer_check.tsv" >"$RESULTS/answers.txt" <<'PY' || die "a peer's answer differs from cutcalc's (see above); not timing"
import http.client, json, math, sys

ports, scenarios = {}, []
for line in open(sys.argv[1]):
    fields = line.rstrip("\n").split("\t")
    if fields[0] == "port":
        ports[fields[1]] = int(fields[2])
    else:
        scenarios.append(fields[1:])

def post(port, path, body):
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    conn.request("POST", path, body=body.encode(), headers={"Content-Type": "application/json"})
    resp = conn.getresponse()
    data = resp.read()
    conn.close()
    return resp.status, data

def differences(a, b, where=""):
    """Where b differs from a: numbers within 1e-12 relative, everything else exactly."""
    if isinstance(a, bool) or isinstance(b, bool) or isinstance(a, str) or isinstance(b, str) or a is None:
        return [] if a == b and type(a) is type(b) else [f"{where or '/'}: {a!r} vs {b!r}"]
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        ok = a == b or (math.isfinite(a) and math.isfinite(b)
                        and abs(a - b) <= 1e-12 * max(abs(a), abs(b)))
        return [] if ok else [f"{where}: {a!r} vs {b!r}"]
    if isinstance(a, dict) and isinstance(b, dict):
        if set(a) != set(b):
            return [f"{where or '/'}: fields {sorted(a)} vs {sorted(b)}"]
        return [d for k in a for d in differences(a[k], b[k], f"{where}/{k}")]
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, f"{where}/{i}")]
    return [f"{where or '/'}: {a!r} vs {b!r}"]

bad = 0
for name, path, body in scenarios:
    answers = {t: post(p, path, body) for t, p in ports.items()}
    status, reference = answers["cutcalc"]
    print(f"{name}: POST {path} {body}")
    print(f"  cutcalc {status} {reference.decode()}")
    if status != 200:
        print(f"http_bench: cutcalc answered {name} with {status}: {reference[:300]!r}", file=sys.stderr)
        bad += 1
        continue
    expected = json.loads(reference)
    for target, (status, data) in answers.items():
        if target == "cutcalc":
            continue
        problems = [] if status == 200 else [f"status {status}: {data[:300]!r}"]
        if status == 200:
            if target == "echo":  # a bare echo: the request body itself
                problems += [] if data == body.encode() else [f"echoed {data[:300]!r}"]
            else:
                try:
                    problems += differences(expected, json.loads(data))
                except ValueError as error:
                    problems.append(f"not JSON ({error}): {data[:300]!r}")
        print(f"  {target} {status} {'same' if target != 'echo' else 'echo'}"
              + ("" if not problems else " DIFFERS"))
        for p in problems:
            print(f"http_bench: {target}'s answer to {name} differs from cutcalc's: {p}", file=sys.stderr)
        bad += bool(problems)
sys.exit(1 if bad else 0)
PY

# --- per-endpoint requests (--endpoints) -------------------------------------------------------
# $RESULTS/requests/<case>.tsv: one request in bench/requests.lua's format; ENDPOINT_CASES lists
# "<case> <kind>" with kind post (all targets) or get (cutcalc and nginx).
ENDPOINT_CASES=()
if [[ $ENDPOINT_TABLE -eq 1 ]]; then
  mkdir -p "$RESULTS/requests"
  "$CUTCALC_BIN" --routes >"$RESULTS/routes.json" || die "$CUTCALC_BIN --routes failed"
  python3 - "$REFERENCE" "$RESULTS/requests" "${PORTS[cutcalc]}" "$RESULTS/routes.json" \
    >"$RESULTS/endpoint_cases.txt" <<'PY' \
    || die "could not prepare the per-endpoint requests (see above)"
import glob, http.client, json, os, sys

reference, out_dir, port = sys.argv[1], sys.argv[2], int(sys.argv[3])
routes = json.load(open(sys.argv[4]))  # cutcalc --routes: the route table
text_form = {r["path"] for r in routes if "plain_text" in r["forms"]}
# reference/*.json plus the next/ files the route table lists
files = sorted(glob.glob(os.path.join(reference, "*.json"))) + sorted(
    os.path.join(reference, f) for r in routes for f in r["next_reference_files"])
cases = []  # (name, kind, method, path, accept, body)
for path in files:
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
    if endpoint in text_form:
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

if [[ $MAIN_TABLE -eq 1 ]]; then
  declare -A SCENARIO_CONNS=([groove-wall]="$CONNS" [entry-length]="$ENTRY_CONNS")
else
  declare -A SCENARIO_CONNS=([groove-wall]="" [entry-length]="")
fi

{
  echo "date: $STAMP"
  echo "host: $(uname -srm), $(nproc --all) CPUs, this process may use: $ALLOWED_CPUS; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "git: $(git -C "$ROOT" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)$(git -C "$ROOT" diff --quiet 2>/dev/null || echo ' (dirty)')"
  if [[ $PIN -eq 1 ]]; then
    echo "pinning: every server under taskset -c $SERVER_CPU, wrk -t1 under taskset -c $CLIENT_CPU"
  else
    echo "pinning: none (--no-pin): servers may use CPUs $ALLOWED_CPUS, wrk -t$WRK_THREADS unpinned"
  fi
  for target in "${TARGETS[@]}"; do
    echo "  $target: pid ${PIDS[$target]}, Cpus_allowed_list $(affinity_of "${PIDS[$target]}")"
  done
  echo "cutcalc: $CUTCALC_BIN --threads $THREADS (built $(date -u -r "$CUTCALC_BIN" +%FT%TZ))"
  echo "echo: $ECHO_BIN --threads $THREADS (built $(date -u -r "$ECHO_BIN" +%FT%TZ))"
  echo "nginx: $("$NGINX_BIN" -v 2>&1 | sed 's/^nginx version: //'), worker_processes $SERVER_PROCS"
  echo "node: $(node --version), bench/peers/node_peer.js, one process"
  echo "go: $("$GO" version | sed 's/^go version //'), bench/peers/go_peer, GOMAXPROCS=$SERVER_PROCS"
  echo "fastapi: $("$FASTAPI_PYTHON" - <<'PY'
import importlib.util, platform, fastapi, pydantic, starlette, uvicorn
loop = "uvloop" if importlib.util.find_spec("uvloop") else "asyncio"
http = "httptools" if importlib.util.find_spec("httptools") else "h11"
print(f"FastAPI {fastapi.__version__}, Starlette {starlette.__version__}, pydantic {pydantic.VERSION}, "
      f"uvicorn {uvicorn.__version__} ({loop}, {http}), Python {platform.python_version()}, one worker")
PY
)"
  echo "wrk: $(wrk -v 2>&1 | head -1 | cut -d' ' -f1-2), $WRK_THREADS thread(s) (no more than connections), ${DURATION} s per run, 1 s warm-up per target per scenario"
  echo "rounds: $ROUNDS, target order rotated each round"
  for scenario in "${SCENARIOS[@]}"; do
    [[ -n "${SCENARIO_CONNS[$scenario]}" ]] &&
      echo "$scenario: POST ${SCENARIO_PATH[$scenario]} at connections ${SCENARIO_CONNS[$scenario]}; body ${SCENARIO_BODY[$scenario]}"
  done
  echo "answers checked before timing:"
  sed 's/^/  /' "$RESULTS/answers.txt"
  if [[ $ENDPOINT_TABLE -eq 1 ]]; then
    echo "per-endpoint table: $ENDPOINT_CONNS connections; requests from $REFERENCE (first case expecting 200)"
    echo "  case kind request_bytes cutcalc_response_bytes:"
    sed 's/^/    /' "$RESULTS/endpoint_cases.txt"
  fi
  true
} >"$RESULTS/meta.txt"

# --- runs ------------------------------------------------------------------------------------
CLK_TCK="$(getconf CLK_TCK)"
server_cpu_ticks() {  # utime + stime (+ cutime + cstime of reaped children) of a server and its children
  local pid total=0 ticks
  for pid in "$1" $(descendants "$1"); do
    ticks="$(awk '{print $14 + $15 + $16 + $17}' "/proc/$pid/stat" 2>/dev/null || echo 0)"
    total=$((total + ticks))
  done
  echo "$total"
}

# kind name target conns round -> appends one JSON line to results.jsonl. kind scenario: the
# scenario's path and body (bench/wrk_post.lua); kind case: $RESULTS/requests/<case>.tsv
# (bench/requests.lua).
run_wrk() {
  local kind="$1" name="$2" target="$3" conns="$4" round="$5" threads raw cpu_before cpu_after
  local script_args=()
  threads=$(( conns < WRK_THREADS ? conns : WRK_THREADS ))
  raw="$RESULTS/raw/${name}_${target}_c${conns}_r${round}.txt"
  if [[ "$kind" == scenario ]]; then
    script_args=(-s "$ROOT/bench/wrk_post.lua" "http://127.0.0.1:${PORTS[$target]}${SCENARIO_PATH[$name]}"
                 -- "${SCENARIO_BODY[$name]}")
  else
    script_args=(-s "$ROOT/bench/requests.lua" "http://127.0.0.1:${PORTS[$target]}/"
                 -- "$RESULTS/requests/$name.tsv")
  fi
  cpu_before="$(server_cpu_ticks "${PIDS[$target]}")"
  timeout $((DURATION + 20)) ${PIN_CLIENT[@]+"${PIN_CLIENT[@]}"} \
    wrk -t"$threads" -c"$conns" -d"${DURATION}s" --latency "${script_args[@]}" >"$raw" 2>&1 &
  WRK_PID=$!
  wait "$WRK_PID" || true
  WRK_PID=""
  cpu_after="$(server_cpu_ticks "${PIDS[$target]}")"
  local line cpu_ms
  cpu_ms=$(( (cpu_after - cpu_before) * 1000 / CLK_TCK ))
  line="$(grep -m1 '^WRK_RESULT ' "$raw" | cut -d' ' -f2- || true)"
  [[ -n "$line" ]] || line='{"failed":1}'
  echo "{\"$kind\":\"$name\",\"target\":\"$target\",\"conns\":$conns,\"round\":$round,\"server_cpu_ms\":$cpu_ms,\"wrk\":$line}" >>"$RESULTS/results.jsonl"
  kill -0 "${PIDS[$target]}" 2>/dev/null || die "$target died during the run (see $RESULTS/raw)"
}

max_of() { tr ' ' '\n' <<<"$1" | sed '/^$/d' | sort -n | tail -1; }

echo "http_bench: warming up (1 s per target per scenario)" >&2
for scenario in "${SCENARIOS[@]}"; do
  warm_conns="$(max_of "${SCENARIO_CONNS[$scenario]}")"
  if [[ -z "$warm_conns" ]]; then
    [[ $MAIN_TABLE -eq 0 && "$scenario" == groove-wall ]] || continue
    warm_conns="$(max_of "$ENDPOINT_CONNS")"  # --endpoints-only: one warm-up per target
  fi
  for target in "${TARGETS[@]}"; do
    ${PIN_CLIENT[@]+"${PIN_CLIENT[@]}"} wrk -t"$(( warm_conns < WRK_THREADS ? warm_conns : WRK_THREADS ))" \
      -c"$warm_conns" -d1s -s "$ROOT/bench/wrk_post.lua" \
      "http://127.0.0.1:${PORTS[$target]}${SCENARIO_PATH[$scenario]}" -- "${SCENARIO_BODY[$scenario]}" \
      >/dev/null 2>&1 || true
  done
done

: >"$RESULTS/results.jsonl"
n_targets=${#TARGETS[@]}
for ((round = 1; round <= ROUNDS; round++)); do
  for scenario in "${SCENARIOS[@]}"; do
    for conns in ${SCENARIO_CONNS[$scenario]}; do
      for ((k = 0; k < n_targets; k++)); do
        target="${TARGETS[$(( (k + round - 1) % n_targets ))]}"
        echo "http_bench: round $round/$ROUNDS, $scenario, $conns connections, $target" >&2
        run_wrk scenario "$scenario" "$target" "$conns" "$round"
        sleep 0.5
      done
    done
  done
  for entry in ${ENDPOINT_CASES[@]+"${ENDPOINT_CASES[@]}"}; do
    case_name="${entry% *}"
    kind="${entry#* }"
    if [[ "$kind" == get ]]; then case_targets=(cutcalc nginx); else case_targets=("${TARGETS[@]}"); fi
    n_case=${#case_targets[@]}
    for conns in $ENDPOINT_CONNS; do
      for ((k = 0; k < n_case; k++)); do
        target="${case_targets[$(( (k + round - 1) % n_case ))]}"
        echo "http_bench: round $round/$ROUNDS, $case_name, $conns connections, $target" >&2
        run_wrk case "$case_name" "$target" "$conns" "$round"
        sleep 0.5
      done
    done
  done
done
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$RESULTS/meta.txt"

# --- report ----------------------------------------------------------------------------------
set +e
python3 - "$RESULTS" "$ROUNDS" "${TARGETS[*]}" \
  "$(for s in "${SCENARIOS[@]}"; do printf '%s=%s ' "$s" "${SCENARIO_PATH[$s]}"; done)" <<'PY'
import json, math, os, statistics, sys

results_dir, rounds = sys.argv[1], int(sys.argv[2])
targets = sys.argv[3].split()
scenario_paths = dict(item.split("=", 1) for item in sys.argv[4].split())
rows = [json.loads(l) for l in open(os.path.join(results_dir, "results.jsonl"))]
main_rows = [r for r in rows if "scenario" in r]
case_rows = [r for r in rows if "case" in r]

def agg(rows, key, name, target, conns):
    picked = [r for r in rows if r[key] == name and r["target"] == target and r["conns"] == conns]
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

def usable(a):
    return a is not None and a != "absent"

def cells(a):
    runs = f"{a['runs']}" + (f" (+{a['failed_runs']} failed)" if a["failed_runs"] else "")
    return (f"{a['rps']:,.0f} ({a['rps_min']:,.0f}-{a['rps_max']:,.0f}) | {a['p50']:.3f} | "
            f"{a['p99']:.3f} | {a['cpu_us']:.1f} | {a['non2xx']} | {a['sock_detail']} | {runs} |")

def ratio(a, b):
    return a / b if b else float("inf")

def flag(a):  # a peer whose answers were not 2xx did other work than cutcalc's
    return f" (its {a['non2xx']} non-2xx answers make this no comparison)" if a["non2xx"] else ""

out = []      # the tables, then the goals
goals = []
verdicts = []  # True/False per goal measured
not_run = []
def verdict(ok, text):
    verdicts.append(ok)
    goals.append(("PASS " if ok else "FAIL ") + text)

HEADER = ("| target | req/s median (min-max) | p50 ms | p99 ms | server CPU us/req | non-2xx "
          "| socket errors c/r/w/t | runs |")
cut_aggs = []  # every cutcalc aggregate, for the error goal
table = {}     # (scenario, conns, target) -> aggregate
for scenario in scenario_paths:
    for c in sorted({r["conns"] for r in main_rows if r["scenario"] == scenario}):
        per = {t: agg(main_rows, "scenario", scenario, t, c) for t in targets}
        out.append(f"### POST {scenario_paths[scenario]}, {c} connections")
        out.append("")
        out.append(HEADER)
        out.append("|---|---:|---:|---:|---:|---:|---:|---:|")
        for t in targets:
            a = per[t]
            table[(scenario, c, t)] = a
            if a is None:
                out.append(f"| {t} | wrk failed | | | | | | 0 |")
            elif a != "absent":
                out.append(f"| {t} | " + cells(a))
        out.append("")
        cc = per["cutcalc"]
        cut_aggs.append(cc)
        if usable(cc):
            parts = []
            for t in ("go", "node", "fastapi"):
                if usable(per[t]):
                    parts.append(f"cutcalc/{t} {ratio(cc['rps'], per[t]['rps']):.2f}x req/s "
                                 f"({t} needs {ratio(per[t]['cpu_us'], cc['cpu_us']):.2f}x cutcalc's "
                                 f"CPU per request){flag(per[t])}")
            if usable(per["echo"]):
                parts.append(f"cutcalc/echo {100.0 * ratio(cc['rps'], per['echo']['rps']):.0f}% req/s"
                             + flag(per["echo"]))
            if usable(per["nginx"]):
                parts.append(f"p99 cutcalc/nginx {ratio(cc['p99'], per['nginx']['p99']):.2f}x"
                             + flag(per["nginx"]))
            out.append("Ratios: " + "; ".join(parts) + ".")
            out.append("")

def goal(scenario, c, other, text, check):
    cc, ot = table.get((scenario, c, "cutcalc")), table.get((scenario, c, other))
    if not (usable(cc) and usable(ot)):
        not_run.append(text)
        goals.append(f"NOT RUN {text} ({scenario} at {c} connections not measured)")
        return
    ok, detail = check(cc, ot)
    verdict(ok, f"{text}: {detail}")

if main_rows:
    for scenario in ("groove-wall", "entry-length"):
        goal(scenario, 64, "node", f"cutcalc >= 1.3x Node on {scenario} at 64 connections, one core each",
             lambda cc, nd: (cc["rps"] >= 1.3 * nd["rps"],
                             f"cutcalc {cc['rps']:,.0f} vs node {nd['rps']:,.0f} req/s "
                             f"({ratio(cc['rps'], nd['rps']):.2f}x)"))
    for scenario in ("groove-wall", "entry-length"):
        goal(scenario, 64, "echo", f"cutcalc >= 85 % of the engine's echo on {scenario} at 64 connections",
             lambda cc, ec: (cc["rps"] >= 0.85 * ec["rps"],
                             f"cutcalc {cc['rps']:,.0f} vs echo {ec['rps']:,.0f} req/s "
                             f"({100.0 * ratio(cc['rps'], ec['rps']):.0f}%)"))
    for scenario in ("groove-wall", "entry-length"):  # informative: not a verdict of this script
        cc, gp = table.get((scenario, 64, "cutcalc")), table.get((scenario, 64, "go"))
        if usable(cc) and usable(gp):
            goals.append(f"INFO issue 23's target cutcalc >= 1.6x Go net/http on {scenario} at 64 "
                         f"connections, one core each: {ratio(cc['rps'], gp['rps']):.2f}x req/s, "
                         f"Go needs {ratio(gp['cpu_us'], cc['cpu_us']):.2f}x cutcalc's CPU per request")
    for c in (8, 64, 256):
        goal("groove-wall", c, "nginx", f"p99 within 2x nginx's on groove-wall at {c} connections",
             lambda cc, ng: (cc["p99"] <= 2.0 * ng["p99"],
                             f"cutcalc {cc['p99']:.3f} ms vs nginx {ng['p99']:.3f} ms "
                             f"({ratio(cc['p99'], ng['p99']):.2f}x)"))

if case_rows:
    cases = list(dict.fromkeys(r["case"] for r in case_rows))
    conns_list = sorted({r["conns"] for r in case_rows})
    out.append("### Every endpoint (one request each)")
    out.append("")
    out.append("The peers get the same request: echo answers the body, nginx its fixed JSON, node, go "
               "and fastapi compute groove-wall and entry-length (straight entry, no exit: 422 on a case "
               "with an exit) and echo the rest.")
    out.append("")
    out.append("| endpoint | target | conns | req/s median (min-max) | p50 ms | p99 ms | server CPU us/req | non-2xx | socket errors c/r/w/t | runs |")
    out.append("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    ratios = []
    for case in cases:
        for c in conns_list:
            per = {t: agg(case_rows, "case", case, t, c) for t in targets}
            for t in targets:
                a = per[t]
                if a is None:
                    out.append(f"| {case} | {t} | {c} | wrk failed | | | | | | 0 |")
                elif a != "absent":
                    out.append(f"| {case} | {t} | {c} | " + cells(a))
            cut_aggs.append(per["cutcalc"])
            cc = per["cutcalc"]
            if usable(cc):
                parts = [f"{100.0 * ratio(cc['rps'], per[t]['rps']):.0f}% of {t}'s req/s{flag(per[t])}"
                         for t in ("echo", "node", "go", "fastapi") if usable(per[t])]
                if usable(per["nginx"]):
                    parts.append(f"p99 {ratio(cc['p99'], per['nginx']['p99']):.2f}x nginx's")
                ratios.append(f"- {case} at {c} conns: cutcalc {cc['rps']:,.0f} req/s, "
                              f"{cc['cpu_us']:.1f} us CPU/req; " + ", ".join(parts))
    out.append("")
    out.extend(ratios)
    out.append("")

errors = sum(a["non2xx"] + a["sock"] for a in cut_aggs if usable(a))
runs = sum(a["runs"] for a in cut_aggs if usable(a))
failed = (sum(1 for a in cut_aggs if a is None)
          + sum(a["failed_runs"] for a in cut_aggs if usable(a)))
verdict(errors == 0 and failed == 0,
        f"zero errors: cutcalc non-2xx + socket errors = {errors} over all {runs} runs"
        + (f", {failed} wrk runs failed" if failed else ""))
out.append("Goals (issue 14):")
out.append("")
out.extend(goals)
out.append("")
if rounds < 3:
    out.append(f"Note: {rounds} round(s); the goals are stated for medians of >= 3 alternating rounds.")
out.append("Server CPU us/req: utime + stime of the server process and its children during the run "
           "divided by the requests answered; unlike req/s it hardly depends on what else the "
           "machine runs.")
summary = "ALL GOALS PASS" if all(verdicts) else "SOME GOALS FAIL"
out.append(f"{summary} ({sum(verdicts)}/{len(verdicts)} pass"
           + (f", {len(not_run)} not run" if not_run else "")
           + f"); medians over the rounds; raw results in {results_dir}")

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
