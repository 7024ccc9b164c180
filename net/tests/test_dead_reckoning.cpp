// Dead reckoning algorithms 1-5 against analytic motion; the sender's threshold policy.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "test_util.hpp"

using Eigen::Vector3d;

namespace {

net::KinematicState moving() {
  net::KinematicState s;
  s.position = {-2707522.0, -4353260.0, 3781450.0};
  s.velocity = {10.0, -5.0, 2.0};
  s.acceleration = {1.0, 0.5, -0.25};
  s.orientation = {0.3, 0.1, -0.05};
  s.angular_velocity = {0.0, 0.0, 0.2};  // yawing about body z at 0.2 rad/s
  return s;
}

}  // namespace

TEST(DeadReckoning, StaticAndOtherDoNotMove) {
  const auto s = moving();
  for (auto alg : {net::DrAlgorithm::Static, net::DrAlgorithm::Other}) {
    const auto p = net::dead_reckon(s, alg, 7.0);
    EXPECT_EQ(p.position, s.position);
    EXPECT_NEAR(net::orientation_error_rad(p.orientation, s.orientation), 0.0, 1e-12);
  }
}

TEST(DeadReckoning, FpwIsConstantVelocityFixedOrientation) {
  const auto s = moving();
  for (double t : {0.0, 0.5, 3.0, 12.0}) {
    const auto p = net::dead_reckon(s, net::DrAlgorithm::FPW, t);
    EXPECT_NEAR((p.position - (s.position + s.velocity * t)).norm(), 0.0, 1e-9) << t;
    EXPECT_NEAR(net::orientation_error_rad(p.orientation, s.orientation), 0.0, 1e-9) << t;
  }
}

TEST(DeadReckoning, FvwAddsHalfAtSquared) {
  const auto s = moving();
  for (double t : {0.5, 3.0, 12.0}) {
    const auto p = net::dead_reckon(s, net::DrAlgorithm::FVW, t);
    const Vector3d expect = s.position + s.velocity * t + 0.5 * s.acceleration * t * t;
    EXPECT_NEAR((p.position - expect).norm(), 0.0, 1e-8) << t;
    EXPECT_NEAR(net::orientation_error_rad(p.orientation, s.orientation), 0.0, 1e-9);
  }
}

TEST(DeadReckoning, RpwRotatesAboutBodyAxisAtTheGivenRate) {
  // Level entity (theta = phi = 0) yawing about body z: psi grows linearly, position as FPW.
  net::KinematicState s = moving();
  s.orientation = {0.3, 0.0, 0.0};
  s.angular_velocity = {0.0, 0.0, 0.2};
  for (double t : {0.5, 2.0, 5.0}) {
    const auto p = net::dead_reckon(s, net::DrAlgorithm::RPW, t);
    EXPECT_NEAR(p.orientation.psi, std::remainder(0.3 + 0.2 * t, 2 * M_PI), 1e-9) << t;
    EXPECT_NEAR(p.orientation.theta, 0.0, 1e-9);
    EXPECT_NEAR(p.orientation.phi, 0.0, 1e-9);
    EXPECT_NEAR((p.position - (s.position + s.velocity * t)).norm(), 0.0, 1e-9);
  }
}

TEST(DeadReckoning, RvwRollsAboutBodyXWithAcceleration) {
  // Pitched entity rolling about its own x axis: phi grows, psi/theta stay.
  net::KinematicState s = moving();
  s.orientation = {1.0, 0.2, 0.0};
  s.angular_velocity = {0.1, 0.0, 0.0};
  const double t = 3.0;
  const auto p = net::dead_reckon(s, net::DrAlgorithm::RVW, t);
  EXPECT_NEAR(p.orientation.psi, 1.0, 1e-9);
  EXPECT_NEAR(p.orientation.theta, 0.2, 1e-9);
  EXPECT_NEAR(p.orientation.phi, 0.3, 1e-9);
  const Vector3d expect = s.position + s.velocity * t + 0.5 * s.acceleration * t * t;
  EXPECT_NEAR((p.position - expect).norm(), 0.0, 1e-8);
}

TEST(DeadReckoning, RotationMatchesMatrixExponential) {
  // General rates: R(t) = R0 * exp([w] t), checked against many small steps.
  net::KinematicState s = moving();
  s.angular_velocity = {0.05, -0.1, 0.2};
  const double t = 4.0;
  Eigen::Quaterniond q = net::to_quaternion(s.orientation);
  const int steps = 4000;
  for (int i = 0; i < steps; ++i)
    q = q * Eigen::Quaterniond(Eigen::AngleAxisd(s.angular_velocity.norm() * t / steps,
                                                 s.angular_velocity.normalized()));
  const auto p = net::dead_reckon(s, net::DrAlgorithm::RPW, t);
  EXPECT_NEAR(net::orientation_error_rad(p.orientation, net::to_euler(q)), 0.0, 1e-9);
}

TEST(DeadReckoning, EulerQuaternionRoundTrip) {
  for (const net::Euler e : {net::Euler{0.3, 0.1, -0.05}, net::Euler{-2.5, -1.2, 2.9},
                             net::Euler{3.0, 0.0, 0.0}}) {
    const auto back = net::to_euler(net::to_quaternion(e));
    EXPECT_NEAR(back.psi, e.psi, 1e-12);
    EXPECT_NEAR(back.theta, e.theta, 1e-12);
    EXPECT_NEAR(back.phi, e.phi, 1e-12);
  }
  EXPECT_NEAR(net::orientation_error_rad({0, 0, 0}, {3 * net::kDegToRad, 0, 0}),
              3 * net::kDegToRad, 1e-12);
}

TEST(DeadReckoning, PduConversionKeepsTheState) {
  net::EntityStatePdu pdu;
  const auto s = moving();
  net::write_kinematics(s, net::DrAlgorithm::RVW, pdu);
  EXPECT_EQ(pdu.dead_reckoning.algorithm, 4);
  const auto back = net::kinematic_state(pdu);
  EXPECT_EQ(back.position, s.position);  // doubles on the wire
  EXPECT_NEAR((back.velocity - s.velocity).norm(), 0.0, 1e-5);
  EXPECT_NEAR((back.angular_velocity - s.angular_velocity).norm(), 0.0, 1e-6);
  EXPECT_EQ(net::dr_algorithm_from_wire(200), net::DrAlgorithm::Other);
}

// A double beyond a float's range has no float (a plain conversion is undefined there): the
// PDU carries the largest float of its sign; in range, the nearest float, as a plain conversion.
TEST(DeadReckoning, PduFloatsSaturateBeyondAFloatsRange) {
  constexpr float kMax = std::numeric_limits<float>::max();
  EXPECT_EQ(net::wire_float(1e300), kMax);
  EXPECT_EQ(net::wire_float(-1e300), -kMax);
  EXPECT_EQ(net::wire_float(std::numeric_limits<double>::infinity()), kMax);
  EXPECT_EQ(net::wire_float(-std::numeric_limits<double>::infinity()), -kMax);
  EXPECT_EQ(net::wire_float(double(kMax)), kMax);
  EXPECT_TRUE(std::isnan(net::wire_float(std::nan(""))));
  for (double x : {0.1, -12.345678901234, 6.02e23, -1e-40, 3.4e38, -3.4e38})
    EXPECT_EQ(std::bit_cast<uint32_t>(net::wire_float(x)), std::bit_cast<uint32_t>(static_cast<float>(x))) << x;
  const net::Vec3f v = net::wire_vec3f(1e39, -2.5, -1e39);
  EXPECT_EQ(v, (net::Vec3f{kMax, -2.5f, -kMax}));

  net::KinematicState s = moving();
  s.velocity = {1e300, -1e300, 4};
  s.acceleration = {0, 5e38, 0};
  s.angular_velocity = {-1e50, 0, 0};
  s.orientation.psi = 1e40;
  net::EntityStatePdu pdu;
  net::write_kinematics(s, net::DrAlgorithm::RVW, pdu);
  EXPECT_EQ(pdu.linear_velocity, (net::Vec3f{kMax, -kMax, 4}));
  EXPECT_EQ(pdu.dead_reckoning.linear_acceleration, (net::Vec3f{0, kMax, 0}));
  EXPECT_EQ(pdu.dead_reckoning.angular_velocity, (net::Vec3f{-kMax, 0, 0}));
  EXPECT_EQ(pdu.orientation.psi, kMax);
}

TEST(DrPublisher, FirstThenPositionThreshold) {
  net::DrPublisher pub(net::DrAlgorithm::FPW);
  net::KinematicState truth;
  truth.position = {1000, 2000, 3000};
  truth.velocity = {10, 0, 0};
  EXPECT_EQ(pub.needs_update(truth, 0.0), net::DrPublisher::Reason::First);
  pub.mark_sent(truth, 0.0);
  // The truth follows the DR track exactly: nothing due until the heartbeat.
  for (double t = 0.1; t < 4.95; t += 0.1) {
    net::KinematicState now = truth;
    now.position = truth.position + truth.velocity * t;
    EXPECT_EQ(pub.needs_update(now, t), net::DrPublisher::Reason::None) << t;
  }
  // The truth turns: the DR error grows past 1 m and triggers exactly then.
  net::KinematicState turned = truth;
  turned.position = truth.position + truth.velocity * 2.0 + Vector3d(0, 0.99, 0);
  EXPECT_EQ(pub.needs_update(turned, 2.0), net::DrPublisher::Reason::None);
  turned.position.y() += 0.02;  // 1.01 m off
  EXPECT_EQ(pub.needs_update(turned, 2.0), net::DrPublisher::Reason::Position);
}

TEST(DrPublisher, OrientationThresholdAndHeartbeat) {
  net::DrThresholds th;
  th.heartbeat_s = 5.0;
  net::DrPublisher pub(net::DrAlgorithm::FPW, th);
  net::KinematicState truth;
  pub.mark_sent(truth, 10.0);
  net::KinematicState turned = truth;
  turned.orientation.psi = 2.9 * net::kDegToRad;
  EXPECT_EQ(pub.needs_update(turned, 11.0), net::DrPublisher::Reason::None);
  turned.orientation.psi = 3.1 * net::kDegToRad;
  EXPECT_EQ(pub.needs_update(turned, 11.0), net::DrPublisher::Reason::Orientation);
  EXPECT_EQ(pub.needs_update(truth, 14.99), net::DrPublisher::Reason::None);
  EXPECT_EQ(pub.needs_update(truth, 15.0), net::DrPublisher::Reason::Heartbeat);
}

TEST(DrPublisher, TestGivesWhatItCompared) {
  net::DrPublisher pub(net::DrAlgorithm::RVW);
  net::KinematicState sent;
  sent.position = {1000, 2000, 3000};
  sent.velocity = {10, 0, 0};
  sent.orientation = {0.3, 0.05, -0.02};
  sent.angular_velocity = {0, 0, 0.1};
  EXPECT_EQ(pub.test(sent, 0.0).reason, net::DrPublisher::Reason::First);
  EXPECT_TRUE(std::isnan(pub.test(sent, 0.0).orientation_error_rad));
  pub.mark_sent(sent, 0.0);
  net::KinematicState truth = sent;
  truth.position += Vector3d(5.0, 0.3, 0);
  truth.orientation.psi += 0.05;
  const auto near = pub.test(truth, 0.5);  // on its track but 0.3 m off, turned as sent
  EXPECT_EQ(near.reason, net::DrPublisher::Reason::None);
  EXPECT_EQ(near.reason, pub.needs_update(truth, 0.5));
  const net::Pose b = pub.believed_pose(0.5);
  EXPECT_EQ(near.believed.position, b.position);  // the same bits
  EXPECT_EQ(near.believed.orientation.psi, b.orientation.psi);
  EXPECT_EQ(near.orientation_error_rad, net::orientation_error_rad(truth.orientation, b.orientation));
  EXPECT_LT(near.orientation_error_rad, 0.01);
  truth.position.y() += 1.0;  // the position decides: no orientation error computed
  const auto far = pub.test(truth, 0.5);
  EXPECT_EQ(far.reason, net::DrPublisher::Reason::Position);
  EXPECT_TRUE(std::isnan(far.orientation_error_rad));
}

TEST(DrPublisher, SimulatedRunSendsFarFewerThanEveryTick) {
  // A vehicle driving a circle of radius 200 m at 10 m/s for 60 s, 10 Hz ticks. Counting sends
  // and checking the believed pose never strays more than the threshold (plus one tick of motion).
  net::DrPublisher pub(net::DrAlgorithm::FPW);
  const double r = 200, v = 10, w = v / r;
  int sends = 0;
  double worst = 0;
  for (int i = 0; i <= 600; ++i) {
    const double t = i * 0.1;
    net::KinematicState s;
    s.position = {r * std::cos(w * t), r * std::sin(w * t), 0};
    s.velocity = {-v * std::sin(w * t), v * std::cos(w * t), 0};
    s.orientation.psi = w * t + M_PI / 2;
    if (pub.needs_update(s, t) != net::DrPublisher::Reason::None) {
      pub.mark_sent(s, t);
      ++sends;
    }
    worst = std::max(worst, (pub.believed_pose(t).position - s.position).norm());
  }
  // Chord error 1 m at v^2/r = 0.5 m/s^2 needs ~2 s per update; heading drift 3 deg at
  // 0.05 rad/s needs ~1.05 s: so ~57 sends, not 601.
  EXPECT_GE(sends, 40);
  EXPECT_LE(sends, 80);
  EXPECT_LE(worst, 1.0 + 1e-9);
}
