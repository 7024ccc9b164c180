// Camera presets (renderer.hpp): the snapshot view of a colliding pair and a vehicle's own eye.
#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "render/renderer.hpp"

namespace npsnet::render {

Camera look_at_pair(const world::World& w, const Vec3& a, const Vec3& b) {
  const Vec3 mid = 0.5 * (a + b);
  Vec2 dir(b.x() - a.x(), b.y() - a.y());
  const double sep = dir.norm();
  dir = sep > 1e-6 ? Vec2(dir / sep) : Vec2(0, 1);
  const Vec2 side(-dir.y(), dir.x());
  const double dist = std::max(30.0, 1.3 * sep + 20.0);
  Camera c;
  c.fov_y_deg = 50;
  c.target = mid + Vec3(0, 0, 1.5);
  Vec3 eye = mid + Vec3(side.x(), side.y(), 0) * (0.9 * dist) - Vec3(dir.x(), dir.y(), 0) * (0.3 * dist);
  eye.z() = std::max(mid.z(), w.terrain.height(eye.x(), eye.y())) + std::max(8.0, 0.35 * dist);
  // raise the eye until the terrain no longer hides the target (bounded)
  for (int tries = 0; tries < 20; ++tries) {
    bool blocked = false;
    for (int k = 1; k < 24 && !blocked; ++k) {
      const Vec3 q = eye + (c.target - eye) * (k / 24.0);
      blocked = w.terrain.height(q.x(), q.y()) > q.z() - 1.0;
    }
    if (!blocked) break;
    eye.z() += 0.15 * dist;
  }
  c.eye = eye;
  return c;
}

Camera vehicle_eye(const Vec3& pos, double heading_deg, double pitch_deg, double eye_height_m) {
  const Vec2 d = heading_to_dir(heading_deg);
  const double cp = std::cos(deg2rad(pitch_deg)), sp = std::sin(deg2rad(pitch_deg));
  Camera c;
  c.eye = pos + Vec3(0, 0, eye_height_m);
  c.target = c.eye + Vec3(d.x() * cp, d.y() * cp, sp) * 100.0;
  c.fov_y_deg = 50;
  return c;
}

}  // namespace npsnet::render
