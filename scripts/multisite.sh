#!/usr/bin/env bash
# Routed multi-site DIS exercise in network namespaces (issue 14; README "Routed multi-site
# exercise"). Needs root, iproute2, smcroute and a built build/npsnet.
#
#   site 1 LAN (bridge br0)        router namespace (smcrouted)         site 2 LAN, site 3 LAN
#   node ns 10.214.1.11 ─┐                                               (10.214.2.x, 10.214.3.x)
#   node ns 10.214.1.12 ─┼─ br0 ── wan ═══ r1 10.214.1.1  r2 10.214.2.1 ═══ ...
#   ...                  ┘                 r3 10.214.3.1
#
# Every node runs `npsnet run --net udp://239.1.2.3:PORT --iface <its address> --ttl 8 --aoi CELL`
# in its own namespace on tests/multinode/data/multisite.toml; the router forwards the exercise's
# groups (239.1.0.0/16) between the three sites with static (*,G) routes (smcrouted). Each site
# link delays every frame by DELAY ms and loses LOSS % of them, each way: with netem when the
# kernel has sch_netem, else in user space (scripts/linkshaper.py: a TAP pair and a forwarding
# process instead of the veth pair), else (no python3 or /dev/net/tun) unshaped except a tbf
# 10 Mbit/s rate; the script says which. Everything it creates (namespaces, bridges, veths,
# the daemon, the nodes) is named with a per-run prefix and removed by name on exit (trap).
#
# The nodes run with NPSNET_DIS_TIMEOUT_S=4.8 (heartbeat 2 s; override by setting it): a kernel
# multicast router queues at most 10 datagrams of (source, group) pairs it has no route for yet,
# so at start-up, when every node sends its first Entity States into new groups at once, the rest
# are dropped and the entity is heard at its next heartbeat.
#
# Usage: scripts/multisite.sh [--short] [--nodes N] [--seconds S] [--aoi CELL_M|0] [--out DIR]
#                             [--scenario FILE] [--delay-ms D] [--loss PERCENT]
#   --short      2 nodes a site, 8 s, no loss (the ctest run: a lost Detonation is never sent again)
#   --delay-ms, --loss   each site link, each way (default 30 ms, 1 %)
#   --nodes N    nodes a site (1-4, default 4: 12 nodes); the scenario's node numbers are
#                4 x (site - 1) + k, k = 1..N
#   --aoi        cell size in metres (default 2000); 0 runs without area of interest
# Exit: 0 when every node ran and the cross-site collision and the crater are in the event log of
# every node with a vehicle in the battle area (nodes 1 and 2 of each site; with --aoi 0 every
# node), and not in those of nodes 3 and 4 (whose vehicles are all 12+ km away) with --aoi;
# 1 when not, 2 bad arguments, 77 when this machine cannot run it (not root, no smcrouted, ...).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)

NODES=4
SECONDS_RUN=20
AOI=2000
OUT=""
SCENARIO="$ROOT/tests/multinode/data/multisite.toml"
DELAY=30
LOSS=1
while [ $# -gt 0 ]; do
  case "$1" in
    --short) NODES=2; SECONDS_RUN=8; LOSS=0 ;;
    --delay-ms) DELAY="$2"; shift ;;
    --loss) LOSS="$2"; shift ;;
    --nodes) NODES="$2"; shift ;;
    --seconds) SECONDS_RUN="$2"; shift ;;
    --aoi) AOI="$2"; shift ;;
    --out) OUT="$2"; shift ;;
    --scenario) SCENARIO="$2"; shift ;;
    -h|--help) sed -n '2,34p' "$0"; exit 0 ;;
    *) echo "multisite: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
case "$NODES" in 1|2|3|4) ;; *) echo "multisite: --nodes must be 1-4" >&2; exit 2 ;; esac

TOOL=multisite
# shellcheck source=scripts/netns_lib.sh
source "$ROOT/scripts/netns_lib.sh"
netns_preflight
command -v smcrouted >/dev/null || skip "smcroute is not installed (scripts/install-deps.sh)"
# smcrouted only asks the kernel to forward (without it every route is rejected: README).
[ -e /proc/net/ip_mr_vif ] || skip "this kernel has no IPv4 multicast routing (CONFIG_IP_MROUTE; no /proc/net/ip_mr_vif): smcrouted cannot forward between sites"

P="nms$(( $$ % 100000 ))"          # per-run prefix of every namespace
R="${P}r"
[ -n "$OUT" ] || OUT=$(mktemp -d /tmp/npsnet-multisite.XXXXXX)
mkdir -p "$OUT"
PORT=$(( 20000 + $$ % 40000 ))
DAEMON_PID=""

cleanup() {
  set +e
  stop_processes
  [ -n "$DAEMON_PID" ] && kill -TERM "$DAEMON_PID" 2>/dev/null && wait "$DAEMON_PID" 2>/dev/null
  # Links by name first (a veth takes its peer with it), then the namespaces by name.
  ip -n "$R" link del probe0 2>/dev/null
  for s in 1 2 3; do
    ip -n "$R" link del "r$s" 2>/dev/null
    ip -n "${P}s$s" link del wan 2>/dev/null
    ip -n "${P}s$s" link del br0 2>/dev/null
    for k in 1 2 3 4; do ip -n "${P}s$s" link del "n$k" 2>/dev/null; done
  done
  netns_remove_all
}
trap cleanup EXIT
trap 'exit 1' INT TERM

# ---- topology
newns "$R"
ip netns exec "$R" sysctl -qw net.ipv4.ip_forward=1
# How the site links are shaped: netem if the kernel has it, else in user space, else tbf only.
ip -n "$R" link add probe0 type veth peer name probe1
if err=$(ip netns exec "$R" tc qdisc add dev probe0 root netem delay 1ms 2>&1); then
  MODE=netem; SHAPING="netem delay ${DELAY}ms loss ${LOSS}% on both ends of each site link"
elif command -v python3 >/dev/null && [ -c /dev/net/tun ]; then
  MODE=user; SHAPING="user space (scripts/linkshaper.py): ${DELAY} ms, ${LOSS} % loss each way on each site link"
else
  MODE=tbf; SHAPING="tbf rate 10mbit only: no delay, no loss"
fi
ip -n "$R" link del probe0
[ "$MODE" = netem ] || echo "multisite: netem unavailable ('$err'): this kernel has no sch_netem; site links shaped $SHAPING" >&2
for s in 1 2 3; do
  S="${P}s$s"
  newns "$S"
  ip -n "$S" link add br0 type bridge mcast_snooping 0   # a plain LAN: multicast floods
  ip -n "$S" link set br0 up
  if [ "$MODE" = user ]; then   # TAP wan (site) <-> TAP r$s (router), frames carried by linkshaper.py
    rm -f "$OUT/linkshaper_s$s.log"   # a log of an earlier run in the same --out must not say ready
    ip netns exec "$S" python3 "$ROOT/scripts/linkshaper.py" wan "r$s" "$R" "$DELAY" "$LOSS" "$s" \
      > "$OUT/linkshaper_s$s.log" 2>&1 &
    SHAPERS+=($!)
    for _ in $(seq 1 50); do grep -qs ready "$OUT/linkshaper_s$s.log" && break; sleep 0.1; done
    grep -q ready "$OUT/linkshaper_s$s.log" || { cat "$OUT/linkshaper_s$s.log" >&2; exit 1; }
  else
    ip link add "r$s" netns "$R" type veth peer name wan netns "$S"
  fi
  ip -n "$S" link set wan master br0
  ip -n "$S" link set wan up
  ip -n "$R" addr add "10.214.$s.1/24" dev "r$s"
  ip -n "$R" link set "r$s" up
  if [ "$MODE" = netem ]; then
    ip netns exec "$R" tc qdisc add dev "r$s" root netem delay "${DELAY}ms" loss "${LOSS}%"
    ip netns exec "$S" tc qdisc add dev wan root netem delay "${DELAY}ms" loss "${LOSS}%"
  elif [ "$MODE" = tbf ]; then
    ip netns exec "$R" tc qdisc add dev "r$s" root tbf rate 10mbit burst 32kbit latency 100ms
    ip netns exec "$S" tc qdisc add dev wan root tbf rate 10mbit burst 32kbit latency 100ms
  fi
  for k in $(seq 1 "$NODES"); do
    N="${P}s${s}n$k"
    newns "$N"
    ip link add "n$k" netns "$S" type veth peer name eth0 netns "$N"
    ip -n "$S" link set "n$k" master br0
    ip -n "$S" link set "n$k" up
    ip -n "$N" addr add "10.214.$s.$((10 + k))/24" dev eth0
    ip -n "$N" link set eth0 up
    ip -n "$N" route add default via "10.214.$s.1"
  done
done
echo "$SHAPING" > "$OUT/shaping.txt"
# What the shaping gives: site 1 -> site 2 round trip (4 link crossings), a UDP echo through the
# router (python3; median of 5).
RTT=""
if command -v python3 >/dev/null; then
  ip netns exec "${P}s2n1" timeout 5 python3 -c '
import socket
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("10.214.2.11", 7)); s.settimeout(4)
try:
    while True:
        d, a = s.recvfrom(64); s.sendto(d, a)
except OSError:
    pass' &
  ECHO_PID=$!
  sleep 0.5
  RTT=$(ip netns exec "${P}s1n1" timeout 5 python3 -c '
import socket, time
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.settimeout(1); r = []
for i in range(5):
    t = time.monotonic(); s.sendto(b"x", ("10.214.2.11", 7))
    try:
        s.recvfrom(64); r.append((time.monotonic() - t) * 1000)
    except OSError:
        pass
print("%.1f ms (%d of 5 answered)" % (sorted(r)[len(r) // 2], len(r)) if r else "")' || true)
  kill "$ECHO_PID" 2>/dev/null; wait "$ECHO_PID" 2>/dev/null || true
fi
echo "multisite: site 1 -> site 2 UDP round trip: ${RTT:-no answer}" >&2

# ---- the multicast router: static (*,G) routes for the exercise's groups between the sites
cat > "$OUT/smcroute.conf" <<EOF
phyint r1 enable
phyint r2 enable
phyint r3 enable
mroute from r1 group 239.1.0.0/16 to r2 r3
mroute from r2 group 239.1.0.0/16 to r1 r3
mroute from r3 group 239.1.0.0/16 to r1 r2
EOF
ip netns exec "$R" smcrouted -n -N -f "$OUT/smcroute.conf" -u "$OUT/smcroute.sock" -P "$OUT/smcroute.pid" \
  -l info > "$OUT/smcrouted.log" 2>&1 &
DAEMON_PID=$!
for _ in $(seq 1 50); do
  [ -S "$OUT/smcroute.sock" ] && break
  kill -0 "$DAEMON_PID" 2>/dev/null || { cat "$OUT/smcrouted.log" >&2; echo "multisite: smcrouted died" >&2; exit 1; }
  sleep 0.1
done

# ---- the nodes
AOI_ARGS=()
[ "$AOI" != "0" ] && AOI_ARGS=(--aoi "$AOI")
START=$(( $(date +%s) + 3 ))
TAGS=()
for s in 1 2 3; do
  for k in $(seq 1 "$NODES"); do
    n=$(( 4 * (s - 1) + k ))
    tag="s${s}n$k"
    TAGS+=("$tag")
    ip netns exec "${P}s${s}n$k" env NPSNET_DIS_TIMEOUT_S="${NPSNET_DIS_TIMEOUT_S:-4.8}" "$NPSNET" run --scenario "$SCENARIO" --no-render --quiet \
      --net "udp://239.1.2.3:$PORT" --iface "10.214.$s.$((10 + k))" --ttl 8 "${AOI_ARGS[@]}" \
      --node "$n" --site "$s" --app "$n" --start-at "$START" --seconds "$SECONDS_RUN" \
      --events "$OUT/events_$tag.jsonl" --snapshots "$OUT/snap_$tag" > "$OUT/out_$tag.txt" 2>&1 &
    PIDS+=($!)
  done
done
echo "multisite: ${#PIDS[@]} nodes in 3 sites, ${SECONDS_RUN} s from $(date -d "@$START" +%T), aoi ${AOI}, links: $SHAPING; out $OUT" >&2

# ---- wait (bounded), then report
DEADLINE=$(( START + SECONDS_RUN + 30 ))
rc=0
for i in "${!PIDS[@]}"; do
  pid=${PIDS[$i]}
  while kill -0 "$pid" 2>/dev/null && [ "$(date +%s)" -lt "$DEADLINE" ]; do sleep 0.2; done
  if kill -0 "$pid" 2>/dev/null; then
    echo "multisite: node ${TAGS[$i]} still running at the deadline: killed" >&2
    kill -KILL "$pid"; rc=1
  fi
  wait "$pid" || { echo "multisite: node ${TAGS[$i]} failed: $(tail -3 "$OUT/out_${TAGS[$i]}.txt")" >&2; rc=1; }
done
PIDS=()
ip netns exec "$R" ip mroute show > "$OUT/mroute.txt" 2>&1 || true

printf '%-7s %-10s %-6s %-6s %-14s %s\n' node collision crater joined decoded_es aoi
for tag in "${TAGS[@]}"; do
  ev="$OUT/events_$tag.jsonl"
  col=$(grep '"event":"collision"' "$ev" | grep '"s1t1"' | grep -c '"s2a1"' || true)
  cra=$(grep -c '"event":"crater"' "$ev" || true)
  joi=$(grep -c '"event":"entity_joined"' "$ev" || true)
  des=$(grep -o 'decoded[^|]*entity_state=[0-9]*' "$OUT/out_$tag.txt" | grep -o '[0-9]*$' || echo 0)
  aoi=$(grep -o 'aoi groups=[0-9]* joins=[0-9]* leaves=[0-9]*' "$OUT/out_$tag.txt" || echo "-")
  printf '%-7s %-10s %-6s %-6s %-14s %s\n' "$tag" "$col" "$cra" "$joi" "$des" "$aoi"
  # Nodes 1 and 2 of a site have vehicles in the battle area; nodes 3 and 4 only at home, 12+ km
  # away: with --aoi they rightly hear neither event, without it every node must.
  k=${tag#s?n}
  if [ "$AOI" = "0" ] || [ "$k" -le 2 ]; then
    [ "$col" = 1 ] && [ "$cra" = 1 ] || { echo "multisite: node $tag misses the collision or the crater" >&2; rc=1; }
  elif [ "$col" != 0 ] || [ "$cra" != 0 ]; then
    echo "multisite: node $tag heard the battle though none of its vehicles is within range" >&2; rc=1
  fi
done
echo "multisite: routes the router used: $(grep -c . "$OUT/mroute.txt" || true) lines in $OUT/mroute.txt" >&2
[ "$rc" = 0 ] && echo "multisite: OK: the cross-site collision and the crater reached every site" >&2
true
exit "$rc"
