// The local-frame dead-reckoning bound (dr_bound.hpp).
#include "node/dr_bound.hpp"

#include <cmath>
#include <limits>

#include "node/pdu_build.hpp"

namespace npsnet::node {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr float kInf = std::numeric_limits<float>::infinity();
// x as a float (beyond the floats' range: an infinity; NaN stays NaN), and the same on the safe
// side: toward +kInf no smaller than x (float_up), toward -kInf no larger (float_down).
float to_float(double x) {
  if (std::abs(x) > std::numeric_limits<float>::max()) return x > 0 ? kInf : -kInf;
  return static_cast<float>(x);
}
float float_toward(double x, float side) {
  const float f = to_float(x);
  const bool wrong_side = side > 0 ? static_cast<double>(f) < x : static_cast<double>(f) > x;
  return wrong_side ? std::nextafter(f, side) : f;
}
float float_up(double x) { return float_toward(x, kInf); }
float float_down(double x) { return float_toward(x, -kInf); }
Vec3f to_float(const Vec3& v) { return {to_float(v.x()), to_float(v.y()), to_float(v.z())}; }
}  // namespace

DrQuick dr_quick(const DrAnchor& a, const net::DrPublisher& pub) {
  DrQuick q;
  q.has_sent = pub.has_sent();
  if (!a.valid || !pub.has_sent() || pub.algorithm() != net::DrAlgorithm::RVW) return q;
  const net::DrThresholds& th = pub.thresholds();
  const net::KinematicState& s = pub.sent_state();
  const Mat3 jtj = a.jac.transpose() * a.jac;
  const double row = jtj.cwiseAbs().rowwise().sum().maxCoeff();
  const Mat3 inv = a.jac.inverse();
  if (!(std::isfinite(row) && inv.allFinite() && std::abs(a.jac.determinant()) > 1e-6)) return q;
  q.sigma = float_up(std::sqrt(row) * (1 + 1e-12));
  q.p = a.p;
  q.err = to_float(inv * a.err), q.vel = to_float(inv * s.velocity), q.acc = to_float(inv * s.acceleration);
  // |rho|: the residuals of the kept (float) vectors, each twice for its own rounding, times the
  // largest factor each gets.
  const double hb = th.heartbeat_s;
  const double rho = 2 * ((a.err - a.jac * q.err.cast<double>()).norm() + (s.velocity - a.jac * q.vel.cast<double>()).norm() * hb +
                          (s.acceleration - a.jac * q.acc.cast<double>()).norm() * 0.5 * hb * hb) + 1e-9;
  q.t = a.t, q.last_sent = pub.last_sent_s();
  q.theta = float_up(a.theta), q.turn_rate = float_up(s.angular_velocity.norm());
  q.pos_limit = float_down(th.position_threshold_m - rho), q.rot_limit = float_down(th.orientation_threshold_rad);
  q.heartbeat_s = float_down(hb);
  q.heading = a.heading, q.pitch = a.pitch, q.roll = a.roll;
  q.usable = std::isfinite(q.err.squaredNorm() + q.vel.squaredNorm() + q.acc.squaredNorm() + q.sigma + q.theta +
                           q.turn_rate + q.pos_limit + q.rot_limit + q.heartbeat_s);
  return q;
}

bool dr_quiet(const DrQuick& q, const world::World& w, int e, double t) {
  if (!q.usable) return false;
  const double since = t - q.last_sent;
  if (since >= q.heartbeat_s) return false;
  const Vec3 d = w.ents.pos[e] - q.p;
  const double nd = d.norm();
  if (!(nd <= kMaxAnchorDistM)) return false;
  // Orientation first: cheaper, and no bound at all for a vehicle turning.
  const auto& ents = w.ents;
  const double rot = double(q.theta) + double(q.turn_rate) * (t - q.t) +
                     (std::fabs(wrap180(ents.heading_deg[e] - q.heading)) + std::fabs(ents.pitch_deg[e] - q.pitch) +
                      std::fabs(ents.roll_deg[e] - q.roll)) * kDeg +
                     kFrameTurnPerM * nd + kBoundEpsRad;
  if (!(rot < q.rot_limit)) return false;
  const double tc = q.t - q.last_sent;
  if (!(tc >= 0)) return false;  // (an anchor is made at or after the last send: rho's factors)
  const Vec3 x = q.err.cast<double>() + d -
                 (q.vel.cast<double>() * (since - tc) + 0.5 * q.acc.cast<double>() * (since * since - tc * tc));
  const double pos = double(q.sigma) * x.norm() + 0.5 * kCurvaturePerM * nd * nd + kCurvaturePerM * nd + kBoundEpsM;
  return pos < q.pos_limit;
}

void dr_rebase(const net::KinematicState& s, const net::DrPublisher& pub, double t, DrAnchor& a) {
  net::DrPublisher::Test test;
  test.believed = pub.believed_pose(t);
  test.orientation_error_rad = net::orientation_error_rad(s.orientation, test.believed.orientation);
  dr_rebase(s, test, t, a);
}

void dr_rebase(const net::KinematicState& s, const net::DrPublisher::Test& test, double t, DrAnchor& a) {
  a.err = Vec3(s.position - test.believed.position);
  a.theta = test.orientation_error_rad;
  a.t = t;
  a.valid = true;
}

net::KinematicState exact_state(const world::World& w, int e, DrAnchor& a) {
  // p into ECEF and DIS angles, and the Jacobian there (the one its velocity went through).
  geo::FrameMemo memo(w.terrain.frame());
  const net::KinematicState s = entity_truth(w, e, memo, &a.jac);
  a.p = w.ents.pos[e];
  a.heading = w.ents.heading_deg[e], a.pitch = w.ents.pitch_deg[e], a.roll = w.ents.roll_deg[e];
  a.valid = false;  // until dr_rebase
  return s;
}

}  // namespace npsnet::node
