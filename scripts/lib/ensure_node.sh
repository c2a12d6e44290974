# shellcheck shell=bash
# Sourced by scripts/setup.sh and the CI steps that run Node.js tools, from the repository root.
#
# ensure_node STEP [MAJOR MINOR WHY]: installs Debian's nodejs and npm when either is missing (a
# NodeSource nodejs bundles npm and conflicts with Debian's npm package, so neither is in
# debian-packages.txt), then fails when Node.js is older than MAJOR.MINOR, saying WHY needs it.
ensure_node() {
  local step=$1 major=${2:-0} minor=${3:-0} why=${4:-}
  if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
    local sudo_cmd=()
    [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
    echo "=== $step: installing nodejs and npm (apt)"
    "${sudo_cmd[@]}" apt-get update
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y --no-install-recommends nodejs npm
  fi
  # shellcheck disable=SC2016 # JavaScript, not shell
  node -e '
    const [step, major, minor, why] = process.argv.slice(1);
    const [maj, min] = process.versions.node.split(".").map(Number);
    if (maj < Number(major) || (maj === Number(major) && min < Number(minor))) {
      console.error(`${step}: Node.js ${process.versions.node} is too old: ${why} needs >= ${major}.${minor}`);
      process.exit(1);
    }' "$step" "$major" "$minor" "$why"
}
