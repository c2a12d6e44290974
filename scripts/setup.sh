#!/usr/bin/env bash
# Installs the Debian packages cutcalc needs (only the missing ones, so re-runs are quick).
#   scripts/setup.sh            everything the tests need (the service's packages, the tests'
#                               packages, Node.js and the contract checker's npm packages)
#   scripts/setup.sh --service  only what building and running the service needs (scripts/run.sh)
set -euo pipefail
cd "$(dirname "$0")/.."

lists=(scripts/debian-packages-service.txt)
[[ ${1:-} == --service ]] || lists+=(scripts/debian-packages.txt)
mapfile -t packages < <(cat "${lists[@]}" | grep -v '^\s*#' | grep -v '^\s*$')
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]})); then
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  echo "setup: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
fi

[[ ${1:-} == --service ]] && exit 0

# The tests' contract checker is Node.js code (tools/contract: Ajv). Its locked packages are
# installed here, by the setup step, never by the build (again only when package-lock.json is newer
# than the installed tree).
contract_tools=tools/contract
# shellcheck source=scripts/lib/ensure_node.sh
source scripts/lib/ensure_node.sh
ensure_node setup
if [[ ! -f $contract_tools/node_modules/.package-lock.json ||
      $contract_tools/package-lock.json -nt $contract_tools/node_modules/.package-lock.json ]]; then
  echo "setup: npm ci in $contract_tools"
  (cd "$contract_tools" && NO_UPDATE_NOTIFIER=1 npm ci --no-audit --no-fund --loglevel=error)
fi
