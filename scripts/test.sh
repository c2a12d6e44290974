#!/usr/bin/env bash
# Sets up, then builds and runs every test twice: an optimised release build, and a Debug build
# with AddressSanitizer + UndefinedBehaviorSanitizer; then the service's tests (HTTP engine,
# framing, abuse, shutdown) a third time under ThreadSanitizer (the tsan preset). Any warning fails the build (-Werror); any
# test failure or sanitizer report fails the run. Then the fuzzers, the OpenAPI contract replay, the
# generated clients (codegen), the container and the Kubernetes manifests (each script says what it proves).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh

for preset in release dev tsan; do
  echo "=== ${preset}: configure and build"
  cmake --preset "$preset"
  cmake --build --preset "$preset"
  echo "=== ${preset}: test"
  ctest --preset "$preset" -j 2
done
echo "=== fuzz: every libFuzzer harness (ASan + UBSan) for a bounded time, seeded from the reference cases"
scripts/ci-fuzz.sh
echo "=== contract: lint openapi.yaml, replay every reference and bad-input case through Prism, then property-based requests from the request schemas"
scripts/ci-contract.sh
echo "=== codegen: openapi-typescript + openapi-fetch and @hey-api/openapi-ts clients, tsc --strict, every reference case against cutcalc"
scripts/ci-codegen.sh
echo "=== container: build the Dockerfile with podman, run it and replay the reference cases"
scripts/ci-container.sh
echo "=== Kubernetes manifests: render offline and validate"
scripts/ci-k8s.sh
echo "=== e2e: the web calculator in headless Chromium (Playwright) against a live release cutcalc"
scripts/ci-e2e.sh
echo "=== all tests passed"
