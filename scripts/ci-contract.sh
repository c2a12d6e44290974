#!/usr/bin/env bash
# Contract step: lints openapi.yaml with Redocly CLI and Spectral, then replays every reference
# case (../shared/reference/*.json), the operations endpoints and a list of bad-input requests
# through Prism's validating proxy in front of a release cutcalc (tools/contract/replay.mjs).
# Then the property step against the same cutcalc, without Prism (tools/contract/property.mjs):
# a few thousand bodies generated from the request schemas (schema-valid, one and two members
# broken, every numeric bound and the next double past it, every default sent explicitly), each
# answer checked against openapi.yaml and the rules of errors[]; its report (every finding with a
# reproducer) is also written to build/contract/property-report.json.
# Fails on any lint error, on any response, success or problem, that does not match its schema,
# and on any property finding not listed in tools/contract/property-known.mjs.
#
# Environment (all optional):
#   CUTCALC_BIN             cutcalc binary (default build/release/service/cutcalc, built if missing)
#   CONTRACT_OPENAPI        the document to check and to serve through Prism (default openapi.yaml)
#   CUTCALC_REFERENCE_DIR   reference cases (default ../shared/reference, relative to the repo)
#   REPLAY_VERBOSE=1        print every exchange
#   PROPERTY_SEED           the property step's seed (default fixed: the same bodies every run)
#   PROPERTY_REQUESTS       about how many requests it sends (default 5000)
#   PROPERTY_SECONDS        its time budget for new cases (default 150)
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
# shellcheck source=scripts/lib/start_cutcalc.sh
source "$ROOT/scripts/lib/start_cutcalc.sh"
# shellcheck source=scripts/lib/ensure_node.sh
source "$ROOT/scripts/lib/ensure_node.sh"
TOOLS=$ROOT/tools/contract
OPENAPI=$(realpath "${CONTRACT_OPENAPI:-$ROOT/openapi.yaml}")
BIN=${CUTCALC_BIN:-$ROOT/build/release/service/cutcalc}
STARTED=$(date +%s)

export REDOCLY_TELEMETRY=off REDOCLY_SUPPRESS_UPDATE_NOTICE=true SCARF_ANALYTICS=false \
  NO_UPDATE_NOTIFIER=1 npm_config_update_notifier=false npm_config_fund=false npm_config_audit=false

WORK=$(mktemp -d)
PIDS=()
cleanup() {
  local pid
  for pid in "${PIDS[@]}" ${CUTCALC_PID:+"$CUTCALC_PID"}; do kill "$pid" 2>/dev/null || true; done
  for pid in "${PIDS[@]}" ${CUTCALC_PID:+"$CUTCALC_PID"}; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$WORK"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

die() {
  echo "ci-contract: $*" >&2
  exit 1
}

# ---------------------------------------------------------------- Node.js and the tools
ensure_node ci-contract 20 19 "Redocly CLI 2" || exit 1
echo "=== contract: npm ci (tools/contract; node $(node --version), npm $(npm --version 2>/dev/null))"
(cd "$TOOLS" && npm ci --no-audit --no-fund --loglevel=error)
INSTALLED=$(date +%s)

# ---------------------------------------------------------------- lint
echo "=== contract: redocly lint $(basename "$OPENAPI")"
"$TOOLS/node_modules/.bin/redocly" lint --config "$TOOLS/redocly.yaml" "$OPENAPI" ||
  die "Redocly CLI reports errors in $OPENAPI"
echo "=== contract: spectral lint $(basename "$OPENAPI")"
"$TOOLS/node_modules/.bin/spectral" lint --ruleset "$TOOLS/.spectral.yaml" --fail-severity error "$OPENAPI" ||
  die "Spectral reports errors in $OPENAPI"

# ---------------------------------------------------------------- cutcalc
start_cutcalc "$BIN" "$WORK/cutcalc.log" contract
BIN=$CUTCALC_BIN

# ---------------------------------------------------------------- Prism proxies
# Two free loopback ports (Prism reports its port only at log level info, which also logs every
# request); the ports are held until just before Prism binds them.
read -r STRICT_PORT RELAXED_PORT < <(node -e '
  const net = require("net");
  const a = net.createServer().listen(0, "127.0.0.1", () => {
    const b = net.createServer().listen(0, "127.0.0.1", () => {
      console.log(a.address().port, b.address().port);
      a.close(); b.close();
    });
  });')
[[ -n "${RELAXED_PORT:-}" ]] || die "cannot find two free loopback ports"
start_prism() { # port log-name extra-args...
  local port=$1 name=$2
  shift 2
  "$TOOLS/node_modules/.bin/prism" proxy "$OPENAPI" "http://127.0.0.1:$CUTCALC_PORT" \
    --errors --cors=false -v warn -h 127.0.0.1 -p "$port" "$@" >"$WORK/prism-$name.log" 2>&1 &
  PIDS+=("$!")
  eval "PRISM_${name^^}_PID=$!"
}
start_prism "$STRICT_PORT" strict
start_prism "$RELAXED_PORT" relaxed --validate-request=false
wait_port() { # port pid name
  for _ in $(seq 1 900); do
    if (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; then return 0; fi
    kill -0 "$2" 2>/dev/null || { cat "$WORK/prism-$3.log" >&2; die "Prism ($3) exited at start"; }
    sleep 0.1
  done
  cat "$WORK/prism-$3.log" >&2
  die "Prism ($3) did not listen on port $1 within 90 s"
}
wait_port "$STRICT_PORT" "$PRISM_STRICT_PID" strict
wait_port "$RELAXED_PORT" "$PRISM_RELAXED_PID" relaxed

# ---------------------------------------------------------------- replay
echo "=== contract: replay through Prism (cutcalc :$CUTCALC_PORT, Prism :$STRICT_PORT strict, :$RELAXED_PORT relaxed)"
status=0
PRISM_STRICT_URL="http://127.0.0.1:$STRICT_PORT" PRISM_RELAXED_URL="http://127.0.0.1:$RELAXED_PORT" \
  CUTCALC_URL="http://127.0.0.1:$CUTCALC_PORT" OPENAPI_FILE="$OPENAPI" \
  CUTCALC_BIN="$BIN" node "$TOOLS/replay.mjs" --prism || status=$?
for name in strict relaxed; do
  pid_var="PRISM_${name^^}_PID"
  if ! kill -0 "${!pid_var}" 2>/dev/null; then
    echo "ci-contract: Prism ($name) died during the replay:" >&2
    tail -n 30 "$WORK/prism-$name.log" >&2
    status=1
  fi
done
kill -0 "$CUTCALC_PID" 2>/dev/null || { tail -n 30 "$WORK/cutcalc.log" >&2; echo "ci-contract: cutcalc died during the replay" >&2; status=1; }

# ---------------------------------------------------------------- property-based requests
# Directly to cutcalc: Prism re-serialises bodies (1e400 becomes null) and would answer the broken
# ones itself.
for name in strict relaxed; do
  pid_var="PRISM_${name^^}_PID"
  kill "${!pid_var}" 2>/dev/null || true
done
if kill -0 "$CUTCALC_PID" 2>/dev/null; then
  echo "=== contract: property-based requests from the request schemas (cutcalc :$CUTCALC_PORT)"
  mkdir -p "$ROOT/build/contract"
  CUTCALC_URL="http://127.0.0.1:$CUTCALC_PORT" OPENAPI_FILE="$OPENAPI" \
    node "$TOOLS/property.mjs" --report-json "$ROOT/build/contract/property-report.json" || status=1
  kill -0 "$CUTCALC_PID" 2>/dev/null || { tail -n 30 "$WORK/cutcalc.log" >&2; echo "ci-contract: cutcalc died during the property step" >&2; status=1; }
fi
ENDED=$(date +%s)
if [[ $status -ne 0 ]]; then
  echo "=== contract: FAILED ($((ENDED - STARTED)) s)" >&2
  exit 1
fi
echo "=== contract: passed: Redocly and Spectral clean, replay clean, property step clean ($((ENDED - INSTALLED)) s after npm ci, $((ENDED - STARTED)) s in all)"
