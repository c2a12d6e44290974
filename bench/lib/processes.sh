# shellcheck shell=bash
# Stopping the servers and load generators a bench script started, sourced by bench/http_bench.sh
# and bench/mixed_load.sh. The caller sets BENCH_NAME (for messages).

descendants() {  # pids of every descendant of $1
  local child
  # shellcheck disable=SC2013 # the children files hold pids separated by spaces
  for child in $(cat /proc/"$1"/task/*/children 2>/dev/null); do
    echo "$child"
    descendants "$child"
  done
}

# shellcheck disable=SC2317 # run from the callers' EXIT traps
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
    echo "${BENCH_NAME:-bench}: pid $pid ignored SIGTERM; killing it" >&2
    kill -KILL "$pid" 2>/dev/null || true
  fi
  wait "$pid" 2>/dev/null || true
  for i in $kids; do kill -KILL "$i" 2>/dev/null || true; done
}
