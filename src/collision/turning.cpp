// Time of impact of two turning bodies (shapes.hpp: Motion, cast_turning): conservative
// advancement with an angular bound (issue 13).
#include <algorithm>

#include "collision/shapes.hpp"

namespace npsnet::collision {

Pose Motion::pose_at(double t) const {
  Pose p;
  p.pos = end.pos - move * (1 - t);
  if (t >= 1) {
    p.rot = end.rot;
  } else {
    const Eigen::Quaterniond q0(rot0), q1(end.rot);
    p.rot = q0.slerp(t, q1).toRotationMatrix();
  }
  return p;
}

double Motion::angle() const { return Eigen::Quaterniond(rot0).angularDistance(Eigen::Quaterniond(end.rot)); }

Trace cast_turning(const Shape& sa, const Motion& ma, const Shape& sb, const Motion& mb, world::ShapeTier tier,
                   double t_in, double t_out, ShapeScratch& scratch, int64_t* decided) {
  using world::ShapeTier;
  auto count = [&](ShapeTier t) {
    if (decided) ++decided[static_cast<int>(t)];
  };
  // Every point of a and b strays at most this far (m) per unit of the tick from where the
  // middle orientation of an interval puts it (arc <= radius * angle).
  const double spread = sa.pivot_radius * ma.angle() + sb.pivot_radius * mb.angle();
  int tests = 0;
  // May the shapes touch at some time in [t0, t1]? Positions at t0, b sweeping relative to a,
  // orientations of the middle of the interval, grown by the angular bound.
  auto touching = [&](double t0, double t1) {
    ++tests;
    const double tm = 0.5 * (t0 + t1);
    Pose pa = ma.pose_at(tm), pb = mb.pose_at(tm);
    pa.pos = ma.end.pos - ma.move * (1 - t0), pb.pos = mb.end.pos - mb.move * (1 - t0);
    const Vec3 d = (mb.move - ma.move) * (t1 - t0);
    const double margin = 0.5 * spread * (t1 - t0);
    if (!box_overlap_swept(sa, pa, sb, pb, d, margin)) {
      count(ShapeTier::Box);
      return false;
    }
    if (tier == ShapeTier::Box) return count(ShapeTier::Box), true;
    const bool hull = hull_overlap_swept(sa, pa, sb, pb, d, margin);
    if (!hull || tier == ShapeTier::Hull) return count(ShapeTier::Hull), hull;
    count(ShapeTier::Mesh);
    return mesh_overlap_swept(sa, pa, sb, pb, d, scratch, margin);
  };
  Trace out;
  if (!touching(t_in, t_out)) return out;
  if (touching(t_in, t_in)) {  // touching already at t_in
    out.hit = out.started_inside = true;
    out.fraction = t_in, out.exit_fraction = t_out;
    return out;
  }
  // Depth first, earlier half first: the first interval of the finest depth that may touch.
  // An interval is final when no point of either body moves more than kTurnTolM over it.
  const double speed = (ma.move - mb.move).norm() + spread;  // m per unit of the tick, at most
  const double leaf = std::max((t_out - t_in) / double(1 << kTurnDepth), kTurnTolM / std::max(speed, 1e-12));
  auto first = [&](auto&& self, double t0, double t1) -> double {
    if (!touching(t0, t1)) return -1;
    if (t1 - t0 <= leaf || tests >= kTurnTests) return t1;
    const double m = 0.5 * (t0 + t1);
    const double r = self(self, t0, m);
    return r >= 0 ? r : self(self, m, t1);
  };
  const double m = 0.5 * (t_in + t_out);
  double hi = first(first, t_in, m);
  if (hi < 0) hi = first(first, m, t_out);
  if (hi < 0) return out;
  out.hit = true;
  out.fraction = hi;
  out.exit_fraction = t_out;
  return out;
}

}  // namespace npsnet::collision
