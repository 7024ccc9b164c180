#include "node/bridge_options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace npsnet::node {

double dis_timeout_from_env(double fallback) {
  const char* v = std::getenv("NPSNET_DIS_TIMEOUT_S");
  if (!v || !*v) return fallback;
  char* end = nullptr;
  const double s = std::strtod(v, &end);
  if (end == v || *end != '\0' || !std::isfinite(s) || s <= 0 || s > 3600)
    throw std::runtime_error(std::string("NPSNET_DIS_TIMEOUT_S='") + v +
                             "': must be a number of seconds, more than 0 and at most 3600");
  return s;
}

double test_drop_detonations_from_env() {
  const char* v = std::getenv("NPSNET_TEST_DROP_DETONATIONS_S");
  if (!v || !*v) return 0;
  char* end = nullptr;
  const double s = std::strtod(v, &end);
  if (end == v || *end != '\0' || !std::isfinite(s) || s < 0 || s > 3600)
    throw std::runtime_error(std::string("NPSNET_TEST_DROP_DETONATIONS_S='") + v +
                             "': must be a number of seconds, 0 to 3600");
  return s;
}

bool dis_pack_from_env() {
  const char* v = std::getenv("NPSNET_DIS_PACK");
  return v && std::string(v) == "1";
}

net::SessionConfig session_config(const BridgeOptions& o) {
  if (o.app < 1 || o.app >= kCulturalAppBit)
    throw std::runtime_error("--app " + std::to_string(o.app) + ": with --net it must be 1-32767 (32768 and up carry cultural features)");
  if (o.site < 1 || o.site > 65535) throw std::runtime_error("--site " + std::to_string(o.site) + ": must be 1-65535");
  if (o.exercise < 1 || o.exercise > 255) throw std::runtime_error("--exercise " + std::to_string(o.exercise) + ": must be 1-255");
  if (o.dis_version != 6 && o.dis_version != 7)
    throw std::runtime_error("--dis-version " + std::to_string(o.dis_version) + ": must be 6 or 7");
  net::SessionConfig c;
  c.protocol_version = static_cast<std::uint8_t>(o.dis_version);
  c.transport.url = o.url;
  c.transport.iface = o.iface;
  c.exercise_id = static_cast<std::uint8_t>(o.exercise);
  c.site = static_cast<std::uint16_t>(o.site);
  c.application = static_cast<std::uint16_t>(o.app);
  if (o.ttl < 1 || o.ttl > 255) throw std::runtime_error("--ttl " + std::to_string(o.ttl) + ": must be 1-255");
  c.transport.multicast_ttl = o.ttl;
  if (o.aoi_cell_m > 0) {
    auto u = net::parse_udp_url(o.url);
    if (!u || u.value().mode != net::UdpMode::Multicast)
      throw std::runtime_error("--aoi needs a multicast --net group (the base of the cell groups), not " + o.url);
    if (auto g = net::AoiGrid::make(u.value().address, o.aoi_cell_m, o.aoi_groups); !g) throw std::runtime_error(g.error());
    c.transport.join_destination = false;  // the cell groups are joined as the vehicles need them
  }
  c.offline = o.offline;
  return c;
}

net::DrThresholds dr_thresholds(double timeout_s) {
  net::DrThresholds t;
  t.timeout_s = timeout_s;
  t.heartbeat_s = std::min(net::annex_c::kHeartbeatS, timeout_s * net::annex_c::kHeartbeatS / net::annex_c::kTimeoutS);
  return t;
}

std::unique_ptr<net::Session> open_session(const BridgeOptions& o) {
  return std::make_unique<net::Session>(session_config(o));
}

}  // namespace npsnet::node
