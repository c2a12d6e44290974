#!/usr/bin/env bash
# Sets up, then builds and runs every test twice: an optimised release build, and a Debug build
# with AddressSanitizer + UndefinedBehaviorSanitizer; then the service's tests (HTTP engine,
# framing, abuse, shutdown) a third time under ThreadSanitizer (the tsan preset). Any warning fails the build (-Werror); any
# test failure or sanitizer report fails the run. Then the fuzzers, the OpenAPI contract replay, the
# generated clients (codegen), the container and the Kubernetes manifests (each script says what it proves).
set -euo pipefail
cd "$(dirname "$0")/.."
# Each step's start, in seconds since this script began: CI must stay under 50 minutes, and a
# step that grows shows here first.
step() { echo "=== $1 (at ${SECONDS} s)"; }
scripts/setup.sh

for preset in release dev tsan; do
  step "${preset}: configure and build"
  cmake --preset "$preset"
  cmake --build --preset "$preset"
  step "${preset}: test"
  ctest --preset "$preset" -j 2
done
step "oracle: re-time 5 recorded programs with LinuxCNC 2.9's own planner, headless in simulation (tools/oracle)"
scripts/ci-oracle.sh
step "fuzz: every libFuzzer harness (ASan + UBSan) for a bounded time, seeded from the reference cases"
scripts/ci-fuzz.sh
step "contract: lint openapi.yaml, replay every reference and bad-input case through Prism, then property-based requests from the request schemas"
scripts/ci-contract.sh
step "codegen: openapi-typescript + openapi-fetch and @hey-api/openapi-ts clients, tsc --strict, every reference case against cutcalc"
scripts/ci-codegen.sh
step "container: build the Dockerfile with podman, run it and replay the reference cases"
scripts/ci-container.sh
step "Kubernetes manifests: render offline and validate"
scripts/ci-k8s.sh
step "e2e: the web calculator in headless Chromium (Playwright) against a live release cutcalc"
scripts/ci-e2e.sh
step "all tests passed"
