#!/usr/bin/env bash
# Container, proven: builds the repo's Dockerfile unchanged with podman and runs the image.
# No image registry is reachable, so the base image debian:bookworm-slim is made here first:
# debootstrap (minbase) from the Debian mirror apt uses on this machine, slimmed like the
# official -slim images, with its sources.list pointing at that same mirror, imported into
# podman. Then: build (docker format, so HEALTHCHECK is kept), run on a loopback port, and check
# non-root user, HEALTHCHECK (healthy when serving, unhealthy when not), probes, every reference
# case from ../shared/reference, the text/plain G-code, JSON log lines, graceful stop, image size.
#
# Runs as root (CI). Needs network access to the Debian mirror only. Podman storage
# (/var/lib/containers) may persist between runs: the base image is reused when it was made by
# this script from the same sources (CUTCALC_CONTAINER_FRESH_BASE=1 forces a new one), and the
# build's layer cache is used. Nothing is cached in the repository.
#
# Environment: CUTCALC_REFERENCE_DIR (default ../shared/reference from the repo root),
# CUTCALC_IMAGE_SIZE_LIMIT (bytes, default 150000000), CUTCALC_CONTAINER_FRESH_BASE=1.
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
export DEBIAN_FRONTEND=noninteractive
export CONTAINERS_CONF="$repo/scripts/container/containers.conf"

ref_dir=${CUTCALC_REFERENCE_DIR:-$repo/../shared/reference}
size_limit=${CUTCALC_IMAGE_SIZE_LIMIT:-150000000}
image=localhost/cutcalc:ci
base_tags=(debian:bookworm-slim docker.io/library/debian:bookworm-slim)
base_recipe=cutcalc-debootstrap-minbase-slim-v1   # bump when the base recipe below changes
run_name=cutcalc-ci-$$
probe_name=cutcalc-ci-probe-$$

work=""
cleanup() {
  local rc=$? n
  set +e
  # One name per call: podman 4.3's rm -f does nothing at all when one of several names is missing.
  for n in "$run_name" "$probe_name"; do
    podman container exists "$n" 2>/dev/null && podman rm -f -t 0 "$n" >/dev/null 2>&1
  done
  [[ -n "$work" ]] && rm -rf "$work"
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

fail() { echo "ci-container: FAIL: $*" >&2; exit 1; }
now() { date +%s; }
# podman without its systemd noise: with no systemd here it logs an error for every container
# that has a HEALTHCHECK (it cannot add the timer; the checks are run by hand below).
pm() {
  local rc=0
  podman "$@" 2>"$work/podman.err" || rc=$?
  grep -v 'unable to get systemd connection' "$work/podman.err" >&2 || true
  return "$rc"
}
t_start=$(now)

# ---------------------------------------------------------------- dependencies
echo "=== container: dependencies [$(date -u +%T)]"
pkgs=(podman buildah runc debootstrap containernetworking-plugins iptables uidmap
      python3 curl ca-certificates debian-archive-keyring)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
  apt-get install -y --no-install-recommends "${missing[@]}" \
    || { apt-get update && apt-get install -y --no-install-recommends "${missing[@]}"; }
fi
py=/usr/bin/python3
# The replayer is tools/contract's (Node.js, its locked packages).
command -v node >/dev/null 2>&1 || apt-get install -y --no-install-recommends nodejs npm
[[ -f tools/contract/node_modules/.package-lock.json ]] \
  || (cd tools/contract && npm ci --no-audit --no-fund --loglevel=error)
t_deps=$(now)

work=$(mktemp -d /var/tmp/cutcalc-container.XXXXXX)

# ---------------------------------------------------------------- base image
echo "=== container: base image debian:bookworm-slim (debootstrap minbase) [$(date -u +%T)]"
mirror=$("$py" scripts/container/apt_sources.py mirror)
mirror_keyring=$("$py" scripts/container/apt_sources.py mirror-keyring)
"$py" scripts/container/apt_sources.py sources-list >"$work/sources.list"
base_id=$( { echo "$base_recipe"; cat "$work/sources.list"; } | sha256sum | cut -c1-16)
have_base=""
if [[ "${CUTCALC_CONTAINER_FRESH_BASE:-0}" != 1 ]] \
   && podman image exists "${base_tags[1]}" \
   && [[ "$(podman image inspect --format '{{index .Labels "org.cutcalc.base"}}' "${base_tags[1]}")" == "$base_id" ]]; then
  have_base=yes
  for t in "${base_tags[@]}"; do podman tag "${base_tags[1]}" "$t"; done
  echo "reusing base image ${base_id} from podman storage"
fi
if [[ -z "$have_base" ]]; then
  rootfs="$work/rootfs"
  echo "debootstrap --variant=minbase bookworm from ${mirror}"
  keyring_arg=()
  [[ -n "$mirror_keyring" ]] && keyring_arg=(--keyring="$mirror_keyring")
  timeout 600 debootstrap --variant=minbase "${keyring_arg[@]}" bookworm "$rootfs" "$mirror" \
    >"$work/debootstrap.log" 2>&1 \
    || { tail -n 40 "$work/debootstrap.log"; fail "debootstrap"; }
  # Same mirror as the host (and its keyrings if they are not the stock Debian one).
  install -m 0644 "$work/sources.list" "$rootfs/etc/apt/sources.list"
  rm -f "$rootfs"/etc/apt/sources.list.d/*
  while read -r k; do
    [[ -n "$k" && ! -e "$rootfs$k" ]] && install -D -m 0644 "$k" "$rootfs$k"
  done < <("$py" scripts/container/apt_sources.py keyrings)
  # Slim it like the official -slim images: no docs/man/locales now or from later installs,
  # no apt lists or caches.
  cat >"$rootfs/etc/dpkg/dpkg.cfg.d/docker-slim" <<'EOF'
path-exclude /usr/share/doc/*
path-include /usr/share/doc/*/copyright
path-exclude /usr/share/man/*
path-exclude /usr/share/groff/*
path-exclude /usr/share/info/*
path-exclude /usr/share/lintian/*
path-exclude /usr/share/linda/*
path-exclude /usr/share/locale/*
EOF
  cat >"$rootfs/etc/apt/apt.conf.d/docker-clean" <<'EOF'
DPkg::Post-Invoke { "rm -f /var/cache/apt/archives/*.deb /var/cache/apt/archives/partial/*.deb /var/cache/apt/*.bin || true"; };
APT::Update::Post-Invoke { "rm -f /var/cache/apt/archives/*.deb /var/cache/apt/archives/partial/*.deb /var/cache/apt/*.bin || true"; };
Dir::Cache::pkgcache "";
Dir::Cache::srcpkgcache "";
EOF
  echo 'Acquire::Languages "none";' >"$rootfs/etc/apt/apt.conf.d/docker-no-languages"
  find "$rootfs/usr/share/doc" -mindepth 1 ! -type d ! -name copyright -delete
  find "$rootfs/usr/share/doc" -mindepth 1 -type d -empty -delete
  rm -rf "$rootfs"/usr/share/{man,groff,info,lintian,linda,locale}/* \
         "$rootfs"/var/lib/apt/lists/* "$rootfs"/var/cache/apt/*.bin \
         "$rootfs"/var/cache/apt/archives/*.deb "$rootfs"/var/cache/apt/archives/partial/* \
         "$rootfs"/var/log/*.log "$rootfs"/var/log/apt/* \
         "$rootfs"/var/cache/debconf/*-old "$rootfs"/var/lib/dpkg/*-old "$rootfs"/tmp/*
  tar -C "$rootfs" --numeric-owner -c . \
    | podman import --quiet \
        --change 'ENV PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin' \
        --change 'CMD ["bash"]' \
        --change "LABEL org.cutcalc.base=${base_id}" \
        - "${base_tags[0]}" >/dev/null
  podman tag "${base_tags[0]}" "${base_tags[1]}"
  rm -rf "$rootfs"
fi
base_size=$(podman image inspect --format '{{.Size}}' "${base_tags[0]}")
t_base=$(now)

# ---------------------------------------------------------------- build
echo "=== container: podman build (Dockerfile unchanged) [$(date -u +%T)]"
commit=$(git rev-parse HEAD 2>/dev/null || echo unknown)
old_image=$(podman image inspect --format '{{.Id}}' "$image" 2>/dev/null || true)
# --format docker: the OCI image format has no HEALTHCHECK; podman would drop it.
timeout 1200 podman build --pull=never --format docker --layers \
    --build-arg CUTCALC_GIT_COMMIT="$commit" -t "$image" -f Dockerfile . \
    >"$work/build.log" 2>&1 \
  || { tail -n 60 "$work/build.log"; fail "podman build"; }
new_image=$(podman image inspect --format '{{.Id}}' "$image")
if [[ -n "$old_image" && "$old_image" != "$new_image" ]]; then
  podman rmi "$old_image" >/dev/null 2>&1 || true   # the previous run's image, now untagged
fi
size=$(podman image inspect --format '{{.Size}}' "$image")
t_build=$(now)

# ---------------------------------------------------------------- run and check
echo "=== container: run and check [$(date -u +%T)]"
inspect_image() { podman image inspect "$image" | "$py" -c "$1"; }
image_user=$(podman image inspect --format '{{.Config.User}}' "$image")
[[ -n "$image_user" && "${image_user%%:*}" != 0 && "${image_user%%:*}" != root ]] \
  || fail "image USER is '${image_user}' (must be a non-root user)"
inspect_image 'import json,sys; h=json.load(sys.stdin)[0].get("Healthcheck") or {}; sys.exit(0 if h.get("Test") and h["Test"][0] != "NONE" else 1)' \
  || fail "image has no HEALTHCHECK"

port=$("$py" -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
base="http://127.0.0.1:${port}"
pm run -d --pull=never --name "$run_name" -p "127.0.0.1:${port}:8080" "$image" >/dev/null
up=""
for _ in $(seq 1 60); do
  if curl -fsS -m 2 -o /dev/null "$base/healthz" 2>/dev/null; then up=yes; break; fi
  [[ "$(podman inspect --format '{{.State.Running}}' "$run_name")" == true ]] || break
  sleep 0.5
done
[[ -n "$up" ]] || { podman logs "$run_name" | tail -n 20; fail "container did not answer /healthz"; }

uid=$(podman exec "$run_name" id -u)
[[ "$uid" =~ ^[0-9]+$ && "$uid" != 0 ]] || fail "podman exec id -u gave '${uid}'"
pid1_user=$(podman top "$run_name" huser | awk 'NR == 2 {print $1}')
[[ -n "$pid1_user" && "$pid1_user" != 0 && "$pid1_user" != root ]] \
  || fail "the service process runs as '${pid1_user}'"

pm healthcheck run "$run_name" >/dev/null || fail "HEALTHCHECK failed on the running service"
health=$(podman inspect --format '{{.State.Health.Status}}' "$run_name" 2>/dev/null \
         || podman inspect --format '{{.State.Healthcheck.Status}}' "$run_name")
[[ "$health" == healthy ]] || fail "health status '${health}' after a passing check"
# The check must also fail when nothing serves :8080 (same image, service not started).
pm run -d --pull=never --name "$probe_name" --entrypoint sleep "$image" 120 >/dev/null
if pm healthcheck run "$probe_name" >/dev/null; then
  fail "HEALTHCHECK passed with no service running"
fi
pm rm -f -t 0 "$probe_name" >/dev/null

for path in /healthz /readyz /metrics /openapi.yaml; do
  code=$(curl -sS -m 5 -o /dev/null -w '%{http_code}' "$base$path")
  [[ "$code" == 200 ]] || fail "GET $path: HTTP $code"
done
curl -fsS -m 5 -o "$work/openapi.yaml" "$base/openapi.yaml"
head -n 1 "$work/openapi.yaml" | grep -q '^openapi:' || fail "GET /openapi.yaml body"
version=$(curl -fsS -m 5 "$base/version")
if [[ "$commit" != unknown ]]; then
  grep -q "\"commit\":\"${commit}\"" <<<"$version" || fail "/version does not name ${commit}: ${version}"
fi

# The one reference replayer (values, warnings, pointers, program facts, openapi.yaml).
# The reference files: reference/*.json plus the next/ files the image's route table lists.
pm run --rm --pull=never "$image" --routes >"$work/routes.json" || fail "cutcalc --routes in the image"
node tools/contract/replay.mjs --base-url "$base" --reference-dir "$ref_dir" --routes "$work/routes.json" \
  | tee "$work/replay.log" \
  || fail "reference cases (see above)"
replay_line=$(tail -n 1 "$work/replay.log")

gcode_type=$(curl -fsS -m 10 -o "$work/hole.ngc" -w '%{content_type}' -X POST \
  -H 'Content-Type: application/json' -H 'Accept: text/plain' \
  -d '{"faces":4,"inscribed_diameter_mm":16.0,"depth_mm":0.2,"step_down_mm":0.1,"spindle_speed_rpm":30}' \
  "$base/v1/polygon-hole/gcode")
if [[ "$gcode_type" != text/plain* ]] || ! head -n 1 "$work/hole.ngc" | grep -q '^%'; then
  fail "text/plain G-code: Content-Type '${gcode_type}', first line '$(head -n 1 "$work/hole.ngc")'"
fi

# Graceful stop: SIGTERM (STOPSIGNAL) must end the service with status 0 well within the timeout.
t0=$(date +%s.%N)
pm stop -t 20 "$run_name" >/dev/null
stop_s=$("$py" -c "print(f'{$(date +%s.%N) - $t0:.1f}')")
exit_code=$(podman inspect --format '{{.State.ExitCode}}' "$run_name")
[[ "$exit_code" == 0 ]] || fail "the service exited with status ${exit_code} on podman stop"
# CUTCALC_LOG_FORMAT=json in the image: every log line must be one JSON object.
podman logs "$run_name" >"$work/service.log" 2>&1
"$py" - "$work/service.log" <<'EOF' || fail "the container's log lines are not all JSON objects"
import json, sys
lines = [l for l in open(sys.argv[1], encoding="utf-8", errors="replace").read().splitlines() if l.strip()]
bad = []
for l in lines:
    try:
        if not isinstance(json.loads(l), dict):
            bad.append(l)
    except ValueError:
        bad.append(l)
for l in bad[:5]:
    print("  not a JSON object:", l)
print(f"  log: {len(lines) - len(bad)}/{len(lines)} lines are JSON objects")
sys.exit(1 if bad or not lines else 0)
EOF
pm rm "$run_name" >/dev/null
t_run=$(now)

# ---------------------------------------------------------------- size
mb() { "$py" -c "print(f'{$1 / 1e6:.1f}')"; }
((size < size_limit)) || fail "image is $(mb "$size") MB, limit $(mb "$size_limit") MB"

echo "container: OK: image $(mb "$size") MB (< $(mb "$size_limit") MB; base $(mb "$base_size") MB)," \
     "user ${image_user}, healthcheck healthy/unhealthy as expected, ${replay_line#replay: }," \
     "stop ${stop_s}s exit 0;" \
     "times: deps $((t_deps - t_start))s base $((t_base - t_deps))s${have_base:+ (reused)}" \
     "build $((t_build - t_base))s run+checks $((t_run - t_build))s total $((t_run - t_start))s"
