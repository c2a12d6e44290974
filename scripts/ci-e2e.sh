#!/usr/bin/env bash
# Browser step: the web calculator (GET /, web/ embedded in cutcalc) end to end in Debian's headless
# Chromium, driven by Playwright (playwright-core from tools/e2e, never a downloaded browser), against
# a live release cutcalc: every section filled with a reference case, submitted, its numbers and
# diagrams checked, the G-code download, an invalid input's message, keyboard-only use and no
# horizontal scroll at 375 px, the printed setup sheets (PDF, read with poppler's pdftotext), the
# page in Russian and in inches, and no console error or failed request (tests/e2e/*.test.mjs); CORS
# from pages on other loopback origins against a second cutcalc with --cors-origin (cors.test.mjs).
# Screenshots of the final page at 1280 px and 375 px go to build/e2e/ (for people, not assertions).
#
# Environment (all optional):
#   CUTCALC_BIN             cutcalc binary (default build/release/service/cutcalc, built if missing)
#   CUTCALC_REFERENCE_DIR   reference cases (default ../shared/reference, relative to the repo)
#   E2E_ARTIFACT_DIR        screenshots (default build/e2e)
#   CHROMIUM_PATH           the browser (default /usr/bin/chromium, installed with apt if missing)
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
# shellcheck source=scripts/lib/start_cutcalc.sh
source "$ROOT/scripts/lib/start_cutcalc.sh"
TOOLS=$ROOT/tools/e2e
BIN=${CUTCALC_BIN:-$ROOT/build/release/service/cutcalc}
CHROMIUM=${CHROMIUM_PATH:-/usr/bin/chromium}
export E2E_ARTIFACT_DIR=${E2E_ARTIFACT_DIR:-$ROOT/build/e2e}
STARTED=$(date +%s)

export NO_UPDATE_NOTIFIER=1 npm_config_update_notifier=false npm_config_fund=false npm_config_audit=false
# Playwright must never fetch a browser of its own.
export PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1

WORK=$(mktemp -d)
CUTCALC_PID=
cleanup() {
  if [[ -n "$CUTCALC_PID" ]]; then
    kill "$CUTCALC_PID" 2>/dev/null || true
    wait "$CUTCALC_PID" 2>/dev/null || true
  fi
  rm -rf "$WORK"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

die() {
  echo "ci-e2e: $*" >&2
  exit 1
}

# ---------------------------------------------------------------- Chromium, Node.js, playwright-core
sudo_cmd=()
[[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
missing=()
[[ -x "$CHROMIUM" ]] || missing+=(chromium)
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)
# pdftotext and pdftoppm read the printed setup sheets (tests/e2e/print_sheet.test.mjs).
command -v pdftotext >/dev/null 2>&1 || missing+=(poppler-utils)
if ((${#missing[@]})); then
  [[ " ${missing[*]} " == *" chromium "* && "$CHROMIUM" != /usr/bin/chromium ]] &&
    die "CHROMIUM_PATH=$CHROMIUM does not exist"
  echo "=== e2e: installing ${missing[*]} (apt)"
  "${sudo_cmd[@]}" apt-get update
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
fi
[[ -x "$CHROMIUM" ]] || die "no browser at $CHROMIUM"
echo "=== e2e: npm ci (tools/e2e; node $(node --version), npm $(npm --version 2>/dev/null); $("$CHROMIUM" --version 2>/dev/null | head -n 1))"
(cd "$TOOLS" && npm ci --no-audit --no-fund --loglevel=error)
INSTALLED=$(date +%s)

# ---------------------------------------------------------------- cutcalc
start_cutcalc "$BIN" "$WORK/cutcalc.log" e2e
BIN=$CUTCALC_BIN
PORT=$CUTCALC_PORT
URL="http://127.0.0.1:$PORT"
# shellcheck disable=SC2016 # JavaScript, not shell
node -e '
  const url = process.argv[1];
  const deadline = Date.now() + 20000;
  (async () => {
    for (;;) {
      try { if ((await fetch(url + "/readyz")).ok) return; } catch {}
      if (Date.now() > deadline) { console.error(`ci-e2e: ${url}/readyz not ready within 20 s`); process.exit(1); }
      await new Promise(r => setTimeout(r, 100));
    }
  })();' "$URL" || { cat "$WORK/cutcalc.log" >&2; exit 1; }

# ---------------------------------------------------------------- the browser test
tests=(tests/e2e/*.test.mjs)
echo "=== e2e: node --test ${tests[*]} (cutcalc $URL, $BIN)"
mkdir -p "$E2E_ARTIFACT_DIR"
rm -f "$E2E_ARTIFACT_DIR"/*.png
status=0
CUTCALC_URL=$URL CUTCALC_BIN=$BIN CHROMIUM_PATH=$CHROMIUM node --test --test-reporter=spec "${tests[@]}" || status=$?
kill -0 "$CUTCALC_PID" 2>/dev/null || { tail -n 30 "$WORK/cutcalc.log" >&2; echo "ci-e2e: cutcalc died during the test" >&2; status=1; }
ENDED=$(date +%s)
if [[ $status -ne 0 ]]; then
  echo "=== e2e: FAILED ($((ENDED - STARTED)) s)" >&2
  exit 1
fi
shots=$(find "$E2E_ARTIFACT_DIR" -maxdepth 1 -name '*.png' -printf '%f ')
echo "=== e2e: passed ($((ENDED - INSTALLED)) s after npm ci, $((ENDED - STARTED)) s in all); screenshots in ${E2E_ARTIFACT_DIR#"$ROOT"/}: ${shots:-none}"
