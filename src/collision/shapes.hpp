// Shape tiers of a model, cheapest first (issue 6): the bounding sphere (thesis), the oriented
// box (the model's bounding box in model space), the convex hull (GJK on the model's vertices:
// the hull's support points are the vertices'), and the exact polygon mesh (the faces fanned
// into triangles; zero-area triangles, from collinear vertices or degenerate faces, dropped;
// triangle-triangle separating-axis tests, boxes culling first). A pose maps model space to the
// local frame: world = rot * model + pos (metres).
#pragma once
#include <array>
#include <vector>

#include "core/math.hpp"
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
  std::vector<Vec3> hull;                        // vertices
  std::vector<std::array<Vec3, 3>> tris;         // non-degenerate triangles
};
Shape make_shape(const world::Model& m);

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
bool box_overlap_swept(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const Vec3& d);
bool hull_overlap_swept(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const Vec3& d);
bool mesh_overlap_swept(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const Vec3& d,
                        ShapeScratch& s);
// Triangle-triangle test (separating axes: the two normals and the nine edge cross products;
// coplanar pairs also the in-plane edge normals). A zero-area triangle has no surface: false.
bool tri_tri_overlap(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u);

}  // namespace npsnet::collision
