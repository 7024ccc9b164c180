#!/usr/bin/env bash
# The main job: install, build, run the default scenario headless. Writes the event log
# (screenshots/events.jsonl) and the snapshot PNGs into screenshots/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh build
./build/npsnet run --scenario scenarios/default.toml --snapshots screenshots --events screenshots/events.jsonl "$@"
