// Body-axis dead reckoning (Annex E: FPB, RPB, RVB, FVB), the dead-reckoned velocity, and the
// received timestamp dating a remote state (issue 10, defect 5). Expected values are worked out
// by hand in the comments (orientation psi = theta = phi = 0: body axes = ECEF axes).
#include <gtest/gtest.h>

#include <cmath>

#include "test_util.hpp"

using Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;
const Vector3d kP0{-2707522.0, -4353260.0, 3781450.0};

net::KinematicState body(Vector3d v, Vector3d a, Vector3d w, double psi = 0) {
  net::KinematicState s;
  s.position = kP0;
  s.velocity = v;
  s.acceleration = a;
  s.angular_velocity = w;
  s.orientation.psi = psi;
  return s;
}

void expect_near(const Vector3d& got, const Vector3d& want, double tol) {
  EXPECT_NEAR(got.x(), want.x(), tol);
  EXPECT_NEAR(got.y(), want.y(), tol);
  EXPECT_NEAR(got.z(), want.z(), tol);
}

}  // namespace

// 10 m/s forward, turning at 0.2 rad/s about body z: a circle of radius 10 / 0.2 = 50 m.
// After a quarter turn (t = (pi/2) / 0.2 = 7.854 s): x = 50 sin(pi/2) = 50, y = 50 (1 - cos) = 50,
// heading pi/2, velocity (0, 10, 0). After a half turn: (0, 100, 0), velocity (-10, 0, 0).
// The old code went straight: x = 78.54 after the quarter turn.
TEST(DeadReckoningBody, RpbFollowsItsCircle) {
  const auto s = body({10, 0, 0}, {0, 0, 0}, {0, 0, 0.2});
  const double quarter = (kPi / 2) / 0.2;
  auto p = net::dead_reckon(s, net::DrAlgorithm::RPB, quarter);
  expect_near(p.position - kP0, {50, 50, 0}, 1e-6);
  EXPECT_NEAR(p.orientation.psi, kPi / 2, 1e-9);
  expect_near(p.velocity, {0, 10, 0}, 1e-9);
  p = net::dead_reckon(s, net::DrAlgorithm::RPB, 2 * quarter);
  expect_near(p.position - kP0, {0, 100, 0}, 1e-6);
  expect_near(p.velocity, {-10, 0, 0}, 1e-9);
  // Every point on the way is 50 m from the centre (0, 50, 0).
  for (double t = 0; t < 31.4; t += 0.7)
    EXPECT_NEAR((net::dead_reckon(s, net::DrAlgorithm::RPB, t).position - kP0 - Vector3d(0, 50, 0)).norm(), 50.0, 1e-6)
        << t;
}

// RVB from rest, 2 m/s^2 forward, turning at c = 0.2 rad/s: P = R2 a with
// R2 = t sin(ct)/c + (cos(ct) - 1)/c^2 along a, sin(ct)/c^2 - t cos(ct)/c across it.
// At ct = pi/2 (t = 7.854): x = 2 (7.854 / 0.2 - 1 / 0.04) = 2 (39.270 - 25) = 28.540,
// y = 2 (1 / 0.04) = 50; velocity a t = 15.708 m/s turned a quarter: (0, 15.708, 0).
TEST(DeadReckoningBody, RvbAcceleratesAlongItsTurningBody) {
  const auto s = body({0, 0, 0}, {2, 0, 0}, {0, 0, 0.2});
  const double t = (kPi / 2) / 0.2;
  const auto p = net::dead_reckon(s, net::DrAlgorithm::RVB, t);
  expect_near(p.position - kP0, {2 * (t / 0.2 - 25.0), 50, 0}, 1e-6);
  EXPECT_NEAR(p.position.x() - kP0.x(), 28.5398, 1e-4);
  expect_near(p.velocity, {0, 2 * t, 0}, 1e-9);
}

// Body velocity is turned into the world by the orientation: heading psi = pi/2 sends body x
// along ECEF y. FPB: (0, 10 t, 0), no rotation even with a body rate. FVB adds a t^2 / 2.
TEST(DeadReckoningBody, FixedBodyFormsUseTheOrientation) {
  const auto s = body({10, 0, 0}, {1, 0, 0}, {0, 0, 0.2}, kPi / 2);
  auto p = net::dead_reckon(s, net::DrAlgorithm::FPB, 3.0);
  expect_near(p.position - kP0, {0, 30, 0}, 1e-6);
  EXPECT_NEAR(p.orientation.psi, kPi / 2, 1e-9);
  p = net::dead_reckon(s, net::DrAlgorithm::FVB, 3.0);
  expect_near(p.position - kP0, {0, 30 + 4.5, 0}, 1e-6);
  expect_near(p.velocity, {0, 13, 0}, 1e-9);
}

// World forms give the velocity at that moment: v + a t (RVW, FVW), v (FPW, RPW), 0 (static).
TEST(DeadReckoningBody, WorldFormsVelocityIsVPlusAt) {
  const auto s = body({10, -5, 2}, {1, 0.5, -0.25}, {0, 0, 0.2});
  expect_near(net::dead_reckon(s, net::DrAlgorithm::RVW, 2.0).velocity, {12, -4, 1.5}, 1e-12);
  expect_near(net::dead_reckon(s, net::DrAlgorithm::FVW, 2.0).velocity, {12, -4, 1.5}, 1e-12);
  expect_near(net::dead_reckon(s, net::DrAlgorithm::FPW, 2.0).velocity, {10, -5, 2}, 1e-12);
  expect_near(net::dead_reckon(s, net::DrAlgorithm::Static, 2.0).velocity, {0, 0, 0}, 1e-12);
}

namespace {
net::EntityStatePdu fpw(Vector3d pos, std::uint32_t timestamp) {
  net::EntityStatePdu p;
  p.entity_id = {7, 8, 9};
  net::KinematicState s;
  s.position = pos;
  s.velocity = {10, 0, 0};
  net::write_kinematics(s, net::DrAlgorithm::FPW, p);
  p.header.timestamp = timestamp;
  return p;
}
}  // namespace

// An absolute timestamp 0.5 s older than our UTC: the state is 0.5 s old when it arrives, so
// at arrival it is already 5 m further (10 m/s).
TEST(RemoteTimestamps, AbsoluteTimestampDatesTheState) {
  net::RemoteEntityTable table;
  const double unix_now = 1'700'000'010.5;  // any UTC time
  const double past_hour = std::fmod(unix_now, 3600.0);
  table.apply(fpw(kP0, net::absolute_timestamp(past_hour - 0.5)), 100.0, unix_now);
  expect_near(table.dead_reckoned_pose(0, 100.0).position - kP0, {5, 0, 0}, 1e-3);
  expect_near(table.dead_reckoned_pose(0, 101.0).position - kP0, {15, 0, 0}, 1e-3);
  // Without our UTC (a replay) it is taken as arriving fresh.
  net::RemoteEntityTable replay;
  replay.apply(fpw(kP0, net::absolute_timestamp(past_hour - 0.5)), 100.0, net::RemoteEntityTable::kNoUtc);
  expect_near(replay.dead_reckoned_pose(0, 100.0).position - kP0, {0, 0, 0}, 1e-9);
}

// Relative timestamps: the first update fixes the clock offset (arrival 100 s at sender 20 s);
// the next one, stamped 21 s, arrives at 101.3 s: 0.3 s later than the first one's delay, so
// its state is 0.3 s old on arrival (3 m at 10 m/s). A sender leaving its timestamp 0 gives
// no timing: each state is taken as of its arrival.
TEST(RemoteTimestamps, RelativeTimestampsAgeByTheExtraDelay) {
  net::RemoteEntityTable table;
  table.apply(fpw(kP0, net::relative_timestamp(20.0)), 100.0);
  expect_near(table.dead_reckoned_pose(0, 100.0).position - kP0, {0, 0, 0}, 1e-9);
  const Vector3d p1 = kP0 + Vector3d(10, 0, 0);
  table.apply(fpw(p1, net::relative_timestamp(21.0)), 101.3);
  expect_near(table.dead_reckoned_pose(0, 101.3).position - p1, {3, 0, 0}, 1e-3);
  // Across the hour: 3599.9 s then 0.1 s is 0.2 s later.
  net::RemoteEntityTable hour;
  hour.apply(fpw(kP0, net::relative_timestamp(3599.9)), 50.0);
  hour.apply(fpw(p1, net::relative_timestamp(0.1)), 50.3);
  expect_near(hour.dead_reckoned_pose(0, 50.3).position - p1, {1, 0, 0}, 1e-3);

  net::RemoteEntityTable zero;
  zero.apply(fpw(kP0, 0), 100.0);
  zero.apply(fpw(p1, 0), 103.0);
  expect_near(zero.dead_reckoned_pose(0, 103.0).position - p1, {0, 0, 0}, 1e-9);
}
