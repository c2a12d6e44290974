#!/usr/bin/env bash
# CI step for the LinuxCNC oracle (tools/oracle/): re-times a fixed sample of the cases recorded in
# tests/oracle/linuxcnc-times.json, one per path-control category and all short, with LinuxCNC 2.9's
# real trajectory planner run headless in simulation (linuxcnc-uspace, scripts/debian-packages.txt),
# one simulation at a time, and fails if any simulated time differs from the recorded sim_time_s by
# more than 10 ms. This proves the recorded times are still what the installed LinuxCNC gives and that
# the oracle (INI/HAL generation, start-up, clock, shutdown) still works on this machine.
# Runs as root (rtapi_app then runs with RTAPI_UID of nobody, set by time_program.py) or as a user.
# Budget: about 5 s a case, under 4 minutes in all. Exit non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
started=$SECONDS

# one fixed, short case per category
cases=(
  single-rapid-x80-router-g61
  g611-zigzag-router
  g61-triangle-router
  g64-circle-r2-router
  g64p001-square60-router
)
tolerance_s=0.010
recorded=tests/oracle/linuxcnc-times.json

if ! dpkg-query -W -f='${Status}' linuxcnc-uspace 2>/dev/null | grep -q "install ok installed"; then
  echo "ci-oracle: linuxcnc-uspace is not installed (scripts/setup.sh installs it)" >&2
  exit 1
fi
echo "ci-oracle: linuxcnc-uspace $(dpkg-query -W -f='${Version}' linuxcnc-uspace), ${#cases[@]} cases, tolerance ${tolerance_s} s"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

passed=0
failed=0
for id in "${cases[@]}"; do
  # the case's program and its profile's machine object, from the recorded file
  if ! /usr/bin/python3 - "$recorded" "$id" "$work" <<'EOF'
import json, sys
path, cid, work = sys.argv[1:4]
doc = json.load(open(path))
case = next((c for c in doc["cases"] if c["id"] == cid), None)
if case is None:
    sys.exit(f"ci-oracle: {cid} is not in {path}")
open(f"{work}/{cid}.ngc", "w").write(case["program"])
json.dump(doc["profiles"][case["profile"]], open(f"{work}/{cid}.json", "w"))
open(f"{work}/{cid}.want", "w").write(f"{case['sim_time_s']:.3f} {case['category']} {case['profile']}\n")
EOF
  then
    failed=$((failed + 1))
    continue
  fi
  read -r want category profile <"$work/$id.want"
  case_started=$SECONDS
  if got=$(timeout -k 15 60 /usr/bin/python3 tools/oracle/time_program.py "$work/$id.ngc" "$work/$id.json" 2>"$work/$id.err"); then
    verdict=$(awk -v g="$got" -v w="$want" -v t="$tolerance_s" 'BEGIN { d = g - w; if (d < 0) d = -d; print (d <= t + 1e-9) ? "ok" : "FAIL" }')
    diff_ms=$(awk -v g="$got" -v w="$want" 'BEGIN { printf "%+.0f", (g - w) * 1000 }')
    echo "ci-oracle: ${verdict} ${id} (${category}, ${profile}): recorded ${want} s, now ${got} s (${diff_ms} ms; wall $((SECONDS - case_started)) s)"
    if [[ $verdict == ok ]]; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
  else
    echo "ci-oracle: FAIL ${id} (${category}, ${profile}): the oracle did not run: $(tail -n 3 "$work/$id.err" | tr '\n' ' ')"
    failed=$((failed + 1))
  fi
done

echo "ci-oracle: wall $((SECONDS - started)) s"
echo "${passed} passed, ${failed} failed"
[[ $failed -eq 0 ]]
