#!/usr/bin/env bash
# CI step for deploy/k8s (the kustomize base), fully offline after the installs:
#  1. installs what is missing: kubectl (Debian's kubernetes-client) and Node.js + npm (Debian's),
#     then `npm ci` in tools/k8s from its committed lock file;
#  2. renders the base with `kubectl kustomize deploy/k8s` (no cluster needed);
#  3. validates the rendered objects with tools/k8s/validate.mjs: Kubernetes schemas
#     (kubernetes-models), unknown/misspelled fields, and cutcalc's deployment rules;
#  4. proves the validator can fail: broken copies of the base (in a temp dir) must be rejected,
#     each with the expected message.
# Budget: well under 2 minutes after the installs (two cores shared). Exit non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
started=$SECONDS

work=$(mktemp -d)
cleanup() { rm -rf "$work"; }
trap cleanup EXIT

# ---------------------------------------------------------------- 1. dependencies
node_ok() { command -v node >/dev/null && command -v npm >/dev/null &&
  node -e 'process.exit(Number(process.versions.node.split(".")[0]) >= 18 ? 0 : 1)'; }
missing=()
command -v kubectl >/dev/null || missing+=(kubernetes-client)
node_ok || missing+=(nodejs npm)
if ((${#missing[@]})); then
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  echo "ci-k8s: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
  node_ok || { echo "ci-k8s: Node.js >= 18 with npm is required" >&2; exit 1; }
fi
kubectl_version=$(kubectl version --client 2>/dev/null | grep -o 'v[0-9]\+\.[0-9]\+\.[0-9]\+' | head -n 1 || true)
echo "ci-k8s: kubectl ${kubectl_version:-unknown}, node $(node --version), npm $(npm --version)"

# Reuse tools/k8s/node_modules when it was installed from this very lock file.
if ! cmp -s tools/k8s/package-lock.json tools/k8s/node_modules/.ci-k8s-lock 2>/dev/null; then
  (cd tools/k8s && npm ci --no-audit --no-fund --loglevel=error && cp package-lock.json node_modules/.ci-k8s-lock)
fi
install_done=$SECONDS

# ---------------------------------------------------------------- 2. + 3. render and validate
# kustomize v5 warns that commonLabels is deprecated; it is kept on purpose because Debian's
# kubectl (1.20, kustomize v2) does not know its replacement `labels:`. Other warnings show.
render() { # render DIR OUT
  if ! kubectl kustomize "$1" >"$2" 2>"$work/render.err"; then
    cat "$work/render.err" >&2
    return 1
  fi
  grep -v "'commonLabels' is deprecated" "$work/render.err" >&2 || true
}
validate() { node tools/k8s/validate.mjs "$@"; }

render deploy/k8s "$work/rendered.yaml"
echo "ci-k8s: rendered $(grep -c '^kind:' "$work/rendered.yaml") objects from deploy/k8s"
validate_out=$(validate "$work/rendered.yaml" 2>&1) || {
  echo "$validate_out" >&2
  echo "ci-k8s: deploy/k8s FAILED validation" >&2
  exit 1
}
echo "$validate_out"
checks=$(sed -n 's/^k8s: \([0-9]\+\) passed, 0 failed$/\1/p' <<<"$validate_out")

# ---------------------------------------------------------------- 4. the validator can fail
# broken NAME FILE SED_EXPRESSION EXPECTED_MESSAGE: a copy of the base with one edit, rendered;
# the validator (one process for all cases) must reject each with EXPECTED_MESSAGE.
expect=()
cases=0
broken() {
  local name=$1 file=$2 edit=$3 expected=$4 dir="$work/broken-$1"
  cases=$((cases + 1))
  cp -r deploy/k8s "$dir"
  sed -i "$edit" "$dir/$file"
  if cmp -s "deploy/k8s/$file" "$dir/$file"; then
    echo "ci-k8s: broken case '$name': the edit changed nothing in $file" >&2
  elif ! render "$dir" "$work/$name.yaml"; then
    echo "ci-k8s: broken case '$name' did not render" >&2
  else
    expect+=(--expect-reject "$expected" "$work/$name.yaml")
  fi
}
broken replicas-not-integer deployment.yaml 's/^  replicas: 2$/  replicas: "two"/' \
  'data/spec/replicas must be integer'
broken misspelled-field deployment.yaml 's/readinessProbe:/readinesProbe:/' \
  'did you mean "readinessProbe"'
broken misspelled-nested-field deployment.yaml \
  's/readOnlyRootFilesystem: true/readOnlyRootFileSystem: true/' \
  'did you mean "readOnlyRootFilesystem"'
broken unknown-kind hpa.yaml 's/^kind: HorizontalPodAutoscaler$/kind: HorizontalPodAutoScaler/' \
  'unknown kind autoscaling/v2/HorizontalPodAutoScaler'
broken writable-root deployment.yaml \
  's/readOnlyRootFilesystem: true/readOnlyRootFilesystem: false/' \
  'container cutcalc readOnlyRootFilesystem'
broken runs-as-root deployment.yaml 's/runAsUser: 10001/runAsUser: 0/g; s/runAsNonRoot: true/runAsNonRoot: false/g' \
  'container cutcalc runAsNonRoot'
broken no-memory-limit deployment.yaml '/memory: 256Mi/d' \
  'container cutcalc sets memory request and limit'
broken pdb-selects-nothing pdb.yaml 's|app.kubernetes.io/name: cutcalc|app.kubernetes.io/component: worker|' \
  'PodDisruptionBudget/cutcalc selector matches the pods'
broken hpa-wrong-target hpa.yaml 's/^    name: cutcalc$/    name: cutcalc-api/' \
  'HorizontalPodAutoscaler/cutcalc targets Deployment/cutcalc'
broken service-wrong-port service.yaml 's/targetPort: http/targetPort: 9090/' \
  'Service/cutcalc port http 80 -> 8080'
broken grace-too-short deployment.yaml \
  's/terminationGracePeriodSeconds: 30/terminationGracePeriodSeconds: 10/' \
  'terminationGracePeriodSeconds covers'

rejected=0
if ((${#expect[@]})); then
  broken_out=$(validate "${expect[@]}" 2>&1) && broken_rc=0 || broken_rc=$?
  echo "$broken_out"
  rejected=$(sed -n 's/^k8s-broken: \([0-9]\+\) passed, [0-9]\+ failed$/\1/p' <<<"$broken_out")
  ((broken_rc == 0)) || echo "ci-k8s: the validator accepted (or misreported) a broken variant" >&2
fi
failed=$((cases - ${rejected:-0}))
echo "ci-k8s: base valid (${checks:-?} checks), ${rejected:-0}/${cases} broken variants rejected;" \
  "$((install_done - started)) s install, $((SECONDS - install_done)) s render + validate"
echo "ci-k8s: $((${checks:-0} + ${rejected:-0})) passed, ${failed} failed"
((failed == 0))
