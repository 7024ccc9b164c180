#!/usr/bin/env bash
# Configures and builds into build/ (or $1 with extra CMake args after it), through ccache when
# installed (scripts/ccache.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${1:-build}"
shift || true
source scripts/ccache.sh
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${ccache_args[@]}" "$@" >/dev/null
cmake --build "$dir" -j2
