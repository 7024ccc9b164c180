// Shape tiers of a model, cheapest first (issue 6): the bounding sphere (thesis), the oriented
// box (the model's bounding box in model space), the convex hull (GJK on the model's vertices:
// the hull's support points are the vertices'), and the exact polygon mesh (the faces fanned
// into triangles; zero-area triangles, from collinear vertices or degenerate faces, dropped;
// triangle-triangle separating-axis tests, boxes culling first). A pose maps model space to the
// local frame: world = rot * model + pos (metres).
#pragma once
#include <array>
#include <vector>

#include "collision/trace.hpp"
#include "core/math.hpp"
#include "world/collision_names.hpp"
#include "world/model.hpp"

namespace npsnet::collision {

struct Pose {
  Mat3 rot = Mat3::Identity();
  Vec3 pos{0, 0, 0};
};

struct Shape {
  Vec3 box_centre{0, 0, 0}, box_half{0, 0, 0};  // model space
  Vec3 sphere_centre{0, 0, 0};
  double bound_radius = 0;                       // every vertex lies within (from sphere_centre)
  double min_half = 0;                           // smallest box half extent (> 0)
  double pivot_radius = 0;                       // every vertex lies within this of the model origin (m)
  std::vector<Vec3> hull;                        // vertices
  std::vector<std::array<Vec3, 3>> tris;         // non-degenerate triangles
};
Shape make_shape(const world::Model& m);
// A standing trunk (tree, pole: kinds.toml trunk_radius_m): a vertical cylinder of radius r (m) from
// the model's foot to its top, as a prism of kTrunkSides sides around it (box: its square; hull
// and mesh: the prism), in place of the model's crown and branches.
inline constexpr int kTrunkSides = 8;
Shape make_trunk(const world::Model& m, double r);

struct ShapeScratch {  // reused buffers of the mesh test
  std::vector<std::array<Vec3, 3>> tb;
  std::vector<Vec3> lo_b, hi_b;
};

// True when the oriented boxes overlap (15-axis separating-axis test; touching counts).
bool box_overlap(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb);
// True when the convex hulls overlap (GJK; touching counts; a run that does not converge in
// 64 iterations answers true, so that a hull contact is never missed).
bool hull_overlap(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb);
// True when a triangle of a meets a triangle of b (surfaces intersect or touch). One mesh wholly
// inside the other without surface contact is not seen (the sweep finds the first touch first).
// When found and `point` is given: the mean of the points where the edges of the first meeting
// pair of triangles cross the other triangle (a point on their intersection).
bool mesh_overlap(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, ShapeScratch& s,
                  Vec3* point = nullptr);
// The same over a time interval: b moves by `d` (world frame, m) relative to a from the poses
// given, without turning. True when the shapes touch at some time of the interval (the moving
// shape swept along d is convex for a box, a hull and a triangle: GJK answers exactly).
// `margin` (m, >= 0): the shapes count as touching when they come within it (each triangle, hull
// or box grown by a ball of that radius: the turning search's bound, below).
bool box_overlap_swept(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const Vec3& d,
                       double margin = 0);
bool hull_overlap_swept(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const Vec3& d,
                        double margin = 0);
bool mesh_overlap_swept(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const Vec3& d,
                        ShapeScratch& s, double margin = 0);
// Time of impact of two shapes moving straight over a tick without turning: a's pose at
// fraction t is (a_end.rot, a_end.pos - a_move (1 - t)), likewise b's. Searches [t_in, t_out]
// up to `tier` (Box, Hull or Mesh; each step the cheapest tier that decides: a box apart says
// no): the whole interval first, then intervals of about the thinner shape's smallest half
// extent of relative motion (at most 64; each exactly, by the swept tests above), then halves
// the first that touches 20 times. A Trace with hit, fraction (the end of the last halving)
// and started_inside (touching at t_in); point and normal are the caller's. `decided`, when
// given, counts the tests each tier decided (index = ShapeTier).
Trace cast_shapes(const Shape& a, const Pose& a_end, const Vec3& a_move, const Shape& b, const Pose& b_end,
                  const Vec3& b_move, world::ShapeTier tier, double t_in, double t_out, ShapeScratch& s,
                  int64_t* decided = nullptr);
// A body turning during the tick (issue 13): its orientation goes from rot0 (start of the tick)
// to end.rot at a constant rate about one axis (the shortest way, slerp), its position straight
// from end.pos - move to end.pos. pose_at(t): its pose at fraction t.
struct Motion {
  Pose end;
  Vec3 move{0, 0, 0};
  Mat3 rot0 = Mat3::Identity();
  Pose pose_at(double t) const;
  double angle() const;  // the turn over the tick (rad, [0, pi])
};
// Time of impact of two turning bodies: conservative advancement with an angular bound. Over
// [t0, t1] every point of a shape lies within pivot_radius * angle * (t1 - t0) / 2 of where the
// shape turned to the middle of the interval puts it, so the swept test of the middle
// orientations grown by both bounds (margin) never misses a touch in [t0, t1]; "no" there
// clears the whole interval. Intervals that may touch are halved, earlier half first, until no
// point of either body moves more than kTurnTolM over one (or 2^-kTurnDepth of [t_in, t_out]):
// the first such interval that may touch ends at the time of impact, so the first touch is found
// to kTurnTolM and a body turning near but clear of another (by more than kTurnTolM) is cleared.
// At most kTurnTests tests a pair; past that the earliest interval not cleared counts as the
// touch (never a miss). Same tiers, answer and `decided` as cast_shapes (which the detector uses
// when neither body turns).
inline constexpr int kTurnDepth = 24, kTurnTests = 1024;
inline constexpr double kTurnTolM = 1e-4;
Trace cast_turning(const Shape& a, const Motion& ma, const Shape& b, const Motion& mb, world::ShapeTier tier,
                   double t_in, double t_out, ShapeScratch& s, int64_t* decided = nullptr);
// Triangle-triangle test (separating axes: the two normals and the nine edge cross products;
// coplanar pairs also the in-plane edge normals). A zero-area triangle has no surface: false.
bool tri_tri_overlap(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u);

}  // namespace npsnet::collision
