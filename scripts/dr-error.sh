#!/usr/bin/env bash
# Dead-reckoning error of remote entities under loss (issue 11; README "Faults"): two nodes in
# network namespaces of their own on a bridge, every frame a node sends impaired in user space
# as in scripts/faults.sh (scripts/linkshaper.py: loss LOSS %, duplicated 5 %, reordered 25 %,
# delayed 20 ms +- 10 ms), no other fault. Both run the bundled scenarios/fhl/fhl.toml (node 1:
# tank1, ship1, jet1; node 2: jeep1, heli1, all moving over the GeoTIFF terrain) from a common
# --start-at with --track-every 0.1 (every tick); then `npsnet dr-error` compares each node's
# copies of the other's vehicles with their true positions at the same frame, from both logs.
# Needs root, iproute2, python3 with /dev/net/tun and a built build/npsnet.
#
# Usage: scripts/dr-error.sh [--control] [--loss PERCENT] [--seconds S] [--out DIR]
#   --control   clean links (no loss, duplication, reordering or delay): the reference
# Exit: 0 with the figures printed, 1 when a node or the tool failed, 2 bad arguments, 77 when
# this machine cannot run it. Everything it creates is named with a per-run prefix and removed
# by name on exit.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
OUT=""
CONTROL=0
LOSS=20
RUN_S=30
while [ $# -gt 0 ]; do
  case "$1" in
    --control) CONTROL=1 ;;
    --out) OUT="$2"; shift ;;
    --loss) LOSS="$2"; shift ;;
    --seconds) RUN_S="$2"; shift ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    *) echo "dr-error: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
TOOL=dr-error
# shellcheck source=scripts/netns_lib.sh
source "$ROOT/scripts/netns_lib.sh"
shaped_lan_preflight dr-error

P="ndr$(( $$ % 100000 ))"
PORT=$(( 20000 + $$ % 40000 ))
SCENARIO="$ROOT/scenarios/fhl/fhl.toml"
trap shaped_lan_cleanup EXIT
trap 'exit 1' INT TERM
fault_shape "$LOSS" "$CONTROL"
shaped_lan "$P" 2 10.216.0 "${SHAPE[@]}"

T0=$(( $(date +%s) + 4 ))  # the scenario loads in well under that
echo "dr-error: $([ "$CONTROL" = 1 ] && echo 'control run (clean links)' || echo "loss ${LOSS} %, dup 5 %, reorder 25 %, delay 20+-10 ms on both links"), ${RUN_S} s; out $OUT" >&2
for k in 1 2; do
  ip netns exec "${P}n$k" "$NPSNET" run --scenario "$SCENARIO" --no-render --quiet --net "udp://239.1.2.3:$PORT" \
    --iface "10.216.0.$((10 + k))" --node "$k" --site 1 --app "$k" --start-at "$T0" --seconds "$RUN_S" \
    --track-every 0.1 --events "$OUT/events_n$k.jsonl" --snapshots "$OUT/snap_$k" > "$OUT/out_n$k.txt" 2>&1 &
  PIDS+=($!)
done
rc=0
wait_nodes $(( T0 + RUN_S + 30 )) "${PIDS[@]}" || rc=1
PIDS=()
stop_shapers
"$NPSNET" dr-error "$OUT/events_n1.jsonl" "$OUT/events_n2.jsonl" || rc=1
exit "$rc"
