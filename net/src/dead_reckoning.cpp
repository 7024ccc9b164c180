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

Eigen::Matrix3d skew(const Eigen::Vector3d& u) {
  Eigen::Matrix3d m;
  m << 0, -u.z(), u.y(), u.z(), 0, -u.x(), -u.y(), u.x(), 0;
  return m;
}

// Annex E (E.6) body-axis integrals for body rates w over t, about the unit axis u = w/|w|,
// c = |w|: exp([w] t) = u u' + cos(ct) (I - u u') + sin(ct) [u];
// R1 = int_0^t exp([w] s) ds = t u u' + sin(ct)/c (I - u u') + (1 - cos(ct))/c [u];
// R2 = int_0^t s exp([w] s) ds = t^2/2 u u' + (t sin(ct)/c + (cos(ct) - 1)/c^2) (I - u u')
//                               + (sin(ct)/c^2 - t cos(ct)/c) [u].
// Below 1e-9 rad/s the limits (R1 = t I, R2 = t^2/2 I) hold to double precision.
struct BodyIntegrals {
  Eigen::Matrix3d rot, r1, r2;
};
BodyIntegrals body_integrals(const Eigen::Vector3d& w, double t) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const double c = w.norm();
  if (!(c > 1e-9) || !std::isfinite(c)) return {I, t * I, 0.5 * t * t * I};
  const Eigen::Vector3d u = w / c;
  const Eigen::Matrix3d uu = u * u.transpose(), perp = I - uu, k = skew(u);
  const double ct = c * t, sn = std::sin(ct), cs = std::cos(ct);
  return {uu + cs * perp + sn * k,                                   //
          t * uu + (sn / c) * perp + ((1 - cs) / c) * k,             //
          0.5 * t * t * uu + (t * sn / c + (cs - 1) / (c * c)) * perp + (sn / (c * c) - t * cs / c) * k};
}

}  // namespace

Pose dead_reckon(const KinematicState& s, DrAlgorithm algorithm, double dt) noexcept {
  Pose p{s.position, s.orientation, s.velocity};
  const Eigen::Vector3d& v = s.velocity;
  const Eigen::Vector3d& a = s.acceleration;
  const int alg = static_cast<int>(algorithm);
  if (alg >= 6 && alg <= 9) {  // body axes
    const Eigen::Matrix3d r0 = to_quaternion(s.orientation).toRotationMatrix();
    const bool rotating = alg == 7 || alg == 8;
    const bool accel = alg == 8 || alg == 9;
    const Eigen::Vector3d w = rotating ? s.angular_velocity : Eigen::Vector3d::Zero();
    const BodyIntegrals b = body_integrals(w, dt);
    p.position += r0 * (b.r1 * v + (accel ? Eigen::Vector3d(b.r2 * a) : Eigen::Vector3d::Zero()));
    p.velocity = r0 * b.rot * (accel ? Eigen::Vector3d(v + a * dt) : v);
    if (rotating) p.orientation = rotate(s.orientation, s.angular_velocity, dt);
    return p;
  }
  switch (alg) {
    case 2:  // FPW
      p.position += v * dt;
      break;
    case 3:  // RPW
      p.position += v * dt;
      p.orientation = rotate(s.orientation, s.angular_velocity, dt);
      break;
    case 4:  // RVW
      p.position += v * dt + 0.5 * a * dt * dt;
      p.velocity = v + a * dt;
      p.orientation = rotate(s.orientation, s.angular_velocity, dt);
      break;
    case 5:  // FVW
      p.position += v * dt + 0.5 * a * dt * dt;
      p.velocity = v + a * dt;
      break;
    default:  // 0 other, 1 static
      p.velocity.setZero();
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
  p.linear_velocity = wire_vec3f(s.velocity.x(), s.velocity.y(), s.velocity.z());
  p.orientation = {wire_float(s.orientation.psi), wire_float(s.orientation.theta), wire_float(s.orientation.phi)};
  auto& dr = p.dead_reckoning;
  dr.algorithm = static_cast<std::uint8_t>(algorithm);
  dr.linear_acceleration = wire_vec3f(s.acceleration.x(), s.acceleration.y(), s.acceleration.z());
  dr.angular_velocity = wire_vec3f(s.angular_velocity.x(), s.angular_velocity.y(), s.angular_velocity.z());
}

DrPublisher::Test DrPublisher::test(const KinematicState& truth, double now_s) const noexcept {
  Test r;
  if (!has_sent_) return r;  // Reason::First
  r.believed = believed_pose(now_s);
  if ((truth.position - r.believed.position).norm() > thresholds_.position_threshold_m) {
    r.reason = Reason::Position;
    return r;
  }
  r.orientation_error_rad = orientation_error_rad(truth.orientation, r.believed.orientation);
  r.reason = r.orientation_error_rad > thresholds_.orientation_threshold_rad ? Reason::Orientation
             : now_s - last_sent_s_ >= thresholds_.heartbeat_s                ? Reason::Heartbeat
                                                                              : Reason::None;
  return r;
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
