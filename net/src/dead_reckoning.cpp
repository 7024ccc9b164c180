// dead_reckoning.cpp — Annex E extrapolation and the DR-threshold send policy.
#include "net/dead_reckoning.hpp"

#include <algorithm>
#include <cmath>

namespace net {

Eigen::Quaterniond to_quaternion(const Euler& e) noexcept {
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  return Eigen::Quaterniond(AngleAxisd(e.psi, Vector3d::UnitZ()) *
                            AngleAxisd(e.theta, Vector3d::UnitY()) *
                            AngleAxisd(e.phi, Vector3d::UnitX()));
}

Euler to_euler(const Eigen::Quaterniond& q) noexcept {
  const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
  Euler e;
  e.theta = -std::asin(std::clamp(r(2, 0), -1.0, 1.0));
  if (std::abs(r(2, 0)) < 1.0 - 1e-12) {
    e.psi = std::atan2(r(1, 0), r(0, 0));
    e.phi = std::atan2(r(2, 1), r(2, 2));
  } else {  // gimbal lock: put all heading into psi
    e.phi = 0;
    e.psi = std::atan2(-r(0, 1), r(1, 1));
  }
  return e;
}

double orientation_error_rad(const Euler& a, const Euler& b) noexcept {
  return to_quaternion(a).angularDistance(to_quaternion(b));
}

DrAlgorithm dr_algorithm_from_wire(std::uint8_t v) noexcept {
  return v <= 9 ? static_cast<DrAlgorithm>(v) : DrAlgorithm::Other;
}

namespace {

// Orientation after rotating at body rates w for dt: R(t) = R0 * exp([w] dt).
Euler rotate(const Euler& e, const Eigen::Vector3d& w, double dt) {
  const double angle = w.norm() * dt;
  if (angle == 0.0 || !std::isfinite(angle)) return e;
  const Eigen::Quaterniond q = to_quaternion(e) * Eigen::Quaterniond(Eigen::AngleAxisd(angle, w.normalized()));
  return to_euler(q);
}

}  // namespace

Pose dead_reckon(const KinematicState& s, DrAlgorithm algorithm, double dt) noexcept {
  Pose p{s.position, s.orientation};
  Eigen::Vector3d v = s.velocity, a = s.acceleration;
  int base = static_cast<int>(algorithm);
  if (base >= 6 && base <= 9) {  // body axes: rotate into world with the initial orientation
    const Eigen::Matrix3d r = to_quaternion(s.orientation).toRotationMatrix();
    v = r * v;
    a = r * a;
    base -= 4;
  }
  switch (base) {
    case 2:  // FPW
      p.position += v * dt;
      break;
    case 3:  // RPW
      p.position += v * dt;
      p.orientation = rotate(s.orientation, s.angular_velocity, dt);
      break;
    case 4:  // RVW
      p.position += v * dt + 0.5 * a * dt * dt;
      p.orientation = rotate(s.orientation, s.angular_velocity, dt);
      break;
    case 5:  // FVW
      p.position += v * dt + 0.5 * a * dt * dt;
      break;
    default:  // 0 other, 1 static
      break;
  }
  return p;
}

KinematicState kinematic_state(const EntityStatePdu& p) noexcept {
  KinematicState s;
  s.position = {p.location.x, p.location.y, p.location.z};
  s.velocity = {p.linear_velocity.x, p.linear_velocity.y, p.linear_velocity.z};
  const auto& dr = p.dead_reckoning;
  s.acceleration = {dr.linear_acceleration.x, dr.linear_acceleration.y, dr.linear_acceleration.z};
  s.orientation = {p.orientation.psi, p.orientation.theta, p.orientation.phi};
  s.angular_velocity = {dr.angular_velocity.x, dr.angular_velocity.y, dr.angular_velocity.z};
  return s;
}

void write_kinematics(const KinematicState& s, DrAlgorithm algorithm, EntityStatePdu& p) noexcept {
  p.location = {s.position.x(), s.position.y(), s.position.z()};
  p.linear_velocity = {static_cast<float>(s.velocity.x()), static_cast<float>(s.velocity.y()),
                       static_cast<float>(s.velocity.z())};
  p.orientation = {static_cast<float>(s.orientation.psi), static_cast<float>(s.orientation.theta),
                   static_cast<float>(s.orientation.phi)};
  auto& dr = p.dead_reckoning;
  dr.algorithm = static_cast<std::uint8_t>(algorithm);
  dr.linear_acceleration = {static_cast<float>(s.acceleration.x()),
                            static_cast<float>(s.acceleration.y()),
                            static_cast<float>(s.acceleration.z())};
  dr.angular_velocity = {static_cast<float>(s.angular_velocity.x()),
                         static_cast<float>(s.angular_velocity.y()),
                         static_cast<float>(s.angular_velocity.z())};
}

DrPublisher::Reason DrPublisher::needs_update(const KinematicState& truth,
                                              double now_s) const noexcept {
  if (!has_sent_) return Reason::First;
  const Pose believed = believed_pose(now_s);
  if ((truth.position - believed.position).norm() > thresholds_.position_threshold_m)
    return Reason::Position;
  if (orientation_error_rad(truth.orientation, believed.orientation) >
      thresholds_.orientation_threshold_rad)
    return Reason::Orientation;
  if (now_s - last_sent_s_ >= thresholds_.heartbeat_s) return Reason::Heartbeat;
  return Reason::None;
}

void DrPublisher::mark_sent(const KinematicState& sent, double now_s) noexcept {
  // Keep what receivers will see: the wire carries floats for all but the position.
  EntityStatePdu wire;
  write_kinematics(sent, algorithm_, wire);
  sent_ = kinematic_state(wire);
  last_sent_s_ = now_s;
  has_sent_ = true;
}

Pose DrPublisher::believed_pose(double now_s) const noexcept {
  return dead_reckon(sent_, algorithm_, now_s - last_sent_s_);
}

}  // namespace net
