# Sourced by scripts/faults.sh, scripts/dr-error.sh and scripts/multisite.sh: what they need to run
# nodes in network namespaces of their own. Set TOOL (the script's name, for messages) and ROOT (the
# repository) before sourcing. Nothing here touches an interface or namespace it did not make.
#   skip MSG           prints "TOOL: SKIP: MSG" and exits 77 (ctest's SKIP_RETURN_CODE)
#   netns_preflight    skips unless root, iproute2 and build/npsnet are there; sets NPSNET
#   newns NAME         makes namespace NAME (lo up) and remembers it in NSLIST
#   stop_processes     SIGKILL to PIDS (nodes), SIGTERM to SHAPERS (link shapers), waits for both
#   netns_remove_all   deletes every namespace in NSLIST, by name
NSLIST=()
PIDS=()
SHAPERS=()
skip() { echo "$TOOL: SKIP: $*" >&2; exit 77; }
netns_preflight() {
  [ "$(id -u)" -eq 0 ] || skip "needs root (network namespaces)"
  command -v ip >/dev/null || skip "iproute2 'ip' is not installed"
  NPSNET="$ROOT/build/npsnet"
  [ -x "$NPSNET" ] || skip "build/npsnet is not built (scripts/build.sh)"
}
newns() { ip netns add "$1"; NSLIST+=("$1"); ip -n "$1" link set lo up; }
stop_processes() {
  local pid
  for pid in "${PIDS[@]}"; do kill -KILL "$pid" 2>/dev/null; done
  for pid in "${SHAPERS[@]}"; do kill -TERM "$pid" 2>/dev/null; done
  for pid in "${PIDS[@]}" "${SHAPERS[@]}"; do wait "$pid" 2>/dev/null; done
  return 0
}
netns_remove_all() {
  local ns
  for ns in "${NSLIST[@]}"; do ip netns del "$ns" 2>/dev/null; done
  return 0
}
# Shaped LANs (scripts/faults.sh, scripts/dr-error.sh):
#   shaped_lan_preflight NAME   netns_preflight, python3 and /dev/net/tun (else skip); OUT defaults
#                        to a fresh /tmp/npsnet-NAME.XXXXXX
#   fault_shape LOSS CONTROL    SHAPE = the issue-11 link faults (delay 20 +- 10 ms, LOSS %, dup 5 %,
#                        reorder 25 %, one way), or with CONTROL = 1 a clean link
#   shaped_lan PREFIX NODES SUBNET DELAY_MS LOSS [linkshaper options...]
#       hub namespace PREFIXh (HUB) with bridge br0, and node namespaces PREFIXn1..NODES on it, each
#       joined through scripts/linkshaper.py (log OUT/linkK.log, pid appended to SHAPERS in node
#       order); node K's eth0 is SUBNET.(10 + K)/24
#   shaped_lan_cleanup   the EXIT trap: every process, the bridge, every namespace (by name)
#   wait_nodes UNTIL PID...  waits for each node until UNIX time UNTIL (then SIGKILL); returns 1
#                        when one was killed or failed (TOOL: message on stderr)
#   stop_shapers         SIGTERM to SHAPERS, waits, prints their counts (OUT/link*.log) on stderr
shaped_lan_preflight() {
  netns_preflight
  command -v python3 >/dev/null && [ -c /dev/net/tun ] || skip "needs python3 and /dev/net/tun"
  [ -n "${OUT:-}" ] || OUT=$(mktemp -d "/tmp/npsnet-$1.XXXXXX")
  mkdir -p "$OUT"
}
fault_shape() {
  SHAPE=(20 "$1" --jitter-ms 10 --dup 5 --reorder 25 --one-way)
  [ "$2" = 1 ] && SHAPE=(0 0 --one-way)
  return 0
}
shaped_lan() {
  local prefix=$1 nodes=$2 subnet=$3 k n
  shift 3
  HUB="${prefix}h"
  newns "$HUB"
  ip -n "$HUB" link add br0 type bridge mcast_snooping 0
  ip -n "$HUB" link set br0 up
  for k in $(seq 1 "$nodes"); do
    n="${prefix}n$k"
    newns "$n"
    rm -f "$OUT/link$k.log"
    ip netns exec "$HUB" python3 "$ROOT/scripts/linkshaper.py" "p$k" eth0 "$n" "$1" "$2" "$k" "${@:3}" \
      > "$OUT/link$k.log" 2>&1 &
    SHAPERS+=($!)
    for _ in $(seq 1 50); do grep -qs ready "$OUT/link$k.log" && break; sleep 0.1; done
    grep -q ready "$OUT/link$k.log" || { cat "$OUT/link$k.log" >&2; exit 1; }
    ip -n "$HUB" link set "p$k" master br0
    ip -n "$HUB" link set "p$k" up
    ip -n "$n" addr add "$subnet.$((10 + k))/24" dev eth0
    ip -n "$n" link set eth0 up
  done
}
shaped_lan_cleanup() {
  set +e
  stop_processes
  [ -n "${HUB:-}" ] && ip -n "$HUB" link del br0 2>/dev/null
  netns_remove_all
}
wait_nodes() {
  local until=$1 pid bad=0
  shift
  for pid in "$@"; do
    while kill -0 "$pid" 2>/dev/null && [ "$(date +%s)" -lt "$until" ]; do sleep 0.2; done
    kill -0 "$pid" 2>/dev/null && { echo "$TOOL: a node still runs past its end: killed" >&2; kill -KILL "$pid"; bad=1; }
    wait "$pid" || { echo "$TOOL: a node failed (see $OUT/out_*.txt)" >&2; bad=1; }
  done
  return "$bad"
}
stop_shapers() {
  local pid
  for pid in "${SHAPERS[@]}"; do kill -TERM "$pid" 2>/dev/null; wait "$pid" 2>/dev/null || true; done
  SHAPERS=()
  cat "$OUT"/link?.log | grep linkshaper >&2 || true
}
