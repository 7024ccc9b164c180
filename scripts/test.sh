#!/usr/bin/env bash
# Every test: install, build, run ctest; then the same tests under AddressSanitizer +
# UndefinedBehaviorSanitizer (skip that part with NPSNET_NO_SANITIZE=1); then each libFuzzer
# target from its seeds, a repeatable run of NPSNET_FUZZ_RUNS inputs (default 3000) capped at
# NPSNET_FUZZ_SECONDS (default 15) each (skip with NPSNET_NO_FUZZ=1).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh build
# Under a virtual display when xvfb-run exists, so the GLFW window test runs too.
XVFB=""
if command -v xvfb-run >/dev/null 2>&1 && [ -z "${DISPLAY:-}" ]; then XVFB="xvfb-run -a"; fi
(cd build && $XVFB ctest --output-on-failure -j2 --timeout 600)
if [ "${NPSNET_NO_SANITIZE:-0}" != "1" ]; then
  bash scripts/build.sh build-asan -DNPSNET_SANITIZE=ON -DNPSNET_BENCH=OFF
  (cd build-asan && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j2 --timeout 900)
fi
if [ "${NPSNET_NO_FUZZ:-0}" != "1" ]; then
  NPSNET_FUZZ_RUNS="${NPSNET_FUZZ_RUNS:-3000}" bash scripts/fuzz.sh "${NPSNET_FUZZ_SECONDS:-15}"
fi
