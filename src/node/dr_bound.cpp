// The local-frame dead-reckoning bound (dr_bound.hpp).
#include "node/dr_bound.hpp"

#include <cmath>

#include "node/pdu_build.hpp"

namespace npsnet::node {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
double wrapped_abs_deg(double d) {  // |d| wrapped to [0, 180]
  d = std::fabs(d);
  if (d >= 360.0) d = std::fmod(d, 360.0);
  return d > 180.0 ? 360.0 - d : d;
}
}  // namespace

bool dr_quiet(const DrAnchor& a, const net::DrPublisher& pub, const world::World& w, int e, double t) {
  if (!a.valid || !pub.has_sent() || pub.algorithm() != net::DrAlgorithm::RVW) return false;
  const net::DrThresholds& th = pub.thresholds();
  const double since = t - pub.last_sent_s();
  if (since >= th.heartbeat_s) return false;
  const Vec3 d = w.ents.pos[e] - a.p;
  const double nd = d.norm();
  if (!(nd <= kMaxAnchorDistM)) return false;
  // Orientation first: cheaper, and no bound at all for a vehicle turning.
  const auto& ents = w.ents;
  const net::KinematicState& s = pub.sent_state();
  const double rot = a.theta + s.angular_velocity.norm() * (t - a.t) +
                     (wrapped_abs_deg(ents.heading_deg[e] - a.heading) + std::fabs(ents.pitch_deg[e] - a.pitch) +
                      std::fabs(ents.roll_deg[e] - a.roll)) * kDeg +
                     kFrameTurnPerM * nd + kBoundEpsRad;
  if (!(rot < th.orientation_threshold_rad)) return false;
  const double tc = a.t - pub.last_sent_s();
  const Vec3 db = Eigen::Vector3d(s.velocity * (since - tc) + 0.5 * s.acceleration * (since * since - tc * tc));
  const double pos = (a.err + a.jac * d - db).norm() + 0.5 * kCurvaturePerM * nd * nd + kCurvaturePerM * nd + kBoundEpsM;
  return pos < th.position_threshold_m;
}

void dr_rebase(const net::KinematicState& s, const net::DrPublisher& pub, double t, DrAnchor& a) {
  const net::Pose b = pub.believed_pose(t);
  a.err = Vec3(s.position - b.position);
  a.theta = net::orientation_error_rad(s.orientation, b.orientation);
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
