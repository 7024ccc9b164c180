#!/usr/bin/env bash
# Every test: install, build, run ctest; then the engine rooms' tests (core, world, dynamics,
# collision, input, record, net, the FCL oracle, the fuzz replays that need no node) under
# AddressSanitizer + UndefinedBehaviorSanitizer: NPSNET_SANITIZE_ROOMS=all builds and runs every
# test there instead (about an hour more), NPSNET_NO_SANITIZE=1 skips the stage; then each
# libFuzzer target (ASan + UBSan, the node's datagrams and checkpoints among them) from its seeds,
# a repeatable run of NPSNET_FUZZ_RUNS inputs (default 3000) capped at NPSNET_FUZZ_SECONDS
# (default 15) each (skip with NPSNET_NO_FUZZ=1). Each stage prints its minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
t0=$SECONDS
stage() { echo "== test.sh: $1 ($(( (SECONDS - t0) / 60 )) min so far)"; }
# What the last build took from ccache (scripts/ccache.sh), when it is used; then zeroes the count.
cached() {
  [ "$ccache_on" = 1 ] || return 0
  ccache --print-stats | awk -v tree="$1" '{ s[$1] = $2 } END {
    hits = s["direct_cache_hit"] + s["preprocessed_cache_hit"]; misses = s["cache_miss"]
    printf "== test.sh: ccache, %s: Hits %d Misses %d of %d compiles\n", tree, hits, misses, hits + misses }'
  ccache -z >/dev/null
}
bash scripts/install-deps.sh
source scripts/ccache.sh  # after install-deps.sh, which installs ccache
if [ "$ccache_on" = 1 ]; then ccache -z >/dev/null; fi
stage "build"
bash scripts/build.sh build
cached build
stage "ctest"
# Under a virtual display when xvfb-run exists, so the GLFW window test runs too.
XVFB=""
if command -v xvfb-run >/dev/null 2>&1 && [ -z "${DISPLAY:-}" ]; then XVFB="xvfb-run -a"; fi
(cd build && $XVFB ctest --output-on-failure -j2 --timeout 600)
if [ "${NPSNET_NO_SANITIZE:-0}" != "1" ]; then
  stage "ASan + UBSan build and ctest, rooms: ${NPSNET_SANITIZE_ROOMS:-engine}"
  bash scripts/build.sh build-asan -DNPSNET_SANITIZE=ON -DNPSNET_BENCH=OFF \
    -DNPSNET_ROOMS="${NPSNET_SANITIZE_ROOMS:-engine}"
  cached build-asan
  (cd build-asan && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j2 --timeout 900)
fi
if [ "${NPSNET_NO_FUZZ:-0}" != "1" ]; then
  stage "fuzz"
  NPSNET_FUZZ_RUNS="${NPSNET_FUZZ_RUNS:-3000}" bash scripts/fuzz.sh "${NPSNET_FUZZ_SECONDS:-15}"
  cached build-fuzz
fi
stage "done"
