// A node under test and a DIS peer beside it on loopback multicast (127.0.0.1, a random port):
// the federate tests (test_federate_*.cpp) start `npsnet run --net` with a scenario of
// tests/multinode/data, send it PDUs from a net::Session (application 50) and read what it sent
// back and what it logged. Every wait is bounded in time. Each test holds only its own steps:
// fed::Federate is the setup (world, node, peer), entity_state / detonation / orientation /
// ecef_velocity / set_marking_bytes build the PDUs a peer sends.
#pragma once
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <string>
#include <thread>
#include <vector>

#include "support/dirs.hpp"
#include "lan_support.hpp"
#include "net/net.hpp"
#include "world/scenario.hpp"

namespace fed {

inline const std::filesystem::path kData = std::filesystem::path(npsnet::dirs::source()) / "tests" / "multinode" / "data";

struct Node {
  std::filesystem::path dir, events, out;
  int port = 0;
  double start = 0;     // UNIX time the scenario clock starts (await_node moves it when late)
  double start_at = 0;  // the --start-at it was given
  int pid = -1;
};

// Starts node 1 on `scenario` for `seconds`, starting `lead_s` from now.
inline Node start_node(lan::Procs& procs, const std::string& tag, const std::string& scenario, double seconds,
                       std::vector<std::string> extra = {}, std::vector<std::string> env = {}, double lead_s = 1.0) {
  Node n;
  n.dir = lan::fresh_dir(tag);
  n.port = lan::random_port();
  n.start = n.start_at = lan::unix_now() + lead_s;
  n.events = n.dir / "events.jsonl";
  n.out = n.dir / "out.txt";
  char s[64];
  std::snprintf(s, sizeof s, "%.3f", n.start);
  std::vector<std::string> args{"run", "--scenario", (kData / scenario).string(), "--net",
                                "udp://239.1.2.3:" + std::to_string(n.port), "--iface", "127.0.0.1", "--node", "1",
                                "--start-at", s, "--no-render", "--seconds", std::to_string(seconds), "--events",
                                n.events.string(), "--snapshots", (n.dir / "snap").string()};
  args.insert(args.end(), extra.begin(), extra.end());
  n.pid = procs.start(args, n.out, env);
  return n;
}

// Waits (at most 20 s) until node `n` listens on its port, before a peer sends it anything: on a
// loaded machine a node slow to start misses the PDUs sent before (CI saw one start seconds
// late). Ready after its start time, the node starts its clock that much late and says so
// (lan::start_lag_s): n.start moves with it, so that the tests' schedules are the node's clock.
inline bool await_node(Node& n) {
  const bool bound = lan::await_udp_port(n.port, 20.0);
  if (bound && lan::unix_now() > n.start) {
    double lag = 0;
    for (int i = 0; i < 30 && lag == 0; ++i) {  // said right after its socket is bound (0 when on time)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      lag = lan::start_lag_s(n.out);
    }
    n.start += lag;
  }
  return bound;
}

// The node's scenario time at UNIX time `unix_s`, from what it said once it ended: t = 0 at
// --start-at or as late as it said it started (node_time). node_time_at_least: the time its ticks
// had reached at worst then, less how far they ran behind the wall clock (its paced summary).
inline double node_time(const Node& n, double unix_s) { return unix_s - (n.start_at + lan::start_lag_s(n.out)); }
inline double node_time_at_least(const Node& n, double unix_s) { return node_time(n, unix_s) - lan::worst_late_s(n.out); }

// The peer: application 50 on site 1, same exercise. Its own echo is dropped by its session.
inline net::SessionConfig peer_config(int port, std::uint16_t app = 50) {
  net::SessionConfig cfg;
  cfg.transport.url = "udp://239.1.2.3:" + std::to_string(port);
  cfg.transport.iface = "127.0.0.1";
  cfg.application = app;
  return cfg;
}

// The world of a scenario, for positions (local frame <-> ECEF).
inline npsnet::world::World world_of(const std::string& scenario) {
  return npsnet::world::build_world(npsnet::world::load_scenario(kData / scenario));
}

// One federate test's setup: the scenario's world, node 1 running it (start_node) and a peer on
// its group (application 50). Its folder is removed at the end unless the test failed.
struct Federate {
  npsnet::world::World world;
  lan::Procs procs;
  Node node;
  bool listening;  // the node's socket was bound before the peer's (await_node)
  net::Session peer;
  Federate(const std::string& tag, const std::string& scenario, double seconds, std::vector<std::string> extra = {},
           std::vector<std::string> env = {})
      : world(world_of(scenario)),
        node(start_node(procs, tag, scenario, seconds, std::move(extra), std::move(env))),
        listening(await_node(node)),
        peer(peer_config(node.port)) {}
  ~Federate() {
    if (!::testing::Test::HasFailure()) std::filesystem::remove_all(node.dir);
  }
  // Waits (at most timeout_s) for the node to end; a failure carries its output.
  ::testing::AssertionResult finished(double timeout_s = 30.0) {
    const int rc = procs.wait(node.pid, timeout_s);
    if (rc == 0) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "exit " << rc << (listening ? "" : " (its port was never bound)") << ": "
                                         << lan::read_text(node.out);
  }
  std::vector<nlohmann::json> events() const { return lan::read_events(node.events); }
  net::Vec3d ecef(double x, double y, double agl = 0) const;
};
inline net::Vec3d ecef(const npsnet::world::World& w, double x, double y, double agl = 0) {
  const auto p = w.terrain.frame().to_ecef(npsnet::Vec3(x, y, w.terrain.height(x, y) + agl));
  return {p.x(), p.y(), p.z()};
}
inline net::Vec3d Federate::ecef(double x, double y, double agl) const { return fed::ecef(world, x, y, agl); }
inline npsnet::Vec3 local(const npsnet::world::World& w, const net::Vec3d& e) {
  return w.terrain.frame().from_ecef(npsnet::Vec3(e.x, e.y, e.z));
}

// The DIS orientation (psi, theta, phi) of compass heading `heading_deg`, level, at (x, y).
inline net::EulerAnglesF orientation(const npsnet::world::World& w, double x, double y, double heading_deg) {
  const auto eu = w.terrain.frame().to_dis_euler(npsnet::Vec3(x, y, 0), heading_deg, 0, 0);
  return {static_cast<float>(eu.x()), static_cast<float>(eu.y()), static_cast<float>(eu.z())};
}
// A local velocity (vx east, vy north, m/s) at (x, y) in ECEF axes, as world-axis DR sends it.
inline net::Vec3f ecef_velocity(const npsnet::world::World& w, double x, double y, double vx, double vy) {
  const auto a = ecef(w, x, y), b = ecef(w, x + vx, y + vy);
  return {static_cast<float>(b.x - a.x), static_cast<float>(b.y - a.y), static_cast<float>(b.z - a.z)};
}

// An Entity State of the peer's entity `n`: `type`, `marking`, standing at `at` (DR static).
inline net::EntityStatePdu entity_state(const net::Session& peer, std::uint16_t n, const net::EntityType& type,
                                        const char* marking, const net::Vec3d& at) {
  net::EntityStatePdu p;
  p.entity_id = peer.entity_id(n);
  p.entity_type = type;
  p.marking = net::make_marking(marking).value();
  p.location = at;
  p.dead_reckoning.algorithm = 1;
  return p;
}
// The marking's 11 characters set to raw octets (e.g. Latin-1 "T\xC4NK"), character set kept.
inline void set_marking_bytes(net::EntityStatePdu& p, std::initializer_list<unsigned char> octets) {
  p.marking.characters = {};
  size_t i = 0;
  for (unsigned char c : octets)
    if (i < p.marking.characters.size()) p.marking.characters[i++] = static_cast<char>(c);
}

// A Detonation of the peer's round `round` (exploding entity 100 + round, event round + 1; fired by
// its entity 1) of `type` with warhead, fuse, quantity, landing at `at` with `result`.
inline net::DetonationPdu detonation(const net::Session& peer, std::uint16_t round, const net::EntityType& type,
                                     std::uint16_t warhead, std::uint16_t fuse, std::uint16_t quantity,
                                     std::uint8_t result, const net::Vec3d& at, net::EntityId target = {}) {
  net::DetonationPdu d;
  d.firing_entity_id = peer.entity_id(1);
  d.target_entity_id = target;
  d.exploding_entity_id = peer.entity_id(static_cast<std::uint16_t>(100 + round));
  d.event_id = {peer.entity_id(1).site, peer.entity_id(1).application, static_cast<std::uint16_t>(round + 1)};
  d.location = at;
  d.descriptor = {type, warhead, fuse, quantity, 0};
  d.detonation_result = result;
  return d;
}
inline const net::EntityType kHeRound{2, 8, 225, 2, 14, 1, 0};  // our he_round's type
inline const net::EntityType kM1a1{1, 1, 225, 1, 1, 3, 0};      // our m1a1's type

// Sleeps until UNIX time t (bounded by the caller's schedule).
inline void sleep_until(double t) {
  while (lan::unix_now() < t) std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

// Polls `peer` until UNIX time t, handing every datagram's PDUs to `visit`.
template <class V>
void poll_until(net::Session& peer, double t, V&& visit) {
  do {
    peer.poll(visit);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  } while (lan::unix_now() < t);
}

inline std::vector<nlohmann::json> of_type(const std::vector<nlohmann::json>& evs, const std::string& type) {
  std::vector<nlohmann::json> r;
  for (const auto& e : evs)
    if (e.value("event", "") == type) r.push_back(e);
  return r;
}

}  // namespace fed
