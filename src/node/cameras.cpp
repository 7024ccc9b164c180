#ifdef NPSNET_HAVE_RENDER
#include "node/cameras.hpp"

#include <algorithm>
#include <cmath>

#include "render/view.hpp"
#include "world/pose.hpp"

namespace npsnet::node {

collision::ViewVolume view_volume(const render::Camera& cam, int width, int height) {
  const render::ViewMath vm = render::make_view(cam.eye, cam.target, cam.fov_y_deg, width, height, cam.up);
  collision::ViewVolume v;
  v.eye = vm.eye;
  for (size_t i = 0; i < vm.planes.size(); ++i) {
    const Eigen::Vector4d p = vm.planes[i].cast<double>();
    const double n = p.head<3>().norm();
    v.planes[i] = n > 0 ? Eigen::Vector4d(p / n) : p;
  }
  return v;
}

render::Camera player_camera(const world::World& w, const world::Entities& ents, int e, input::CameraMode mode,
                             double orbit_deg, double orbit_m) {
  const world::Kind& k = w.kinds[ents.kind[e]];
  const world::Model& m = w.models[k.models[0]];
  const Mat3 rot = world::pose_rotation(ents.heading_deg[e], ents.pitch_deg[e], ents.roll_deg[e]);
  const Vec3 pos = ents.pos[e];
  const Vec2 f = heading_to_dir(ents.heading_deg[e]);
  const double len = std::max(2.0, static_cast<double>(m.bbox_max.y() - m.bbox_min.y()));
  const double height = std::max(1.5, k.height_m);
  render::Camera c;
  c.fov_y_deg = 50;
  switch (mode) {
    case input::CameraMode::Driver: {
      // the driver's station: ahead of the centre, near the hull top (model space: y forward, z up)
      // The vehicle itself is not drawn (its hull and gun would fill the view at arm's length);
      // the view rolls and pitches with it.
      const Vec3 station(0, 0.3 * static_cast<double>(m.bbox_max.y()), 0.75 * height);
      c.eye = pos + rot * station;
      c.target = c.eye + rot * Vec3(0, 100, 0);
      c.up = rot * Vec3(0, 0, 1);
      c.hide_entity = e;
      break;
    }
    case input::CameraMode::Chase: {
      const double back = 1.5 * len + 12;
      c.eye = pos - Vec3(f.x(), f.y(), 0) * back + Vec3(0, 0, height + 0.35 * back);
      c.target = pos + Vec3(f.x(), f.y(), 0) * 20.0 + Vec3(0, 0, 0.6 * height);
      break;
    }
    case input::CameraMode::Orbit: {
      const Vec2 d = heading_to_dir(ents.heading_deg[e] + 180 + orbit_deg);
      c.target = pos + Vec3(0, 0, 0.5 * height);
      c.eye = c.target + Vec3(d.x(), d.y(), 0) * orbit_m + Vec3(0, 0, 0.4 * orbit_m);
      break;
    }
    case input::CameraMode::Map:
      c.target = pos;
      c.eye = pos + Vec3(0, 0, kMapCameraHeightM);
      break;
  }
  // never below the ground
  const double ground = w.terrain.height(c.eye.x(), c.eye.y()) + 1.0;
  if (mode != input::CameraMode::Driver && c.eye.z() < ground) c.eye.z() = ground;
  return c;
}

}  // namespace npsnet::node
#endif  // NPSNET_HAVE_RENDER
