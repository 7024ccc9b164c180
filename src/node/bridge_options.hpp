// The bridge's settings from the command line and the environment (shared/ARCHITECTURE.md,
// Network): --net, --iface, --node, --exercise, --site, --app; NPSNET_DIS_TIMEOUT_S (remote
// entity timeout, s) and NPSNET_DIS_PACK=1 (several Entity States to a datagram).
// Every bad value is a std::runtime_error whose message names the flag or variable.
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "core/constants.hpp"
#include "net/net.hpp"
#include "node/entity_type_table.hpp"
#include "node/munition_table.hpp"

namespace npsnet::node {

struct BridgeOptions {
  std::string url = "udp://239.1.2.3:3000";  // --net
  std::string iface = "127.0.0.1";           // --iface
  int node = 1;                              // --node: vehicles with node = N are ours
  int exercise = 1, site = 1, app = 1;       // DIS identity (app default = node, set by caller)
  double timeout_s = net::annex_c::kTimeoutS;  // remote entity timeout, s
  double aoi_cell_m = 0;                     // --aoi: cell size, m; 0 = off (one group)
  int aoi_groups = net::kAoiDefaultMaxGroups;  // --aoi-groups: at most this many cell groups
  int ttl = 1;                               // --ttl: multicast TTL (more than 1 to cross routers)
  bool offline = false;                      // no socket (run --replay): sends go nowhere
  // Other simulators' munitions (models/munitions.toml); null: the bridge loads the bundled one.
  std::shared_ptr<const MunitionTable> munitions;
  // Other simulators' entity types (models/entity_types.toml); null: the bundled one.
  std::shared_ptr<const EntityTypeTable> entity_types;
  int dis_version = 7;                       // --dis-version: protocol version we send (6 or 7)
  // Net out decides in the local frame which vehicles may need an Entity State (dr_bound.hpp) and
  // turns only those into ECEF; false: every vehicle's ECEF state every tick (the same PDUs,
  // slower: the reference of tests/node/test_dr_bound.cpp).
  bool dr_prefilter = true;
  // The node ticks on the wall clock (run.cpp: every --net, --realtime or --window run): each
  // datagram read from the socket is dated by its arrival (net_bridge.hpp, Receive). false
  // (unpaced: tests, the fuzz target; a replay): by the start of the tick that reads it.
  bool paced = false;
};

// Application ids at or above this carry cultural features (fixed objects).
inline constexpr std::uint16_t kCulturalAppBit = 0x8000;

// NPSNET_DIS_TIMEOUT_S (seconds, > 0, <= 3600, finite), or `fallback` when unset.
double dis_timeout_from_env(double fallback);
// NPSNET_DIS_PACK == "1".
bool dis_pack_from_env();
// Test hook (tests/multinode/test_adoption.cpp): NPSNET_TEST_DROP_DETONATIONS_S=S makes the bridge
// ignore every Detonation PDU it receives during its first S seconds, as if each was lost; 0 when
// unset; a value that is not a finite number of seconds in [0, 3600] throws.
double test_drop_detonations_from_env();

// The session of `o`; throws on an identity out of range (--app 1-32767, --site 1-65535,
// --exercise 1-255), a --dis-version other than 6 or 7, a --ttl out of 1-255, or an --aoi grid that cannot be made (net/aoi.hpp);
// with --aoi the transport holds many groups and joins none at first.
net::SessionConfig session_config(const BridgeOptions& o);
// Annex C thresholds with the timeout `timeout_s`; a timeout shorter than the default (tests)
// shortens the heartbeat in the Annex C ratio 5:12, so that a quiet living entity never times out.
net::DrThresholds dr_thresholds(double timeout_s);

// Opens the DIS session of `o` (socket bound, group joined). Throws std::runtime_error with an
// actionable message (bad URL, iface, identity). Done before anything is written.
std::unique_ptr<net::Session> open_session(const BridgeOptions& o);

}  // namespace npsnet::node
