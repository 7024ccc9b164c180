#!/usr/bin/env bash
# Four nodes on a faulty LAN in network namespaces (issue 11; README "Faults"). Needs root,
# iproute2, python3 with /dev/net/tun, and a built build/npsnet.
#
#   hub namespace: bridge br0 ── p1 ═ linkshaper ═ eth0 (node 1 namespace, 10.215.0.11)
#                             ├─ p2 ═ linkshaper ═ eth0 (node 2, .12)   ... nodes 3 and 4
#
# Every frame a node sends is impaired in user space (scripts/linkshaper.py, as this kernel has
# no sch_netem): loss LOSS %, duplicated 5 %, reordered 25 %, delayed 20 ms +- 10 ms. On the
# scenario tests/multinode/data/faults.toml, from a common start (wall clock):
#   8 s - 18 s  node 2 cut off (a 10 s partition, then it heals)
#   12 s        node 3 killed with SIGKILL; 16 s: started again (same site, application, scenario)
#   30 s        node 4 starts (a late joiner)
# The restarted node and the late joiner are given the exercise's real start (--start-at T0): they
# join at its current time (run.cpp: their own scenario caught up headless, nothing replayed).
#   36 s        the faults stop (every link clean)
#   41 s        every node writes its world (--state-out, --state-at: one heartbeat after the faults)
#   42 s        every node ends
# Then every node must hold the same world: the same vehicles with the same damage states, the
# same changed objects, the same craters (tools: python3 compares the state files), and the same
# collisions across nodes with the same outcomes (each node's event log of its last run: pairs of
# vehicles of two nodes, by ids, with outcome_a and outcome_b). With
# --control the same exercise runs with no faults at all (nodes 1-4 from the start, no kill,
# no partition, clean links), the reference.
#
# Every node also logs every vehicle's position every tick (--track-every 0.1), and the script
# prints the dead-reckoning error of remote entities (npsnet dr-error, from all the nodes' logs)
# over 0-8 s (loss, duplication, reordering and delay only: no partition, kill or joiner yet) and
# over 36-41 s (after the faults stop).
#
# Usage: scripts/faults.sh [--control] [--out DIR] [--loss PERCENT]
# Environment: FAULTS_LEAD_S (default 6): the nodes are launched that many seconds before the
# exercise's start; one that comes up 2 s or more after it joins late, and the script says so.
# Exit: 0 when all four worlds agree, 1 when not (the differences are printed), 2 bad arguments,
# 77 when this machine cannot run it. Everything it creates is named with a per-run prefix and
# removed by name on exit.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
OUT=""
CONTROL=0
LOSS=20
while [ $# -gt 0 ]; do
  case "$1" in
    --control) CONTROL=1 ;;
    --out) OUT="$2"; shift ;;
    --loss) LOSS="$2"; shift ;;
    -h|--help) sed -n '2,29p' "$0"; exit 0 ;;
    *) echo "faults: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
TOOL=faults
# shellcheck source=scripts/netns_lib.sh
source "$ROOT/scripts/netns_lib.sh"
shaped_lan_preflight faults

P="nft$(( $$ % 100000 ))"
PORT=$(( 20000 + $$ % 40000 ))
SCENARIO="$ROOT/tests/multinode/data/faults.toml"
trap shaped_lan_cleanup EXIT
trap 'exit 1' INT TERM
fault_shape "$LOSS" "$CONTROL"
shaped_lan "$P" 4 10.215.0 "${SHAPE[@]}"

# The nodes start now and wait for T0: a lead of 6 s covers a node's start-up under a sanitizer
# on a busy machine (one came up 5.3 s after launch); a node up after T0 + 2 s would join at the
# exercise's time and hold the round scripted for 2 s, which the control run counts on.
T0=$(( $(date +%s) + ${FAULTS_LEAD_S:-6} ))
END=$(( T0 + 42 ))
node() {  # node K, run tag, start (UNIX s): runs until END
  local k=$1 tag=$2 start=$3
  ip netns exec "${P}n$k" env NPSNET_DIS_TIMEOUT_S="${NPSNET_DIS_TIMEOUT_S:-12}" "$NPSNET" run --scenario "$SCENARIO" \
    --no-render --quiet --net "udp://239.1.2.3:$PORT" --iface "10.215.0.$((10 + k))" --node "$k" --site 1 --app "$k" \
    --start-at "$start" --seconds "$(( END - start ))" --events "$OUT/events_$tag.jsonl" --snapshots "$OUT/snap_$tag" \
    --state-out "$OUT/state_$k.json" --state-at "$(( END - 1 - start ))" --track-every 0.1 \
    --checkpoint "$OUT/checkpoint_$k.jsonl" > "$OUT/out_$tag.txt" 2>&1 &
  PIDS+=($!)
}
at() { while [ "$(date +%s)" -lt "$(( T0 + $1 ))" ]; do sleep 0.05; done; }  # until T0 + S
sig_link() { kill "-$2" "${SHAPERS[$(( $1 - 1 ))]}"; }

echo "faults: $([ "$CONTROL" = 1 ] && echo 'control run (no faults)' || echo "loss ${LOSS} %, dup 5 %, reorder 25 %, delay 20+-10 ms on every link"); out $OUT" >&2
node 1 n1 "$T0"; node 2 n2 "$T0"; node 3 n3 "$T0"
[ "$CONTROL" = 1 ] && node 4 n4 "$T0"
if [ "$CONTROL" = 0 ]; then
  at 8;  echo "faults: t=8 node 2 cut off" >&2; sig_link 2 USR1
  at 12; echo "faults: t=12 node 3 killed (SIGKILL)" >&2; kill -KILL "${PIDS[2]}"; wait "${PIDS[2]}" 2>/dev/null || true
  at 16; echo "faults: t=16 node 3 started again (joins at the exercise time)" >&2; node 3 n3b "$T0"
  at 18; echo "faults: t=18 node 2 back (partition healed)" >&2; sig_link 2 USR2
  at 30; echo "faults: t=30 node 4 joins late" >&2; node 4 n4 "$T0"
  at 36; echo "faults: t=36 faults stop: every link clean" >&2; for k in 1 2 3 4; do sig_link "$k" HUP; done
fi
rc=0
LIVE=()
for pid in "${PIDS[@]}"; do
  [ "$pid" = "${PIDS[2]}" ] && [ "$CONTROL" = 0 ] && continue  # the killed one
  LIVE+=("$pid")
done
wait_nodes $(( END + 30 )) "${LIVE[@]}" || rc=1
PIDS=()
stop_shapers
LOGS=()
for f in "$OUT"/events_n1.jsonl "$OUT"/events_n2.jsonl "$OUT"/events_n3.jsonl "$OUT"/events_n3b.jsonl "$OUT"/events_n4.jsonl; do
  [ -s "$f" ] && LOGS+=("$f")
done
for window in "0 8" "36 41"; do
  set -- $window
  echo "faults: dead-reckoning error of remote entities, t = $1-$2 s (npsnet dr-error --from $1 --to $2 ${LOGS[*]##*/}):" >&2
  "$NPSNET" dr-error --from "$1" --to "$2" "${LOGS[@]}" >&2 || { echo "faults: npsnet dr-error failed" >&2; rc=1; }
done
python3 - "$OUT" "$SCENARIO" "$CONTROL" <<'PY' || rc=1
import json, os, sys, tomllib
out = sys.argv[1]
with open(sys.argv[2], "rb") as f:
    owner = {v["id"]: v["node"] for v in tomllib.load(f).get("vehicle", [])}

def collisions(k):  # cross-node collisions of node k's last run: sorted (a, b, outcome_a, outcome_b)
    path = "%s/events_n%db.jsonl" % (out, k)
    if not os.path.exists(path):
        path = "%s/events_n%d.jsonl" % (out, k)
    found = []
    with open(path) as f:
        for line in f:
            e = json.loads(line)
            if e.get("event") != "collision" or owner.get(e["a"]) is None or owner.get(e["b"]) is None:
                continue
            if owner[e["a"]] == owner[e["b"]]:
                continue
            a, b, oa, ob = e["a"], e["b"], e["outcome_a"], e["outcome_b"]
            found.append((a, b, oa, ob) if a < b else (b, a, ob, oa))
    return sorted(found)

worlds = {}
for k in (1, 2, 3, 4):
    with open("%s/state_%d.json" % (out, k)) as f:
        s = json.load(f)
    worlds[k] = {"vehicles": sorted((e["id"], e["state"]) for e in s["entities"]),
                 "fixed": sorted((o["id"], o["state"]) for o in s["fixed"]),
                 "craters": [tuple(c) for c in s["craters"]],
                 "collisions": collisions(k)}
ref = worlds[1]
# Nodes launched before the start (node 4 too in the control run): a node logs exercise_joined
# only when it came up too late to start with the exercise (run.cpp, kJoinAfterS).
for tag in ("n1", "n2", "n3") + (("n4",) if sys.argv[3] == "1" else ()):
    path = "%s/events_%s.jsonl" % (out, tag)
    if not os.path.exists(path):
        continue  # (no event log: nothing to say about its start)
    with open(path) as f:
        first = json.loads(f.readline() or "{}")
    if first.get("event") == "exercise_joined":
        print("faults: %s came up %.1f s after the start and joined late: its rounds and collisions "
              "before then are not in this run (raise FAULTS_LEAD_S)" % (tag, first["t"]), file=sys.stderr)
print("faults: node 1 world: %d vehicles %s, changed objects %s, craters %s"
      % (len(ref["vehicles"]), ref["vehicles"], ref["fixed"], ref["craters"]), file=sys.stderr)
print("faults: node 1 collisions across nodes: %s" % ref["collisions"], file=sys.stderr)
bad = 0
for k in (2, 3, 4):
    for what in ("vehicles", "fixed", "craters", "collisions"):
        if worlds[k][what] != ref[what]:
            bad += 1
            print("faults: node %d disagrees on %s: %s (node 1: %s)" % (k, what, worlds[k][what], ref[what]), file=sys.stderr)
if bad:
    sys.exit(1)
print("faults: OK: all four nodes hold the same world", file=sys.stderr)
PY
exit "$rc"
