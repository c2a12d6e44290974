#!/usr/bin/env bash
# Codegen step: generated clients must be able to trust openapi.yaml (issue 12).
#  1. openapi-typescript generates the `paths` types; tools/codegen/gen-reference-client.mjs writes
#     an openapi-fetch client that sends every reference case (../shared/reference/*.json) as an
#     object literal: status 200 cases are checked against their expected values; status 422 cases
#     that the request schema's types can express are written under `// @ts-expect-error` (so the
#     compile fails when the types accept them: too loose), the others plain (so it fails when the
#     types reject a type-correct request: too strict). tsc --strict type-checks it, then the
#     emitted JavaScript runs against a live release cutcalc (every 422 case is sent too).
#  2. @hey-api/openapi-ts generates an SDK (fetch client), tsc --strict compiles it with a small
#     program that calls cutcalc through it (tools/codegen/heyapi-smoke.ts).
# Generated code goes to build/codegen/ (not committed). Fails on any generator error, any tsc
# diagnostic and any wrong answer.
#
# Environment (all optional):
#   CUTCALC_BIN             cutcalc binary (default build/release/service/cutcalc, built if missing)
#   CODEGEN_OPENAPI         the document to generate from (default openapi.yaml)
#   CUTCALC_REFERENCE_DIR   reference cases (default ../shared/reference, relative to the repo)
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
# shellcheck source=scripts/lib/start_cutcalc.sh
source "$ROOT/scripts/lib/start_cutcalc.sh"
# shellcheck source=scripts/lib/ensure_node.sh
source "$ROOT/scripts/lib/ensure_node.sh"
TOOLS=$ROOT/tools/codegen
OPENAPI=$(realpath "${CODEGEN_OPENAPI:-$ROOT/openapi.yaml}")
REFERENCE_DIR=$(realpath "${CUTCALC_REFERENCE_DIR:-$ROOT/../shared/reference}")
BIN=${CUTCALC_BIN:-$ROOT/build/release/service/cutcalc}
OUT=$ROOT/build/codegen
STARTED=$(date +%s)

export NO_UPDATE_NOTIFIER=1 npm_config_update_notifier=false npm_config_fund=false npm_config_audit=false

WORK=$(mktemp -d)
cleanup() {
  if [[ -n "${CUTCALC_PID:-}" ]]; then
    kill "$CUTCALC_PID" 2>/dev/null || true
    wait "$CUTCALC_PID" 2>/dev/null || true
  fi
  rm -rf "$WORK"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

die() {
  echo "ci-codegen: $*" >&2
  exit 1
}

# ---------------------------------------------------------------- Node.js and the tools
ensure_node ci-codegen 20 19 "@hey-api/openapi-ts" || exit 1
[[ -d "$REFERENCE_DIR" ]] || die "no reference directory $REFERENCE_DIR"
echo "=== codegen: npm ci (tools/codegen; node $(node --version), npm $(npm --version 2>/dev/null))"
(cd "$TOOLS" && npm ci --no-audit --no-fund --loglevel=error)
INSTALLED=$(date +%s)
BINS=$TOOLS/node_modules/.bin
rm -rf "$OUT"
mkdir -p "$OUT"
# The generated code imports openapi-fetch, yaml and @types/node from tools/codegen.
ln -s "$TOOLS/node_modules" "$OUT/node_modules"

# ---------------------------------------------------------------- cutcalc
# Started before generating: the client covers the reference files its route table lists
# (`cutcalc --routes`: reference/*.json plus the listed next/ files).
start_cutcalc "$BIN" "$WORK/cutcalc.log" codegen
"$CUTCALC_BIN" --routes >"$WORK/routes.json" || die "$CUTCALC_BIN --routes failed"

# ---------------------------------------------------------------- generate
# --default-non-nullable=false: openapi-typescript (7.x) otherwise makes every property with a
# `default` required in components/schemas, and the request schemas are components: a request
# omitting a defaulted field (valid, and most reference requests do) would not type-check.
echo "=== codegen: openapi-typescript $(basename "$OPENAPI") -> build/codegen/schema.ts"
"$BINS/openapi-typescript" "$OPENAPI" -o "$OUT/schema.ts" --default-non-nullable=false ||
  die "openapi-typescript failed on $OPENAPI"
echo "=== codegen: reference client (tools/codegen/gen-reference-client.mjs)"
node "$TOOLS/gen-reference-client.mjs" --openapi "$OPENAPI" --reference "$REFERENCE_DIR" \
  --routes "$WORK/routes.json" --out "$OUT" ||
  die "gen-reference-client.mjs failed"
echo "=== codegen: @hey-api/openapi-ts $(basename "$OPENAPI") -> build/codegen/heyapi/"
HEYAPI_INPUT=$OPENAPI HEYAPI_OUTPUT=$OUT/heyapi "$BINS/openapi-ts" -f "$TOOLS/openapi-ts.config.mjs" ||
  die "@hey-api/openapi-ts failed on $OPENAPI"
cp "$TOOLS/heyapi-smoke.ts" "$OUT/heyapi-smoke.ts"
cat >"$OUT/tsconfig.heyapi.json" <<'EOF'
{
  "extends": "./tsconfig.json",
  "compilerOptions": { "outDir": "js-heyapi" },
  "files": ["heyapi-smoke.ts"],
  "include": ["heyapi/**/*.ts"]
}
EOF
GENERATED=$(date +%s)

# ---------------------------------------------------------------- compile
# The type check is the test: an unused @ts-expect-error (types too loose) or an error on a plain
# request (too strict) fails it. Then the same program is emitted as JavaScript to run.
echo "=== codegen: tsc --strict --noEmit (openapi-typescript + openapi-fetch reference client)"
"$BINS/tsc" -p "$OUT/tsconfig.json" --strict --noEmit --pretty false ||
  die "the reference client does not type-check against the generated types (see above)"
echo "tsc: reference client: no diagnostics"
echo "=== codegen: tsc --strict --noEmit (@hey-api/openapi-ts SDK and heyapi-smoke.ts)"
"$BINS/tsc" -p "$OUT/tsconfig.heyapi.json" --strict --noEmit --pretty false ||
  die "the @hey-api/openapi-ts SDK does not compile with tsc --strict (see above)"
echo "tsc: hey-api SDK: no diagnostics ($(find "$OUT/heyapi" -name '*.ts' | wc -l) generated files)"
# Emitting needs no second type check (--noCheck, TypeScript >= 5.6).
echo "=== codegen: tsc emit (JavaScript to run)"
"$BINS/tsc" -p "$OUT/tsconfig.json" --noCheck --pretty false || die "tsc could not emit the reference client"
"$BINS/tsc" -p "$OUT/tsconfig.heyapi.json" --noCheck --pretty false || die "tsc could not emit the hey-api SDK"
COMPILED=$(date +%s)

# ---------------------------------------------------------------- run against cutcalc
URL="http://127.0.0.1:$CUTCALC_PORT"
status=0
echo "=== codegen: reference client against cutcalc ($URL)"
CUTCALC_URL=$URL node "$OUT/js/reference-client.js" || status=1
echo "=== codegen: hey-api SDK against cutcalc ($URL)"
CUTCALC_URL=$URL OPENAPI_FILE=$OPENAPI CUTCALC_REFERENCE_DIR=$REFERENCE_DIR CUTCALC_ROUTES_FILE=$WORK/routes.json \
  node "$OUT/js-heyapi/heyapi-smoke.js" || status=1
kill -0 "$CUTCALC_PID" 2>/dev/null || {
  tail -n 30 "$WORK/cutcalc.log" >&2
  echo "ci-codegen: cutcalc died during the run" >&2
  status=1
}
ENDED=$(date +%s)
if [[ $status -ne 0 ]]; then
  echo "=== codegen: FAILED ($((ENDED - STARTED)) s)" >&2
  exit 1
fi
echo "=== codegen: passed: openapi-typescript + openapi-fetch client type-checks and answers as the reference, hey-api SDK compiles and calls cutcalc ($((GENERATED - INSTALLED)) s generate, $((COMPILED - GENERATED)) s tsc, $((ENDED - COMPILED)) s run; $((ENDED - INSTALLED)) s after npm ci, $((ENDED - STARTED)) s in all)"
