// Haines' crossings test and ray/model intersection (thesis Figures 4-6, Glassner 1989 p. 56).
#include <cmath>
#include <limits>

#include "collision/collision.hpp"
#include "world/pose.hpp"

namespace npsnet::collision {

bool haines_inside(const float* u, const float* v, int n) {
  if (n < 3) return false;
  int crossings = 0;
  int sh = v[0] < 0 ? -1 : 1;  // sign holder of V'a (zero counts as positive)
  for (int a = 0; a < n; ++a) {
    const int b = (a + 1) % n;
    const int nsh = v[b] < 0 ? -1 : 1;
    if (sh != nsh) {  // the edge crosses the U' axis
      if (u[a] > 0 && u[b] > 0) {
        ++crossings;  // both to the right: it crosses +U'
      } else if (u[a] > 0 || u[b] > 0) {
        // might cross: where does the edge meet V' = 0?
        if (u[a] - v[a] * (u[b] - u[a]) / (v[b] - v[a]) > 0) ++crossings;
      }
    }
    sh = nsh;
  }
  return (crossings & 1) != 0;
}

Trace ray_model(const world::Model& m, const Vec3& origin, const Vec3& dir, double tmin, double tmax) {
  Trace best;
  double best_t = std::numeric_limits<double>::infinity();
  constexpr int kMaxPoly = 64;
  float u[kMaxPoly], v[kMaxPoly];
  for (size_t f = 0; f < m.faces.size(); ++f) {
    const world::Face& face = m.faces[f];
    const Vec3 n = face.normal.cast<double>();
    if (n.squaredNorm() == 0 || face.count > kMaxPoly) continue;  // degenerate (zero area)
    const double denom = n.dot(dir);
    if (std::abs(denom) < 1e-12) continue;  // parallel to the plane
    const Vec3 v0 = m.vertices[m.face_vertices[face.first]].cast<double>();
    const double t = n.dot(v0 - origin) / denom;
    if (t < tmin || t > tmax || t >= best_t) continue;
    const Vec3 q = origin + t * dir;
    // Dominant axis of the normal: project onto the other two (U, V), translate q to the origin.
    int drop = 0;
    if (std::abs(n.y()) > std::abs(n[drop])) drop = 1;
    if (std::abs(n.z()) > std::abs(n[drop])) drop = 2;
    const int iu = drop == 0 ? 1 : 0, iv = drop == 2 ? 1 : 2;
    for (uint32_t k = 0; k < face.count; ++k) {
      const Vec3f& p = m.vertices[m.face_vertices[face.first + k]];
      u[k] = static_cast<float>(p[iu] - q[iu]);
      v[k] = static_cast<float>(p[iv] - q[iv]);
    }
    if (!haines_inside(u, v, static_cast<int>(face.count))) continue;
    best.hit = true;
    best_t = t;
    best.point = q;
    best.normal = n;
    best.face = static_cast<int>(f);
  }
  if (best.hit) {
    best.fraction = tmax > tmin ? (best_t - tmin) / (tmax - tmin) : 0.0;
    best.started_inside = best.normal.dot(dir) > 0;
  }
  return best;
}

bool l3_real(const world::World& w, int a, int b, Vec3& point) {
  const auto& ents = w.ents;
  const Vec3 ca = world::entity_centre(w, a), cb = world::entity_centre(w, b);
  const world::Kind& kb = w.kinds[ents.kind[b]];
  const double ra = world::entity_radius(w, a);
  const Vec3 ab = cb - ca;
  const double dist = ab.norm();
  if (dist < 1e-9) {  // coincident centres: the bodies certainly overlap
    point = ca;
    return true;
  }
  const Vec3 d = ab / dist;
  const Vec3 p = ca + ra * d;  // first ray: the point on this object's sphere
  // Second ray, from P toward b's centre, in b's model space. Its parameter s from P: the polygon
  // point lies inside a's sphere when s is in [-2 ra, 0] (between the sphere's far and near
  // surface on this line), i.e. the surfaces have met.
  const Mat3 rb = world::pose_rotation(ents.heading_deg[b], ents.pitch_deg[b], ents.roll_deg[b]);
  const Vec3 po = rb.transpose() * (p - ents.pos[b]);
  const Vec3 dir = rb.transpose() * d;
  const double tmin = -2 * ra, tmax = dist - ra;
  const Trace h = ray_model(w.models[kb.models[ents.state[b]]], po, dir, tmin, tmax);
  if (!h.hit) return false;
  const double t = (h.point - po).dot(dir);  // along the ray from P (dir is unit)
  if (t > 0) return false;
  point = p + t * d;
  return true;
}

}  // namespace npsnet::collision
