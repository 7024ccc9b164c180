// Issue 11: a remote copy is dead-reckoned from when its Entity State arrived, not from when the
// receiver's tick read it. Two nodes in this process on loopback multicast (127.0.0.1, a random
// port): node 2 ticks, node 1 ticks 10 ms later and sends its tank's first Entity State, node 2
// reads it at its next tick, 100 ms after its last. Paced (the run's wall-clock ticks), node 2's
// copy stands where the sent state dead-reckons to from its arrival to that tick: about 90 ms of
// the tank's travel (1 m at 40 km/h) past the sent position. Dated by the read (before the fix,
// and still in unpaced runs, where the wall clock means nothing to the scenario) it stands on the
// sent position. Every wait is bounded.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "support/dirs.hpp"
#include "lan_support.hpp"
#include "net/transport.hpp"
#include "node/net_bridge.hpp"
#include "node/simulation.hpp"
#include "support/scratch.hpp"
#include "world/scenario.hpp"

using namespace npsnet;

namespace {

struct Node {
  std::unique_ptr<node::EventLog> log;
  std::unique_ptr<node::Simulation> sim;
  std::unique_ptr<node::NetBridge> bridge;
};

Node make_node(const world::Scenario& sc, int k, int port, bool paced, const std::string& tag) {
  Node n;
  n.log = std::make_unique<node::EventLog>(test::scratch_dir() / (tag + "_n" + std::to_string(k) + ".jsonl"));
  n.sim = std::make_unique<node::Simulation>(world::build_world(sc), sc, *n.log, 0.1);
  node::BridgeOptions bo;
  bo.url = "udp://239.1.2.3:" + std::to_string(port);
  bo.iface = "127.0.0.1";
  bo.node = k;
  bo.app = k;
  bo.paced = paced;
  n.bridge = std::make_unique<node::NetBridge>(bo, *n.sim, *n.log);
  n.bridge->attach();
  return n;
}

struct Seen {
  double along = 0, across = 0;  // the copy past the sent position, along / across its velocity (m)
  double speed = 0;              // the sent speed, m/s
  double earliest = 0, latest = 0;  // the least and most time from the send to node 2's read (s)
};

// Linux turns receive timestamps on a moment after the first socket of the host asks for them
// (net_enable_timestamp defers it); until then a datagram is stamped when it is read. Waits (at
// most 2 s) until a probe datagram read 10 ms after it came says so.
void wait_for_receive_timestamps(int port) {
  net::TransportConfig c;
  c.url = "udp://239.1.2.3:" + std::to_string(port);
  net::UdpTransport rx(c), tx(c);
  const std::uint8_t probe[1] = {0};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (std::chrono::steady_clock::now() < deadline) {
    tx.send(probe);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    net::UdpSource from;
    if (rx.receive(from) && from.arrival_s < net::steady_now_s() - 0.005) return;
  }
}

// The schedule above; returns node 2's copy of the tank against what node 1 sent.
Seen run_pair(bool paced, const std::string& tag) {
  const world::Scenario sc =
      world::load_scenario(std::string(npsnet::dirs::source()) + "/tests/multinode/data/dr_arrival.toml");
  const int port = lan::random_port();
  Node a = make_node(sc, 1, port, paced, tag), b = make_node(sc, 2, port, paced, tag);
  wait_for_receive_timestamps(port + 1);
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  b.sim->tick();  // node 2's tick; nothing to read yet
  std::this_thread::sleep_until(start + std::chrono::milliseconds(10));
  const double a0 = net::steady_now_s();
  a.sim->tick();  // node 1's tick: the tank's first Entity State goes out
  const double a1 = net::steady_now_s();
  const int mover_a = a.sim->find_entity("mover");
  const Vec3 sent = a.sim->world().ents.pos[mover_a], vel = a.sim->world().ents.vel[mover_a];
  std::this_thread::sleep_until(start + std::chrono::milliseconds(100));
  const double b0 = net::steady_now_s();
  b.sim->tick();  // node 2 reads it at the start of this tick
  const double b1 = net::steady_now_s();
  const int mover_b = b.sim->find_entity("mover");
  EXPECT_TRUE(b.sim->world().ents.active[mover_b]) << "node 2 heard the tank";
  const Vec3 d = b.sim->world().ents.pos[mover_b] - sent;
  Seen s;
  s.speed = std::hypot(vel.x(), vel.y());
  const Vec3 dir(vel.x() / s.speed, vel.y() / s.speed, 0);
  s.along = d.x() * dir.x() + d.y() * dir.y();
  s.across = std::abs(d.x() * dir.y() - d.y() * dir.x());
  s.earliest = b0 - a1, s.latest = b1 - a0;
  return s;
}

}  // namespace

TEST(DrArrival, PacedACopyIsDeadReckonedFromItsStatesArrival) {
  const Seen s = run_pair(true, "paced");
  ASSERT_GT(s.speed, 10.0) << "the tank drives at 40 km/h";
  ASSERT_GT(s.earliest, 0.05) << "node 2 read the state well after it came";
  // From its arrival (between node 1's tick start and end) to node 2's read (between its tick's
  // start and end), 1 ms of loopback and clock conversion either side.
  EXPECT_GE(s.along, s.speed * (s.earliest - 1e-3)) << "dead-reckoned from the read, not the arrival";
  EXPECT_LE(s.along, s.speed * (s.latest + 1e-3));
  EXPECT_LT(s.across, 0.01);
}

TEST(DrArrival, UnpacedACopyIsDatedByTheTickThatReadIt) {
  const Seen s = run_pair(false, "unpaced");
  ASSERT_GT(s.speed, 10.0);
  EXPECT_NEAR(s.along, 0.0, 0.01) << "unpaced: no wall-clock time between arrival and read";
  EXPECT_LT(s.across, 0.01);
}
