// Shape tiers: oriented boxes (SAT), convex hulls (GJK), polygon meshes (triangle SAT).
#include "collision/shapes.hpp"

#include <algorithm>
#include <cmath>

namespace npsnet::collision {

Shape make_shape(const world::Model& m) {
  Shape s;
  const Vec3 lo = m.bbox_min.cast<double>(), hi = m.bbox_max.cast<double>();
  s.box_centre = 0.5 * (lo + hi);
  s.box_half = (0.5 * (hi - lo)).cwiseMax(Vec3::Constant(1e-3));
  s.min_half = s.box_half.minCoeff();
  s.sphere_centre = m.centre.cast<double>();
  s.hull.reserve(m.vertices.size());
  for (const Vec3f& v : m.vertices) {
    s.hull.push_back(v.cast<double>());
    s.bound_radius = std::max(s.bound_radius, (v.cast<double>() - s.sphere_centre).norm());
    s.pivot_radius = std::max(s.pivot_radius, v.cast<double>().norm());
  }
  for (const world::Face& f : m.faces) {
    const Vec3 p0 = m.vertices[m.face_vertices[f.first]].cast<double>();
    for (uint32_t k = 1; k + 1 < f.count; ++k) {
      const Vec3 p1 = m.vertices[m.face_vertices[f.first + k]].cast<double>();
      const Vec3 p2 = m.vertices[m.face_vertices[f.first + k + 1]].cast<double>();
      const double area2 = (p1 - p0).cross(p2 - p0).norm();
      const double scale = std::max({(p1 - p0).squaredNorm(), (p2 - p0).squaredNorm(), 1e-12});
      if (area2 <= 1e-9 * scale) continue;  // collinear or repeated vertices: zero area
      s.tris.push_back({p0, p1, p2});
    }
  }
  return s;
}

bool box_overlap(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb) {
  const Mat3& A = pa.rot;
  const Mat3& B = pb.rot;
  const Vec3 ca = pa.rot * a.box_centre + pa.pos, cb = pb.rot * b.box_centre + pb.pos;
  const Vec3 ea = a.box_half, eb = b.box_half;
  // R = A^T B expresses b's axes in a's frame; t = translation in a's frame.
  const Mat3 R = A.transpose() * B;
  Mat3 AbsR;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) AbsR(i, j) = std::abs(R(i, j)) + 1e-9;
  const Vec3 t = A.transpose() * (cb - ca);
  for (int i = 0; i < 3; ++i)
    if (std::abs(t[i]) > ea[i] + eb.dot(AbsR.row(i))) return false;
  for (int j = 0; j < 3; ++j)
    if (std::abs(t.dot(R.col(j))) > ea.dot(AbsR.col(j)) + eb[j]) return false;
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double ra = ea[i1] * AbsR(i2, j) + ea[i2] * AbsR(i1, j);
      const double rb = eb[j1] * AbsR(i, j2) + eb[j2] * AbsR(i, j1);
      if (std::abs(t[i2] * R(i1, j) - t[i1] * R(i2, j)) > ra + rb) return false;
    }
  }
  return true;
}

namespace {

// Support of a posed hull in world direction d.
Vec3 support(const Shape& s, const Pose& p, const Vec3& d) {
  const Vec3 dl = p.rot.transpose() * d;
  double best = -INFINITY;
  const Vec3* arg = &s.hull[0];
  for (const Vec3& v : s.hull) {
    const double x = v.dot(dl);
    if (x > best) best = x, arg = &v;
  }
  return p.rot * *arg + p.pos;
}

// Support of a posed box in world direction d.
Vec3 box_support(const Shape& s, const Pose& p, const Vec3& d) {
  const Vec3 dl = p.rot.transpose() * d;
  Vec3 c = s.box_centre;
  for (int k = 0; k < 3; ++k) c[k] += dl[k] >= 0 ? s.box_half[k] : -s.box_half[k];
  return p.rot * c + p.pos;
}

// A ball of radius m (the margin) added to a Minkowski difference: its support in direction v.
inline Vec3 grown(const Vec3& v, double m) {
  if (m <= 0) return Vec3::Zero();
  const double n = v.norm();
  return n > 0 ? Vec3(v * (m / n)) : Vec3::Zero();
}

// A shape swept along the segment 0..sweep: its support plus the segment's.
inline Vec3 swept(const Vec3& sup, const Vec3& sweep, const Vec3& d) { return sweep.dot(d) > 0 ? Vec3(sup + sweep) : sup; }

// Reduces the simplex to the feature nearest the origin and sets the new direction. True when
// the origin is enclosed (tetrahedron).
bool do_simplex(Vec3* s, int& n, Vec3& d) {
  auto same = [](const Vec3& x, const Vec3& y) { return x.dot(y) > 0; };
  if (n == 2) {
    const Vec3 a = s[1], b = s[0];
    const Vec3 ab = b - a, ao = -a;
    if (same(ab, ao)) {
      d = ab.cross(ao).cross(ab);
      if (d.squaredNorm() < 1e-30) return true;  // origin on the segment
    } else {
      s[0] = a, n = 1, d = ao;
    }
    return false;
  }
  if (n == 3) {
    const Vec3 a = s[2], b = s[1], c = s[0];
    const Vec3 ab = b - a, ac = c - a, ao = -a, abc = ab.cross(ac);
    if (same(abc.cross(ac), ao)) {
      if (same(ac, ao)) {
        s[0] = c, s[1] = a, n = 2, d = ac.cross(ao).cross(ac);
      } else {
        s[0] = b, s[1] = a, n = 2;
        return do_simplex(s, n, d);
      }
    } else if (same(ab.cross(abc), ao)) {
      s[0] = b, s[1] = a, n = 2;
      return do_simplex(s, n, d);
    } else {
      const double side = abc.dot(ao);
      if (std::abs(side) < 1e-30) return true;  // origin in the triangle's plane, inside it
      if (side > 0) d = abc;
      else s[0] = b, s[1] = c, d = -abc;  // keep winding so the normal faces the origin
    }
    if (d.squaredNorm() < 1e-30) return true;
    return false;
  }
  // tetrahedron: a newest
  const Vec3 a = s[3], b = s[2], c = s[1], dd = s[0];
  const Vec3 ao = -a, ab = b - a, ac = c - a, ad = dd - a;
  const Vec3 abc = ab.cross(ac), acd = ac.cross(ad), adb = ad.cross(ab);
  if (same(abc, ao)) {
    s[0] = c, s[1] = b, s[2] = a, n = 3;
    return do_simplex(s, n, d);
  }
  if (same(acd, ao)) {
    s[0] = dd, s[1] = c, s[2] = a, n = 3;
    return do_simplex(s, n, d);
  }
  if (same(adb, ao)) {
    s[0] = b, s[1] = dd, s[2] = a, n = 3;
    return do_simplex(s, n, d);
  }
  return true;
}

// GJK on the Minkowski difference given by its support function: true when it holds the
// origin (touching counts; 64 iterations without an answer count as overlap, and set
// *undecided when given: a near-parallel case where the simplex cycles).
template <class F>
bool gjk(F&& diff_support, Vec3 d, bool* undecided = nullptr) {
  if (d.squaredNorm() < 1e-18) d = Vec3::UnitX();
  Vec3 s[4];
  int n = 0;
  s[n++] = diff_support(d);
  d = -s[0];
  for (int it = 0; it < 64; ++it) {
    if (d.squaredNorm() < 1e-30) return true;  // origin on the simplex
    const Vec3 p = diff_support(d);
    if (p.dot(d) < 0) return false;  // the origin lies beyond the support plane: separated
    s[n++] = p;
    if (do_simplex(s, n, d)) return true;
  }
  if (undecided) *undecided = true;
  return true;
}

// Triangle t against the prism u sweeps along dl, grown by margin: apart along some axis of
// the separating-axis theorem (the faces' normals and the edges' cross products; exact for the
// two polytopes, conservative for the margin's rounding). GJK's fallback when it cycles.
bool tri_prism_apart(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u, const Vec3& dl, double margin) {
  const Vec3 te[3] = {t[1] - t[0], t[2] - t[1], t[0] - t[2]};
  const Vec3 ue[4] = {u[1] - u[0], u[2] - u[1], u[0] - u[2], dl};
  auto apart = [&](const Vec3& n) {
    const double len = n.norm();
    if (!(len > 1e-12 * (1 + te[0].squaredNorm() + ue[0].squaredNorm() + dl.squaredNorm()))) return false;
    double tlo = INFINITY, thi = -INFINITY, ulo = INFINITY, uhi = -INFINITY;
    for (const Vec3& v : t) tlo = std::min(tlo, v.dot(n)), thi = std::max(thi, v.dot(n));
    const double sweep = dl.dot(n);
    for (const Vec3& v : u) {
      const double x = v.dot(n);
      ulo = std::min({ulo, x, x + sweep}), uhi = std::max({uhi, x, x + sweep});
    }
    return tlo - uhi > margin * len || ulo - thi > margin * len;
  };
  if (apart(te[0].cross(te[1])) || apart(ue[0].cross(ue[1]))) return true;
  for (int i = 0; i < 3; ++i)
    if (apart(ue[i].cross(dl))) return true;
  for (const Vec3& a : te)
    for (const Vec3& b : ue)
      if (apart(a.cross(b))) return true;
  return false;
}

}  // namespace

bool hull_overlap(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb) {
  return hull_overlap_swept(a, pa, b, pb, Vec3::Zero());
}

bool hull_overlap_swept(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const Vec3& d, double margin) {
  if (a.hull.empty() || b.hull.empty()) return false;
  const Vec3 d0 = (pb.rot * b.sphere_centre + pb.pos) - (pa.rot * a.sphere_centre + pa.pos);
  return gjk([&](const Vec3& v) { return Vec3(support(a, pa, v) - swept(support(b, pb, -v), d, -v) + grown(v, margin)); }, d0);
}

bool box_overlap_swept(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const Vec3& d, double margin) {
  if (d.squaredNorm() == 0 && margin <= 0) return box_overlap(a, pa, b, pb);
  const Vec3 d0 = (pb.rot * b.box_centre + pb.pos) - (pa.rot * a.box_centre + pa.pos);
  return gjk([&](const Vec3& v) {
    return Vec3(box_support(a, pa, v) - swept(box_support(b, pb, -v), d, -v) + grown(v, margin));
  }, d0);
}

namespace {

inline void tri_box(const std::array<Vec3, 3>& t, Vec3& lo, Vec3& hi) {
  lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]);
  hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
}

// Where segment p-q crosses triangle t (both inclusive); true with the point.
bool segment_triangle(const Vec3& p, const Vec3& q, const std::array<Vec3, 3>& t, Vec3& x) {
  const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]);
  const double dp = n.dot(p - t[0]), dq = n.dot(q - t[0]);
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) return false;
  const double s = dp / (dp - dq);
  x = p + s * (q - p);
  for (int k = 0; k < 3; ++k) {
    const Vec3& v0 = t[k];
    const Vec3& v1 = t[(k + 1) % 3];
    if (n.dot((v1 - v0).cross(x - v0)) < -1e-12 * n.squaredNorm()) return false;
  }
  return true;
}

Vec3 intersection_point(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u) {
  Vec3 sum = Vec3::Zero(), x;
  int cnt = 0;
  for (int k = 0; k < 3; ++k) {
    if (segment_triangle(t[k], t[(k + 1) % 3], u, x)) sum += x, ++cnt;
    if (segment_triangle(u[k], u[(k + 1) % 3], t, x)) sum += x, ++cnt;
  }
  if (cnt > 0) return sum / cnt;
  // Coplanar or touching only at a point the edges miss by rounding: the nearer vertex pair.
  double best = INFINITY;
  Vec3 m = t[0];
  for (const Vec3& p : t)
    for (const Vec3& q : u)
      if ((p - q).squaredNorm() < best) best = (p - q).squaredNorm(), m = 0.5 * (p + q);
  return m;
}

}  // namespace

bool tri_tri_overlap(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u) {
  auto separated = [&](const Vec3& ax) {
    const double l2 = ax.squaredNorm();
    if (l2 < 1e-20) return false;  // parallel edges: not a valid axis
    double t0 = t[0].dot(ax), t1 = t0, u0 = u[0].dot(ax), u1 = u0;
    for (int k = 1; k < 3; ++k) {
      const double a = t[k].dot(ax), b = u[k].dot(ax);
      t0 = std::min(t0, a), t1 = std::max(t1, a), u0 = std::min(u0, b), u1 = std::max(u1, b);
    }
    const double eps = 1e-12 * std::sqrt(l2);
    return t1 < u0 - eps || u1 < t0 - eps;
  };
  const Vec3 et[3] = {t[1] - t[0], t[2] - t[1], t[0] - t[2]};
  const Vec3 eu[3] = {u[1] - u[0], u[2] - u[1], u[0] - u[2]};
  const Vec3 nt = et[0].cross(et[1]), nu = eu[0].cross(eu[1]);
  if (nt.squaredNorm() < 1e-24 || nu.squaredNorm() < 1e-24) return false;  // zero area: no surface
  if (separated(nt) || separated(nu)) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (separated(et[i].cross(eu[j]))) return false;
  // Coplanar triangles: the in-plane edge normals separate them.
  if (nt.cross(nu).squaredNorm() < 1e-12 * nt.squaredNorm() * nu.squaredNorm()) {
    for (int i = 0; i < 3; ++i)
      if (separated(nt.cross(et[i])) || separated(nu.cross(eu[i]))) return false;
  }
  return true;
}

bool mesh_overlap(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, ShapeScratch& s, Vec3* point) {
  // Work in a's model space: b's triangles moved there once.
  const Mat3 r = pa.rot.transpose() * pb.rot;
  const Vec3 t = pa.rot.transpose() * (pb.pos - pa.pos);
  s.tb.resize(b.tris.size());
  s.lo_b.resize(b.tris.size());
  s.hi_b.resize(b.tris.size());
  Vec3 blo = Vec3::Constant(INFINITY), bhi = Vec3::Constant(-INFINITY);
  for (size_t k = 0; k < b.tris.size(); ++k) {
    for (int v = 0; v < 3; ++v) s.tb[k][v] = r * b.tris[k][v] + t;
    tri_box(s.tb[k], s.lo_b[k], s.hi_b[k]);
    blo = blo.cwiseMin(s.lo_b[k]), bhi = bhi.cwiseMax(s.hi_b[k]);
  }
  for (const auto& ta : a.tris) {
    Vec3 lo, hi;
    tri_box(ta, lo, hi);
    if ((lo.array() > bhi.array()).any() || (hi.array() < blo.array()).any()) continue;
    for (size_t k = 0; k < s.tb.size(); ++k) {
      if ((lo.array() > s.hi_b[k].array()).any() || (hi.array() < s.lo_b[k].array()).any()) continue;
      if (!tri_tri_overlap(ta, s.tb[k])) continue;
      if (point) *point = pa.rot * intersection_point(ta, s.tb[k]) + pa.pos;
      return true;
    }
  }
  return false;
}

bool mesh_overlap_swept(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const Vec3& d,
                        ShapeScratch& s, double margin) {
  if (d.squaredNorm() == 0 && margin <= 0) return mesh_overlap(a, pa, b, pb, s);
  // In a's model space: b's triangles at the start, and their sweep.
  const Mat3 r = pa.rot.transpose() * pb.rot;
  const Vec3 t = pa.rot.transpose() * (pb.pos - pa.pos);
  const Vec3 dl = pa.rot.transpose() * d;
  s.tb.resize(b.tris.size());
  s.lo_b.resize(b.tris.size());
  s.hi_b.resize(b.tris.size());
  Vec3 blo = Vec3::Constant(INFINITY), bhi = Vec3::Constant(-INFINITY);
  for (size_t k = 0; k < b.tris.size(); ++k) {
    for (int v = 0; v < 3; ++v) s.tb[k][v] = r * b.tris[k][v] + t;
    tri_box(s.tb[k], s.lo_b[k], s.hi_b[k]);
    s.lo_b[k] = s.lo_b[k].cwiseMin(s.lo_b[k] + dl) - Vec3::Constant(margin);
    s.hi_b[k] = s.hi_b[k].cwiseMax(s.hi_b[k] + dl) + Vec3::Constant(margin);
    blo = blo.cwiseMin(s.lo_b[k]), bhi = bhi.cwiseMax(s.hi_b[k]);
  }
  auto tri_support = [](const std::array<Vec3, 3>& q, const Vec3& v) {
    const double x0 = q[0].dot(v), x1 = q[1].dot(v), x2 = q[2].dot(v);
    return x0 >= x1 && x0 >= x2 ? q[0] : x1 >= x2 ? q[1] : q[2];
  };
  for (const auto& ta : a.tris) {
    Vec3 lo, hi;
    tri_box(ta, lo, hi);
    if ((lo.array() > bhi.array()).any() || (hi.array() < blo.array()).any()) continue;
    for (size_t k = 0; k < s.tb.size(); ++k) {
      if ((lo.array() > s.hi_b[k].array()).any() || (hi.array() < s.lo_b[k].array()).any()) continue;
      const auto& tb = s.tb[k];
      // The prism b's triangle sweeps, against a's triangle (a at rest in its own frame).
      const Vec3 d0 = (tb[0] + tb[1] + tb[2]) / 3 + 0.5 * dl - (ta[0] + ta[1] + ta[2]) / 3;
      bool undecided = false;
      if (gjk([&](const Vec3& v) { return Vec3(tri_support(ta, v) - swept(tri_support(tb, -v), dl, -v) + grown(v, margin)); },
              d0, &undecided) &&
          !(undecided && tri_prism_apart(ta, tb, dl, margin)))
        return true;
    }
  }
  return false;
}

namespace {
// cast_shapes' search: intervals of about the thinner shape's smallest half extent of relative
// motion, at most kMaxSamples a pair; the first that touches halved kBisections times (the time
// of impact to 2^-20 of the interval).
constexpr double kSampleFraction = 1.0;
constexpr int kMaxSamples = 64;
constexpr int kBisections = 20;
constexpr int kResumes = 4;  // touches passed over (above), at most, before the next one is taken
}  // namespace

Trace cast_shapes(const Shape& sa, const Pose& a_end, const Vec3& va, const Shape& sb, const Pose& b_end,
                  const Vec3& vb, world::ShapeTier tier, double t_in, double t_out, ShapeScratch& scratch,
                  int64_t* decided) {
  using world::ShapeTier;
  auto count = [&](ShapeTier t) {
    if (decided) ++decided[static_cast<int>(t)];
  };
  auto poses = [&](double t, Pose& pa, Pose& pb) {
    pa.rot = a_end.rot, pa.pos = a_end.pos - va * (1 - t);
    pb.rot = b_end.rot, pb.pos = b_end.pos - vb * (1 - t);
  };
  // Do the shapes touch at some time in [t0, t1]? b sweeps relative to a; the cheapest tier
  // that decides: a box apart decides "no", the pair's tier decides "yes" (each sweep exact).
  auto touching = [&](double t0, double t1) {
    Pose pa, pb;
    poses(t0, pa, pb);
    const Vec3 d = (vb - va) * (t1 - t0);
    if (!box_overlap_swept(sa, pa, sb, pb, d)) {
      count(ShapeTier::Box);
      return false;
    }
    if (tier == ShapeTier::Box) return count(ShapeTier::Box), true;
    const bool hull = hull_overlap_swept(sa, pa, sb, pb, d);
    if (!hull || tier == ShapeTier::Hull) return count(ShapeTier::Hull), hull;
    count(ShapeTier::Mesh);
    return mesh_overlap_swept(sa, pa, sb, pb, d, scratch);
  };
  Trace out;
  const double rel = (va - vb).norm();
  const double step = kSampleFraction * std::max(1e-3, std::min(sa.min_half, sb.min_half));
  int n = rel > 0 ? static_cast<int>(std::ceil(rel * (t_out - t_in) / step)) : 1;
  n = std::clamp(n, 1, kMaxSamples);
  // The whole interval first: most pairs whose bounds meet never touch, and one exact swept
  // test per tier says so.
  if (!touching(t_in, t_out)) return out;
  if (touching(t_in, t_in)) {  // touching already at t_in
    out.hit = out.started_inside = true;
    out.fraction = t_in, out.exit_fraction = t_out;
    return out;
  }
  double lo = t_in, hi = -1;
  int s = 1;
  for (int pass = 0;; ++pass) {
    for (; s <= n && hi < 0; ++s) {
      const double t = t_in + (t_out - t_in) * s / n;
      if (t <= lo) continue;  // (a resumed scan: within the interval passed over)
      if (touching(lo, t)) hi = t;
      else lo = t;
    }
    if (hi < 0) return out;
    // No touch in [t_in, lo); a touch in [lo, hi]: halve down to the first.
    for (int i = 0; i < kBisections && hi > lo; ++i) {
      const double m = 0.5 * (lo + hi);
      (touching(lo, m) ? hi : lo) = m;
    }
    // Every half after the first that touched said no: the last interval was never tested. When
    // it does not touch, the touch of a longer interval was not real (GJK counts a near-parallel
    // case it cannot settle as a touch), and halving it gave a time before any contact: the
    // scan goes on after it.
    if (pass == kResumes || hi <= lo || touching(lo, hi)) break;
    lo = hi, hi = -1, s = 1;  // the samples from the first after lo
  }
  out.hit = true;
  out.fraction = hi;
  out.exit_fraction = t_out;
  return out;
}

}  // namespace npsnet::collision
