// The oracle of the accuracy benchmarks (bench_accuracy, bench_budget_error): FCL 0.7's exact
// mesh-mesh distance on our shapes' triangles (support/fcl_mesh.hpp), advanced conservatively in
// time. Two bodies move straight over a tick without turning: a's pose at fraction t is
// (ra, a_end - a_move (1 - t)), likewise b's. The distance shrinks at most at the relative speed,
// so stepping t += (distance - touch / 2) / |a_move - b_move| from t0 never skips the first
// touch; the answer is the first t within `touch` (m) before t1. Benchmarks only, never the engine.
#pragma once
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <memory>

#include "support/fcl_mesh.hpp"

namespace npsnet::bench {

inline constexpr double kTouchM = 1e-6;  // within this: touching
inline constexpr double kNearM = 1e-3;   // within this without touching: a graze (no verdict)

struct FclToi {
  bool hit = false;             // within kTouchM at some t in [t0, t1]
  bool started_inside = false;  // already at t0 == 0, overlapping
  bool graze = false;           // came within kNearM but never touched
  bool converged = true;        // false: the step limit ran out first (no verdict either)
  double t = 1;                 // the first touch (fraction of the tick)
  double distance = 0;          // FCL's distance there (m)
  Vec3 point{0, 0, 0};          // the middle of FCL's two nearest points there (local frame)
  int queries = 0;              // FCL distance queries made
};

inline fcl::Transform3d fcl_pose(const Mat3& r, const Vec3& p) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  t.linear() = r;
  t.translation() = p;
  return t;
}

inline FclToi fcl_toi(const std::shared_ptr<test::FclMesh>& ma, const Mat3& ra, const Vec3& a_end, const Vec3& a_move,
                      const std::shared_ptr<test::FclMesh>& mb, const Mat3& rb, const Vec3& b_end, const Vec3& b_move,
                      double t0 = 0, double t1 = 1, int max_steps = 600) {
  FclToi r;
  fcl::CollisionObjectd oa(ma), ob(mb);
  const double per_t = (a_move - b_move).norm();  // metres of relative travel per unit of t
  double t = t0;
  bool near = false;
  for (int it = 0; it < max_steps; ++it) {
    oa.setTransform(fcl_pose(ra, a_end - a_move * (1 - t)));
    ob.setTransform(fcl_pose(rb, b_end - b_move * (1 - t)));
    fcl::DistanceRequestd req(true);
    fcl::DistanceResultd res;
    fcl::distance(&oa, &ob, req, res);
    ++r.queries;
    near = near || res.min_distance <= kNearM;
    if (res.min_distance <= kTouchM) {
      r.hit = true;
      r.t = t;
      r.started_inside = it == 0 && t == 0 && res.min_distance <= 0;
      r.point = 0.5 * (res.nearest_points[0] + res.nearest_points[1]);
      r.distance = res.min_distance;
      break;
    }
    if (per_t <= 0) break;
    t += (res.min_distance - 0.5 * kTouchM) / per_t;
    if (t > t1) break;
    if (it == max_steps - 1) r.converged = false;
  }
  r.graze = near && !r.hit;
  return r;
}

}  // namespace npsnet::bench
