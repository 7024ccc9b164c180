// End to end, the way the node will use the library: node A drives a vehicle on a circle and
// publishes Entity States by the DR-threshold policy over loopback multicast (127.0.0.1); node B
// polls them into a RemoteEntityTable and reads the smoothed pose every 0.1 s tick. Scenario time
// is simulated (ticks), the sockets are real; each wait for a datagram is bounded (1 s).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "test_util.hpp"

using namespace nettest;
using Eigen::Vector3d;

namespace {

net::SessionConfig node(std::uint16_t port, std::uint16_t app) {
  net::SessionConfig c;
  c.transport.url = "udp://239.1.2.3:" + std::to_string(port);
  c.transport.iface = "127.0.0.1";
  c.site = 1;
  c.application = app;
  return c;
}

}  // namespace

TEST(EndToEnd, DeadReckonedRemoteFollowsTheTruthWithinThresholds) {
  const std::uint16_t port = test_port(2);
  net::Session a(node(port, 1)), b(node(port, 2));
  net::DrPublisher pub(net::DrAlgorithm::RVW);
  net::RemoteEntityTable table;

  net::EntityStatePdu es;
  es.entity_id = a.entity_id(1);
  es.entity_type = {1, 1, 225, 1, 1, 3, 0};
  es.marking = net::make_marking("tank1").value();

  const Vector3d centre(-2707522.0, -4353260.0, 3781450.0);  // an ECEF point (metres)
  const double radius = 100.0, speed = 15.0, w = speed / radius, dt = 0.1;
  int sends = 0, joined = 0;
  double worst_pos = 0, worst_ori = 0;
  for (int tick = 0; tick <= 300; ++tick) {  // 30 s
    const double t = tick * dt;
    net::KinematicState truth;
    truth.position = centre + Vector3d(radius * std::cos(w * t), radius * std::sin(w * t), 0);
    truth.velocity = Vector3d(-speed * std::sin(w * t), speed * std::cos(w * t), 0);
    truth.acceleration = -w * w * (truth.position - centre);
    truth.orientation.psi = w * t + M_PI / 2;
    truth.angular_velocity = Vector3d(0, 0, w);  // level: body z is world z here

    if (pub.needs_update(truth, t) != net::DrPublisher::Reason::None) {
      net::write_kinematics(truth, pub.algorithm(), es);
      es.header.timestamp = net::relative_timestamp(t);
      ASSERT_TRUE(a.send(es)) << a.transport().last_error();
      pub.mark_sent(truth, t);
      ++sends;
      // Wait (bounded) until B has it, so it is applied in this tick.
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
      std::size_t got = 0;
      while (got == 0 && std::chrono::steady_clock::now() < deadline) {
        got = b.poll(net::Overloaded{
            [&](const net::EntityStatePdu& p) {
              joined += table.apply(p, t) == net::RemoteEntityTable::ApplyResult::Joined;
            },
            [&](const net::EntityStateUpdatePdu& p) { table.apply(p, t); }});
        if (got == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
      }
      ASSERT_EQ(got, 1u) << "tick " << tick << ": " << b.counters().summary();
    }
    a.poll([](const auto&) {});  // a drains its own echo
    table.expire(t);
    ASSERT_EQ(table.size(), 1u);
    const auto shown = table.displayed_pose(0, t);
    worst_pos = std::max(worst_pos, (shown.position - truth.position).norm());
    worst_ori = std::max(worst_ori, net::orientation_error_rad(shown.orientation, truth.orientation));
  }
  EXPECT_EQ(joined, 1);
  EXPECT_EQ(net::marking_text(table[0].marking), "tank1");
  // RVW with the centripetal acceleration and yaw rate tracks a circle closely: few sends (the
  // 5 s heartbeat and float rounding dominate), far fewer than the 301 ticks.
  EXPECT_LE(sends, 40);
  EXPECT_GE(sends, 7);  // at least first + heartbeats every 5 s
  EXPECT_LE(worst_pos, 1.0 + speed * dt);
  EXPECT_LE(worst_ori, 3.0 * net::kDegToRad + w * dt);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  while (a.counters().own_echo_ignored < static_cast<std::uint64_t>(sends) &&
         std::chrono::steady_clock::now() < deadline) {
    a.poll([](const auto&) {});
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_EQ(a.counters().own_echo_ignored, static_cast<std::uint64_t>(sends)) << a.counters().summary();
  EXPECT_EQ(a.counters().sent[1], static_cast<std::uint64_t>(sends));
  std::printf("end to end: %d sends in 301 ticks, worst displayed error %.3f m, %.3f deg\n", sends,
              worst_pos, worst_ori / net::kDegToRad);
}
