#!/usr/bin/env bash
# Every test: install, build, run ctest; then the same tests under AddressSanitizer +
# UndefinedBehaviorSanitizer (skip that part with NPSNET_NO_SANITIZE=1).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh build
(cd build && ctest --output-on-failure -j2 --timeout 600)
if [ "${NPSNET_NO_SANITIZE:-0}" != "1" ]; then
  bash scripts/build.sh build-asan -DNPSNET_SANITIZE=ON -DNPSNET_BENCH=OFF
  (cd build-asan && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j2 --timeout 900)
fi
