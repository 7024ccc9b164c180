// Collision detection and response, the thesis's method (Osborne 1991, ch. III.C-D):
//  fixed objects: only below the threshold height, from the entity's gridsquare list, bounding
//    spheres (p. 9-10);
//  moving objects: L1 |dx| and |dy| both within 100 m (p. 11), L2 centre distance < sum of
//    radii, L3 two rays + Haines' crossings test (p. 15-19, Figure 6): real when the other's
//    polygon on the line of centres lies inside this object's sphere, else retried next tick;
//  response as Figure 8 (p. 22) with the constants of core/constants.hpp.
// detect() reports only the first tick of each contact episode; it reuses its buffers (no
// allocation per tick once warm). Positions in the local frame, metres; speeds m/s.
#pragma once
#include <cstdint>
#include <vector>

#include "world/changes.hpp"
#include "world/world.hpp"

namespace npsnet::collision {

struct Contact {
  int a = -1, b = -1;     // entity indices; b is a fixed-object index when b_fixed
  bool b_fixed = false;
  Vec3 point{0, 0, 0};    // contact point (local frame)
  Vec3 normal{0, 0, 1};   // unit, from a towards b
  const char* method = "";
};

struct DetectStats {
  int64_t fixed_tests = 0, l1_pairs = 0, l2_pairs = 0, l3_tests = 0, l3_rejects = 0, contacts = 0;
};

class Detector {
 public:
  // Finds the contacts that begin this tick (new episodes) and appends them to `out`.
  void detect(const world::World& w, std::vector<Contact>& out);
  const DetectStats& stats() const { return stats_; }

 private:
  std::vector<uint32_t> order_;         // active entities sorted by x (L1 sweep)
  std::vector<uint64_t> touching_, previous_;  // pair keys in contact this / last tick
  std::vector<Contact> candidates_;
  DetectStats stats_;
};

// ---- geometry (thesis Figures 4-6) ------------------------------------------------------------
// Haines' crossings test (Figure 6) on a polygon already projected to 2D and translated so the
// test point is the origin: a ray along +U' counts edge crossings; odd = inside. Points with
// V' = 0 count as positive, which puts points on edges and vertices consistently on one side.
bool haines_inside(const float* u, const float* v, int n);

// One answer type for rays against models (and later sweeps): fraction along the ray, point,
// face normal, which face, and whether the ray started inside.
struct RayHit {
  bool hit = false;
  double t = 0;           // distance along the unit direction (may be negative: behind origin)
  Vec3 point{0, 0, 0};
  Vec3 normal{0, 0, 1};
  int face = -1;
};
// Every face of `m` whose plane the line origin + t*dir (dir unit, model space) crosses inside
// the polygon (Haines on the dominant-axis projection) with t in [tmin, tmax]; the one with the
// smallest t. Degenerate faces (zero normal) and faces parallel to the ray are skipped.
RayHit ray_model(const world::Model& m, const Vec3& origin, const Vec3& dir, double tmin, double tmax);

// Thesis L3 for the pair (a sphere of this object, b the other object's model at its pose):
// the first ray from ca toward cb gives P on a's sphere; the second from P toward cb finds b's
// polygon on that line; real when that point lies inside a's sphere (|t| <= ra from ca).
bool l3_real(const world::World& w, int a, int b, Vec3& point);

// ---- response (Figure 8) ----------------------------------------------------------------------
// Angle of impact from the two compass headings, in [0, 360).
double impact_angle_deg(double heading_a, double heading_b);
// True in the Figure 8 bands: [85,95], [175,185], [265,275], <= 5, >= 355 (edges included).
bool in_kill_band(double angle_deg);
// Damage levels a fixed object takes from a vehicle's momentum (kg m/s), Figure 8 constants
// scaled by the object's resistance: 0 none, 1 low, 2 med, 3 high.
int fixed_damage_level(double momentum, double resistance);

// Turns contacts into changes and collision records (one per contact), by Figure 8.
void respond(const world::World& w, const std::vector<Contact>& contacts, world::Changes& out);
// A munition detonates at `point`: on an entity (`hit` >= 0) it kills it and leaves the ground
// untouched (p. 15); on the ground it makes a crater; either way objects and vehicles within the
// blast radius are damaged, more the nearer they are.
void detonate(const world::World& w, int munition, const Vec3& point, int hit, world::Changes& out);

}  // namespace npsnet::collision
