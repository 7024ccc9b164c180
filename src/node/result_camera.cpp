#ifdef NPSNET_HAVE_RENDER
#include "node/result_camera.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/view.hpp"
#include "world/pose.hpp"

namespace npsnet::node {

namespace {
constexpr int kFrameW = 960, kFrameH = 540;    // the snapshot frame the share is judged in
constexpr double kKeepFirstShare = 0.9;        // a candidate this near the best one is as good
constexpr double kMinShareSeen = 0.5;          // less seen than this: the vehicle is drawn see-through
constexpr double kElevationsDeg[] = {20.0, 35.0, 55.0, 80.0};
constexpr size_t kMaxSamples = 96;             // object vertices tested at most
constexpr double kOccluderReachM = 40.0;       // entities this far beyond the object may hide it

struct Tri {
  Vec3 a, b, c;
};

// Entity polygons (fan-triangulated) near `centre`, but those of entity `except`.
std::vector<Tri> occluders(const world::World& w, const Vec3& centre, double reach, int except) {
  std::vector<Tri> out;
  const world::Entities& e = w.ents;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.active[i] || !e.pos[i].allFinite() || static_cast<int>(i) == except) continue;
    const world::Kind& k = w.kinds[e.kind[i]];
    if (k.models.empty() || (e.pos[i] - centre).norm() > reach + world::entity_radius(w, i) * 2) continue;
    const world::Model& m = w.models[k.models[std::clamp<size_t>(e.state[i], 0, k.models.size() - 1)]];
    const Mat3 r = world::pose_rotation(e.heading_deg[i], e.pitch_deg[i], e.roll_deg[i]);
    auto at = [&](uint32_t v) { return Vec3(e.pos[i] + r * m.vertices[m.face_vertices[v]].cast<double>()); };
    for (const auto& f : m.faces)
      for (uint32_t j = 1; j + 1 < f.count; ++j) out.push_back({at(f.first), at(f.first + j), at(f.first + j + 1)});
  }
  return out;
}

// Möller-Trumbore: does the segment from -> to cross the triangle before reaching `to`?
bool blocks(const Tri& t, const Vec3& from, const Vec3& to) {
  const Vec3 d = to - from, e1 = t.b - t.a, e2 = t.c - t.a;
  const Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-12) return false;
  const Vec3 s = from - t.a;
  const double u = s.dot(p) / det;
  if (u < 0 || u > 1) return false;
  const Vec3 q = s.cross(e1);
  const double v = d.dot(q) / det;
  if (v < 0 || u + v > 1) return false;
  const double h = e2.dot(q) / det;
  return h > 1e-6 && h < 1 - 0.02 / std::max(d.norm(), 0.02);  // 2 cm short of the point itself
}

std::vector<Vec3> object_points(const world::World& w, int o) {
  const world::Kind& k = w.kinds[w.fixed.kind[o]];
  std::vector<Vec3> pts;
  if (k.models.empty()) return pts;
  const world::Model& m = w.models[k.models[std::clamp<size_t>(w.fixed.state[o], 0, k.models.size() - 1)]];
  const Mat3 r = world::pose_rotation(w.fixed.heading_deg[o], 0, 0);
  const size_t step = std::max<size_t>(1, (m.vertices.size() + kMaxSamples - 1) / kMaxSamples);
  for (size_t v = 0; v < m.vertices.size(); v += step) pts.push_back(w.fixed.pos[o] + r * m.vertices[v].cast<double>());
  return pts;
}

bool on_screen(const render::ViewMath& vm, const Vec3& p) {
  double x, y;
  if (!render::project_to_pixel(vm, p, x, y)) return false;
  const double W = vm.width, H = vm.height;
  if (x < 0.02 * W || x > 0.98 * W || y < 0.02 * H || y > 0.98 * H) return false;
  if (x > W - 0.36 * H && y < 0.36 * H) return false;  // the map inset
  return !(x < 0.36 * W && y > 0.78 * H);              // the HUD panel
}

bool terrain_clear(const world::World& w, const Vec3& from, const Vec3& to) {
  for (int k = 1; k < 20; ++k) {
    const Vec3 q = from + (to - from) * (k / 20.0);
    if (w.terrain.height(q.x(), q.y()) > q.z() + 0.05) return false;
  }
  return true;
}

int seen(const world::World& w, const std::vector<Vec3>& pts, const std::vector<Tri>& occ, const render::Camera& cam) {
  const render::ViewMath vm = render::make_view(cam.eye, cam.target, cam.fov_y_deg, kFrameW, kFrameH, cam.up);
  int n = 0;
  for (const Vec3& p : pts) {
    if (!on_screen(vm, p) || !terrain_clear(w, cam.eye, p)) continue;
    bool hidden = false;
    for (const Tri& t : occ)
      if (blocks(t, cam.eye, p)) {
        hidden = true;
        break;
      }
    n += hidden ? 0 : 1;
  }
  return n;
}
}  // namespace

double object_visible_share(const world::World& w, int object, const render::Camera& cam) {
  const auto pts = object_points(w, object);
  if (pts.empty()) return 0;
  const auto occ = occluders(w, w.fixed.pos[object], kOccluderReachM + world::fixed_radius(w, object), -1);
  return static_cast<double>(seen(w, pts, occ, cam)) / static_cast<double>(pts.size());
}

render::Camera changed_object_camera(const world::World& w, int vehicle, int object) {
  const Vec3 o = w.fixed.pos[object];
  const double r = world::fixed_radius(w, object);
  const auto pts = object_points(w, object);
  Vec3 mid = o;
  if (!pts.empty()) {
    Vec3 lo = pts[0], hi = pts[0];
    for (const Vec3& p : pts) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    mid = 0.5 * (lo + hi);
  }
  const Vec3 target(mid.x(), mid.y(), std::max(mid.z(), o.z() + std::min(2.0, 0.3 * r)));  // its middle
  const Vec2 f = heading_to_dir(w.ents.heading_deg[vehicle]);
  const Vec2 side(-f.y(), f.x());
  const double d = std::max(14.0, 2.5 * r);
  auto make = [&](const Vec3& offset) {
    render::Camera c;
    c.target = target;
    c.eye = target + offset;
    c.eye.z() = std::max(c.eye.z(), w.terrain.height(c.eye.x(), c.eye.y()) + 1.5);
    return c;
  };
  std::vector<render::Camera> cands;
  // the side view of the vehicle's track: to its side, half a distance back, 0.8 d up
  cands.push_back(make(Vec3(side.x(), side.y(), 0) * d - Vec3(f.x(), f.y(), 0) * (0.5 * d) + Vec3(0, 0, 0.8 * d)));
  const double range = std::sqrt(1.0 + 0.25 + 0.64) * d;
  for (double up : kElevationsDeg)
    for (int k = 0; k < 12; ++k) {
      const Vec2 dir = heading_to_dir(dir_to_heading(side) + 30.0 * k);
      const double h = range * std::cos(deg2rad(up)), z = range * std::sin(deg2rad(up));
      cands.push_back(make(Vec3(dir.x() * h, dir.y() * h, z)));
    }
  if (pts.empty()) return cands[0];
  const Vec3 vc = world::entity_centre(w, vehicle);
  // The first candidate that sees at least kKeepFirstShare of the most any candidate sees
  // (preferring one with the vehicle in frame); the candidates' seen counts in `n`.
  auto choose = [&](const std::vector<Tri>& occ, int& seen_best) {
    std::vector<int> n(cands.size());
    for (size_t i = 0; i < cands.size(); ++i) n[i] = seen(w, pts, occ, cands[i]);
    seen_best = *std::max_element(n.begin(), n.end());
    size_t pick = cands.size();
    for (size_t i = 0; i < cands.size(); ++i) {
      if (n[i] < kKeepFirstShare * seen_best) continue;
      const render::Camera& c = cands[i];
      if (on_screen(render::make_view(c.eye, c.target, c.fov_y_deg, kFrameW, kFrameH, c.up), vc)) return i;
      if (pick == cands.size()) pick = i;
    }
    return pick;
  };
  int seen_best = 0;
  const size_t pick = choose(occluders(w, o, kOccluderReachM + r, -1), seen_best);
  if (seen_best >= kMinShareSeen * static_cast<double>(pts.size())) return cands[pick];
  // The vehicle sits on it (a stump under the tank): seen through the vehicle, drawn see-through.
  int seen_through = 0;
  render::Camera c = cands[choose(occluders(w, o, kOccluderReachM + r, vehicle), seen_through)];
  c.ghost_entity = vehicle;
  return c;
}

}  // namespace npsnet::node
#endif  // NPSNET_HAVE_RENDER
