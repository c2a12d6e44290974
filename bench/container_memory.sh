#!/usr/bin/env bash
# Memory attacks on the container image (a benchmark, not a CI test): runs the image in a podman
# container limited to 256 MiB (--memory=256m --memory-swap=256m: no swap either) and attacks it
# with bench/memory_attack.py (/usr/bin/python3, stdlib only):
#   never-read  200 connections (over --spread s, held --hold s) ask for the largest polygon
#               program (15.8 MB of text) and never read it; /healthz is timed meanwhile
#   slow-read   100 connections ask for it and read at --rate bytes/s
#   upload      50 connections, all opened first, send at once the largest body
#               POST /v1/program-time takes (the route's max_body_bytes from `cutcalc --routes`
#               in the image: 32 MiB; a valid LinuxCNC program of G1 moves), reading as they send
# After each attack: whether the service was OOM-killed (podman's State.OOMKilled, the cgroup's
# oom_kill count and the kernel log's "Killed process PID": with podman 4.3 + runc on a cgroup v1
# host, OOMKilled stays false when the kernel kills the service), whether the container still runs
# (and its exit code if not: 137 is SIGKILL), and GET /healthz. One summary line per attack and
# a final PASS/FAIL line: PASS when no container was OOM-killed or stopped, /healthz answered 200
# after every attack, and no accepted request was lost (every request sent got a complete answer:
# 200, 413, or 503 with Retry-After; a reset, a close, a truncated answer or no answer within
# --answer-timeout is lost).
#
# The memory figures: the service's VmRSS (sampled every 100 ms) and VmHWM from /proc/PID/status
# with PID the container's host-side PID (podman inspect .State.Pid; readable as root, and for
# rootless podman by the same user), and its cgroup's memory (v2 memory.current / memory.peak, or
# on a cgroup v1 host the memory controller's memory.usage_in_bytes / memory.max_usage_in_bytes,
# what the 256 MiB limit is enforced on; it is below VmRSS there: shared file pages are charged
# elsewhere), the cgroup's OOM kills.
#
# Each attack gets a fresh container by default (so the peaks, VmHWM and any OOM kill are that
# attack's own); --shared runs all of them, one after the other, in one container. Containers are
# started without --rm: an OOM-killed container would be removed before its State.OOMKilled could
# be read. The EXIT trap removes every container this script started, also on Ctrl-C.
#
# usage: bench/container_memory.sh [--image IMG] [--memory 256m] [--attacks LIST] [--shared]
#                                  [--spread S] [--hold S] [--rate B] [--answer-timeout S]
#                                  [--cpus N] [--server-args "ARGS"] [--strict]
#   --image           default localhost/cutcalc:ci (never pulled, never built here)
#   --memory          the container's memory limit, swap included, default 256m
#   --attacks         comma-separated, default never-read,slow-read,upload
#   --shared          one container for all the attacks
#   --spread, --hold  never-read: seconds to open the 200 connections over (default 10), and to
#                     hold them after (default 10)
#   --rate            slow-read: bytes/s each reader reads (default 262144: a 15.8 MB answer
#                     takes 60 s; memory_attack.py's own default 65536 takes 4 min)
#   --answer-timeout  seconds a sent request may wait for its answer (default 45)
#   --cpus            podman --cpus for the container (default none)
#   --server-args     extra cutcalc flags, e.g. "--memory-limit-mb 256" (default none: the image
#                     as deployed)
#   --strict          exit 3 on FAIL (default: exit 0 once the attacks ran)
# env: CONTAINERS_CONF (default scripts/container/containers.conf, as scripts/ci-container.sh)
# Output: readable lines and the PASS/FAIL line on stdout; each attack's client output,
# container log and podman inspect under bench/results/container-memory-<timestamp>/ (gitignored).
# Example: bench/container_memory.sh --spread 5 --hold 5     (about 3 minutes)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export CONTAINERS_CONF="${CONTAINERS_CONF:-$ROOT/scripts/container/containers.conf}"

IMAGE=localhost/cutcalc:ci
MEMORY=256m
ATTACKS=never-read,slow-read,upload
SHARED=0
SPREAD=10
HOLD=10
RATE=262144
ANSWER_TIMEOUT=45
CPUS=""
SERVER_ARGS=""
STRICT=0

die() { echo "container_memory: $*" >&2; exit 2; }

while [[ $# -gt 0 ]]; do
  case "$1" in
    --image) IMAGE="$2"; shift 2 ;;
    --memory) MEMORY="$2"; shift 2 ;;
    --attacks) ATTACKS="$2"; shift 2 ;;
    --shared) SHARED=1; shift ;;
    --spread) SPREAD="$2"; shift 2 ;;
    --hold) HOLD="$2"; shift 2 ;;
    --rate) RATE="$2"; shift 2 ;;
    --answer-timeout) ANSWER_TIMEOUT="$2"; shift 2 ;;
    --cpus) CPUS="$2"; shift 2 ;;
    --server-args) SERVER_ARGS="$2"; shift 2 ;;
    --strict) STRICT=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d'; exit 0 ;;
    *) die "unknown argument: $1 (see --help)" ;;
  esac
done

number='^[0-9]+([.][0-9]+)?$'
[[ "$SPREAD" =~ $number && "$HOLD" =~ $number && "$RATE" =~ $number && "$ANSWER_TIMEOUT" =~ $number ]] \
  || die "--spread, --hold, --rate and --answer-timeout must be numbers"
[[ "$MEMORY" =~ ^[0-9]+[bkmg]?$ ]] || die "--memory must be like 256m"
IFS=, read -r -a ATTACK_LIST <<<"$ATTACKS"
for a in "${ATTACK_LIST[@]}"; do
  [[ "$a" == never-read || "$a" == slow-read || "$a" == upload ]] || die "unknown attack: $a"
done
read -r -a EXTRA_ARGS <<<"$SERVER_ARGS"
command -v podman >/dev/null || die "podman is required"
command -v curl >/dev/null || die "curl is required"
PYTHON=/usr/bin/python3
[[ -x "$PYTHON" ]] || PYTHON="$(command -v python3)"
podman image exists "$IMAGE" || die "image $IMAGE not found (scripts/ci-container.sh builds it)"

STAMP="$(date -u +%Y%m%dT%H%M%SZ)"
RESULTS="$ROOT/bench/results/container-memory-$STAMP"
mkdir -p "$RESULTS"
# podman's conmon writes an "oom" marker file into its working directory when the container is
# OOM-killed (seen with podman 4.3, runc, cgroup v1): keep it with the results, not in the repo.
cd "$RESULTS"
NAME_PREFIX="cutcalc-memory-$$"
STARTED=()   # every container started here, removed by the trap
CLIENT_PID=""

# podman without its systemd noise (no systemd here: it cannot add the HEALTHCHECK timer).
pm() {
  local rc=0
  podman "$@" 2>"$RESULTS/podman.err" || rc=$?
  grep -v 'unable to get systemd connection' "$RESULTS/podman.err" >&2 || true
  return "$rc"
}

# shellcheck disable=SC2317 # run from the EXIT trap
cleanup() {
  local status=$? n
  trap - EXIT INT TERM
  set +e
  [[ -n "$CLIENT_PID" ]] && kill "$CLIENT_PID" 2>/dev/null && wait "$CLIENT_PID" 2>/dev/null
  # One name per call: podman 4.3's rm -f does nothing when one of several names is missing.
  for n in "${STARTED[@]}"; do
    podman container exists "$n" 2>/dev/null && podman rm -f -t 0 "$n" >/dev/null 2>&1
  done
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

free_port() {
  "$PYTHON" -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'
}

# The body limit of POST /v1/program-time, from the image's own route table.
BODY_BYTES="$(pm run --rm --pull=never --network none "$IMAGE" --routes | "$PYTHON" -c '
import json, sys
print(next(r["max_body_bytes"] for r in json.load(sys.stdin) if r["path"] == "/v1/program-time"))')"
[[ "$BODY_BYTES" =~ ^[0-9]+$ && "$BODY_BYTES" -gt 65536 ]] || die "no body limit for /v1/program-time in $IMAGE --routes"

CONTAINER=""  # the one attacked now
PORT=""
PID=""
start_container() {  # $1: a name suffix
  CONTAINER="$NAME_PREFIX-$1"
  PORT="$(free_port)"
  local args=(run -d --pull=never --name "$CONTAINER" --memory="$MEMORY" --memory-swap="$MEMORY"
              -p "127.0.0.1:$PORT:8080")
  [[ -n "$CPUS" ]] && args+=(--cpus "$CPUS")
  STARTED+=("$CONTAINER")
  pm "${args[@]}" "$IMAGE" "${EXTRA_ARGS[@]}" >/dev/null
  local i
  for ((i = 0; i < 100; i++)); do
    [[ "$(curl -s -o /dev/null -w '%{http_code}' --max-time 1 "http://127.0.0.1:$PORT/healthz" || true)" == 200 ]] && break
    [[ "$(podman inspect --format '{{.State.Running}}' "$CONTAINER")" == true ]] \
      || { podman logs "$CONTAINER" | tail -n 20 >&2; die "container $CONTAINER exited at start"; }
    sleep 0.2
  done
  ((i < 100)) || die "container $CONTAINER did not answer /healthz within 20 s"
  PID="$(podman inspect --format '{{.State.Pid}}' "$CONTAINER")"
  [[ -r "/proc/$PID/status" ]] || die "cannot read /proc/$PID/status (the container's host-side PID)"
  echo "container $CONTAINER: 127.0.0.1:$PORT, host pid $PID, --memory=$MEMORY --memory-swap=$MEMORY${CPUS:+ --cpus=$CPUS}${SERVER_ARGS:+, cutcalc $SERVER_ARGS}"
  # What the service made of its limits (its start-up log lines).
  podman logs "$CONTAINER" 2>&1 | grep -E 'connections at most|event loops' \
    | "$PYTHON" -c 'import json, sys
for l in sys.stdin:
    try: print("  cutcalc:", json.loads(l)["message"])
    except ValueError: print("  cutcalc:", l.rstrip())' || true
}

stop_container() {
  [[ -n "$CONTAINER" ]] || return 0
  podman logs "$CONTAINER" >"$RESULTS/$CONTAINER.log" 2>&1 || true
  if podman container exists "$CONTAINER"; then
    pm rm -f -t 5 "$CONTAINER" >/dev/null || true
  fi
  CONTAINER=""
}

{
  echo "date: $STAMP"
  echo "host: $(uname -srm), $(nproc) cores, load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "cgroup: $(stat -fc %T /sys/fs/cgroup) at /sys/fs/cgroup ($( [[ -f /sys/fs/cgroup/cgroup.controllers ]] && echo 'v2' || echo 'v1: cutcalc reads the memory controller'"'"'s memory.limit_in_bytes'))"
  echo "git: $(git -C "$ROOT" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)"
  echo "image: $IMAGE ($(podman image inspect --format '{{.Id}}' "$IMAGE" | cut -c1-12), created $(podman image inspect --format '{{.Created}}' "$IMAGE"))"
  echo "attacks: ${ATTACK_LIST[*]}; never-read 200 over ${SPREAD} s held ${HOLD} s; slow-read 100 at ${RATE} B/s; upload 50 x ${BODY_BYTES} B; answer timeout ${ANSWER_TIMEOUT} s; $([[ $SHARED -eq 1 ]] && echo 'one container' || echo 'a fresh container each')"
} | tee "$RESULTS/meta.txt"

SUMMARY=()
VERDICT=PASS
for attack in "${ATTACK_LIST[@]}"; do
  if [[ $SHARED -eq 0 || -z "$CONTAINER" ]]; then
    stop_container
    start_container "$([[ $SHARED -eq 1 ]] && echo shared || echo "$attack")"
  fi
  client=("$PYTHON" "$ROOT/bench/memory_attack.py" "$PID" "$PORT" --scenario "$attack"
          --answer-timeout "$ANSWER_TIMEOUT")
  case "$attack" in
    never-read) client+=(--n 200 --spread "$SPREAD" --hold "$HOLD") ;;
    slow-read) client+=(--n 100 --rate "$RATE") ;;
    upload) client+=(--n 50 --body-bytes "$BODY_BYTES") ;;
  esac
  echo "=== $attack [$(date -u +%T)]: ${client[*]:2}"
  t0=$(date +%s)
  "${client[@]}" >"$RESULTS/$attack.txt" 2>&1 &
  CLIENT_PID=$!
  client_rc=0
  wait "$CLIENT_PID" || client_rc=$?
  CLIENT_PID=""
  seconds=$(($(date +%s) - t0))
  grep -v '^MEMORY_RESULT ' "$RESULTS/$attack.txt" || true
  sleep 1  # let an OOM kill, if any, be noticed by podman
  state="$(podman inspect --format '{{.State.Status}} {{.State.Running}} {{.State.OOMKilled}} {{.State.ExitCode}}' "$CONTAINER" 2>/dev/null || echo "gone false unknown unknown")"
  podman inspect "$CONTAINER" >"$RESULTS/$attack.inspect.json" 2>/dev/null || true
  read -r status running oom exit_code <<<"$state"
  # podman's OOMKilled is not the only witness (with runc on a cgroup v1 host it stays false when
  # the kernel kills the service): the cgroup's oom_kill count (the client's last sample) and the
  # kernel log's "Killed process PID" line (when dmesg is readable) count as well.
  if kernel_log="$(dmesg 2>/dev/null)"; then
    kernel_oom="$(grep -c "Killed process $PID (" <<<"$kernel_log" || true)"
  else
    kernel_oom=unknown
  fi
  healthz="$(curl -s -o /dev/null -w '%{http_code}' --max-time 5 "http://127.0.0.1:$PORT/healthz" || true)"
  line="$("$PYTHON" - "$RESULTS/$attack.txt" "$attack" "$client_rc" "$seconds" "$status" "$running" "$oom" "$exit_code" "$healthz" "$kernel_oom" <<'PY'
import json, sys
path, attack, rc, seconds, status, running, oom, exit_code, healthz, kernel_oom = sys.argv[1:]
res = None
for line in open(path):
    if line.startswith("MEMORY_RESULT "):
        res = json.loads(line[len("MEMORY_RESULT "):])
mib = lambda b: f"{b / 1048576:.0f}" if b is not None else "n/a"
problems = []
if res is None:
    problems.append(f"client failed (exit {rc}, no result)")
    text = f"{attack}: no result"
else:
    statuses = ", ".join(f"{k}: {v}" for k, v in sorted(res["statuses"].items()))
    text = (f"{attack}: {res['n']} clients, {seconds} s: statuses {{{statuses}}}, lost {res['lost']}"
            + (f" {res['lost_by']}" if res["lost"] else ""))
    if res.get("refusals"):
        text += f" (refusals {res['refusals']})"
    if res.get("connect_failed"):
        text += f", connect failed {res['connect_failed']}"
    text += (f"; peak VmRSS {mib(res['rss_peak_kib'] * 1024 if res['rss_peak_kib'] else None)} MiB"
             f" (VmHWM {mib(res['hwm_kib'] * 1024 if res['hwm_kib'] else None)}),"
             f" cgroup {mib(res['cgroup_peak_bytes'])} MiB sampled"
             f" / {mib(res['cgroup_hwm_bytes'])} MiB kernel peak"
             f" of {mib(res['cgroup'].get('limit_bytes'))} MiB"
             + (" (reached the limit)" if res["cgroup_hwm_bytes"] and res["cgroup"].get("limit_bytes")
                and res["cgroup_hwm_bytes"] >= res["cgroup"]["limit_bytes"] - (1 << 20) else "")
             + f", cgroup oom_kill {res['cgroup'].get('oom_kill')}")
    if res.get("healthz_ms"):
        h = res["healthz_ms"]
        text += f"; /healthz meanwhile median {h['median']} ms, max {h['max']} ms"
    if res["lost"]:
        problems.append(f"{res['lost']} lost")
    if res.get("503_without_retry_after"):
        problems.append(f"{res['503_without_retry_after']} 503 without Retry-After")
    bad = [k for k in res["statuses"] if k not in ("200", "413", "503")]
    if bad:
        problems.append(f"unexpected statuses {bad}")
    if res.get("cgroup", {}).get("oom_kill"):
        problems.append(f"cgroup oom_kill {res['cgroup']['oom_kill']}")
text += (f"; podman OOMKilled {oom}, kernel OOM kills of the service {kernel_oom}, state {status}"
         + (f" (exit {exit_code})" if running != "true" else ""))
text += f", /healthz after {healthz or 'no answer'}"
if oom != "false":
    problems.append(f"OOMKilled {oom}")
if kernel_oom not in ("0", "unknown"):
    problems.append("OOM-killed (kernel log)")
if running != "true":
    problems.append(f"container {status}")
if healthz != "200":
    problems.append(f"/healthz {healthz or 'no answer'}")
print(("FAIL " if problems else "ok   ") + text + (f" [{'; '.join(problems)}]" if problems else ""))
PY
)"
  echo "$line"
  SUMMARY+=("$line")
  [[ "$line" == ok* ]] || VERDICT=FAIL
  if [[ $SHARED -eq 1 && "$running" != true ]]; then
    stop_container  # the next attack needs a running service
  fi
done
stop_container

{
  echo
  echo "summary ($IMAGE, --memory=$MEMORY --memory-swap=$MEMORY):"
  printf '  %s\n' "${SUMMARY[@]}"
  echo "$VERDICT: $([[ $VERDICT == PASS ]] && echo 'no OOM kill, the service ran and answered /healthz after every attack, no accepted request lost' || echo 'see the FAIL lines above')"
} | tee "$RESULTS/summary.txt"
echo "results: $RESULTS" >&2
if [[ $STRICT -eq 1 && $VERDICT != PASS ]]; then exit 3; fi
exit 0
