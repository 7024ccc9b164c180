# Sourced by scripts/faults.sh and scripts/multisite.sh: what both need to run nodes in network
# namespaces of their own. Set TOOL (the script's name, for messages) and ROOT (the repository)
# before sourcing. Nothing here touches an interface or namespace it did not make.
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
