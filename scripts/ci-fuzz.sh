#!/usr/bin/env bash
# Fuzzing (CI step): builds the libFuzzer harnesses of fuzz/ with clang++ (ASan + UBSan, coverage
# instrumentation; a project of its own in build/fuzz, apart from the gcc build), writes their seed
# corpora from the reference requests (../shared/reference/*.json plus the next/ files the route
# table lists, each case's `request`), and runs every harness for a bounded time. The request
# harnesses are one per (route, answer form) of the route table (api/routes.cpp): the one binary
# endpoint_fuzzer, run once per row of harnesses.txt (written by cutcalc_fuzz_seeds) with
# CUTCALC_FUZZ_ROUTE and CUTCALC_FUZZ_FORM set, under the names <slug>_fuzzer and <slug>_text_fuzzer.
# Fails on any crash, sanitizer report, timeout (> CUTCALC_FUZZ_TIMEOUT s for one
# input), leak, out-of-memory or broken API promise (fuzz/fuzz_support.h: status 500 or
# undocumented, body not JSON, NaN or infinity, a negative length, a response or accepted request
# outside openapi.yaml, a malformed G-code program). Findings are kept in build/fuzz/run/artifacts.
#
# gcode_reader_fuzzer feeds raw bytes to the G-code reader as a program in every dialect, on a mill
# and a lathe (fuzz/gcode_reader_fuzzer.cpp: refusals name a line, column and word inside the
# program, every move is finite and continuous); its seeds are programs the program routes write
# and a few hand-written ones (cutcalc_fuzz_seeds), its dictionary fuzz/gcode.dict.
#
# The last harness, http_engine_fuzzer, feeds raw bytes to the whole service over a socketpair
# (fuzz/http_engine_fuzzer.cpp: framing, pipelining, every endpoint; its oracle checks that the
# answers are well-framed HTTP/1.1, never more than the requests, problem+json for errors, and
# that a fresh connection is still served). Its dictionary is fuzz/http.dict.
#
# Time: one request harness per route and answer form (the rows of harnesses.txt) and the G-code
# reader harness x CUTCALC_FUZZ_SECONDS (default 30) + the engine harness for
# CUTCALC_FUZZ_ENGINE_SECONDS (default 90), run CUTCALC_FUZZ_LANES harnesses at a time (default:
# one per CPU; a libFuzzer process uses one): about (harnesses x 30 s + 60 s) / lanes, a few
# minutes on two cores (the run prints how many harnesses the table gave), plus the build (about 6
# minutes from scratch on two idle cores; incremental afterwards).
#
# Environment:
#   CUTCALC_FUZZ_SECONDS    seconds per request harness (default 30)
#   CUTCALC_FUZZ_ENGINE_SECONDS  seconds for the HTTP engine harness (default 90)
#   CUTCALC_FUZZ_RUNS       run each harness for this many inputs instead of a time (report runs)
#   CUTCALC_FUZZ_TIMEOUT    seconds one input may take before it counts as a hang (default 30)
#   CUTCALC_FUZZERS         space-separated harness names to run (default: all of them)
#   CUTCALC_FUZZ_LANES      harnesses run at the same time (default: the CPU count)
#   CUTCALC_REFERENCE_DIR   the reference cases (default ../shared/reference)
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${CUTCALC_FUZZ_SECONDS:-30}
engine_seconds=${CUTCALC_FUZZ_ENGINE_SECONDS:-90}
runs=${CUTCALC_FUZZ_RUNS:-}
# A hang detector, not a speed limit: the largest legal polygon program (15.8 MB, about 0.1 s in the
# release service) takes about 4 s here under ASan + UBSan + coverage with the oracle on a busy box.
timeout=${CUTCALC_FUZZ_TIMEOUT:-30}
lanes=${CUTCALC_FUZZ_LANES:-$(nproc)}
reference_dir=${CUTCALC_REFERENCE_DIR:-../shared/reference}
build_dir=build/fuzz
run_dir=$build_dir/run

# --- dependencies (Debian 12): only the missing ones
packages=(clang libclang-rt-14-dev cmake ninja-build pkg-config nlohmann-json3-dev libeigen3-dev libcpp-httplib-dev
  libspdlog-dev libyaml-cpp-dev)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if ((${#missing[@]})); then
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  echo "ci-fuzz: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y --no-install-recommends \
    "${missing[@]}"
fi

# --- build
build_start=$SECONDS
echo "=== fuzz: configure and build (clang++, -fsanitize=fuzzer,address,undefined)"
cmake -S fuzz -B "$build_dir" -G Ninja -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build "$build_dir" -j 2
build_seconds=$((SECONDS - build_start))

# --- seeds and dictionary
rm -rf "$run_dir/seeds" "$run_dir/artifacts" "$run_dir/logs"
mkdir -p "$run_dir/seeds" "$run_dir/artifacts" "$run_dir/logs"
"$build_dir/cutcalc_fuzz_seeds" "$reference_dir" openapi.yaml "$run_dir/seeds"
cat fuzz/cutcalc.dict "$run_dir/seeds/tokens.dict" >"$run_dir/cutcalc.dict"
cat fuzz/http.dict "$run_dir/seeds/paths.dict" "$run_dir/seeds/tokens.dict" >"$run_dir/http.dict"
cp fuzz/gcode.dict "$run_dir/gcode.dict"

# harness name -> "path form", from the route table.
declare -A harness_route=()
all_fuzzers=()
while read -r name path form; do
  harness_route[$name]="$path $form"
  all_fuzzers+=("$name")
done <"$run_dir/seeds/harnesses.txt"
# The harnesses of their own (not a route row): their binary is their name, their seeds the
# directory of their name less _fuzzer, their dictionary fuzz/<this>.dict.
declare -A standalone_dict=([http_engine_fuzzer]=http [gcode_reader_fuzzer]=gcode)
# The engine harness first: the longest, so the lanes end together.
all_fuzzers=(http_engine_fuzzer gcode_reader_fuzzer "${all_fuzzers[@]}")
if [[ -n ${CUTCALC_FUZZERS:-} ]]; then
  read -r -a fuzzers <<<"$CUTCALC_FUZZERS"
else
  fuzzers=("${all_fuzzers[@]}")
fi
if [[ -n $runs ]]; then
  echo "=== fuzz: ${#fuzzers[@]} harnesses, $runs inputs each"
else
  echo "=== fuzz: ${#fuzzers[@]} harnesses, ${seconds} s each (the HTTP engine ${engine_seconds} s)"
fi

declare -A running=() # pid -> harness
declare -A started=()  # harness -> $SECONDS at its start
cleanup() {
  local pid
  for pid in "${!running[@]}"; do
    kill "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
}
trap cleanup EXIT
trap 'exit 130' INT TERM

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

fuzz_start=$SECONDS
failed=()
total_execs=0

# Starts one harness in the background.
launch() {
  local fuzzer=$1 seeds binary corpus dict log
  local route=() limit=()
  seeds=${fuzzer%_fuzzer}
  seeds=${seeds%_text}
  binary=$build_dir/$fuzzer
  if [[ -z ${standalone_dict[$fuzzer]:-} ]]; then
    [[ -n ${harness_route[$fuzzer]:-} ]] ||
      { echo "ci-fuzz: no harness $fuzzer (harnesses: ${all_fuzzers[*]})" >&2; exit 1; }
    read -r route_path route_form <<<"${harness_route[$fuzzer]}"
    route=(CUTCALC_FUZZ_ROUTE="$route_path" CUTCALC_FUZZ_FORM="$route_form")
    binary=$build_dir/endpoint_fuzzer
  fi
  if [[ ! -x $binary || -z $(ls -A "$run_dir/seeds/$seeds" 2>/dev/null) ]]; then
    echo "ci-fuzz: no harness $binary or no seeds $seeds (reference files in $reference_dir?)" >&2
    exit 1
  fi
  corpus=$build_dir/corpus/$fuzzer # kept between local runs; CI starts from the seeds
  dict=$run_dir/cutcalc.dict
  [[ -n ${standalone_dict[$fuzzer]:-} ]] && dict=$run_dir/${standalone_dict[$fuzzer]}.dict
  if [[ -n $runs ]]; then
    limit=(-runs="$runs")
  elif [[ $fuzzer == http_engine_fuzzer ]]; then
    limit=(-max_total_time="$engine_seconds")
  else
    limit=(-max_total_time="$seconds")
  fi
  log=$run_dir/logs/$fuzzer.log
  mkdir -p "$corpus"
  started[$fuzzer]=$SECONDS
  env "${route[@]}" "$binary" "$corpus" "$run_dir/seeds/$seeds" -dict="$dict" \
    "${limit[@]}" -timeout="$timeout" -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 \
    -artifact_prefix="$run_dir/artifacts/$fuzzer-" >"$log" 2>&1 &
  running[$!]=$fuzzer
}

# Waits for any running harness and reports it.
reap() {
  local pid status=0 fuzzer log execs rate coverage
  wait -n -p pid "${!running[@]}" || status=$?
  fuzzer=${running[$pid]}
  unset "running[$pid]"
  log=$run_dir/logs/$fuzzer.log
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  coverage=$(grep -Eo 'cov: [0-9]+ ft: [0-9]+' "$log" | tail -1 || true)
  total_execs=$((total_execs + ${execs:-0}))
  printf '%-32s %10s execs %6s exec/s  %-22s %4d s  %s\n' "$fuzzer" "${execs:-?}" "${rate:-?}" \
    "${coverage:-cov: ?}" $((SECONDS - started[$fuzzer])) "$([[ $status -eq 0 ]] && echo ok || echo "FAILED ($status)")"
  if [[ $status -ne 0 ]] || compgen -G "$run_dir/artifacts/$fuzzer-*" >/dev/null; then
    failed+=("$fuzzer")
    echo "--- $fuzzer: end of $log"
    grep -v -E '^(#[0-9]+|INFO:|MS:|stat::)' "$log" | tail -60 || true
    ls -l "$run_dir/artifacts/$fuzzer-"* 2>/dev/null || true
  fi
}

for fuzzer in "${fuzzers[@]}"; do
  while ((${#running[@]} >= lanes)); do reap; done
  launch "$fuzzer"
done
while ((${#running[@]} > 0)); do reap; done

echo "ci-fuzz: ${#fuzzers[@]} harnesses, $total_execs executions in $((SECONDS - fuzz_start)) s" \
  "(build $build_seconds s), ${#failed[@]} failing${failed[*]:+: ${failed[*]}}"
((${#failed[@]} == 0))
