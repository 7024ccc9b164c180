#include "collision/ground.hpp"

#include "core/constants.hpp"

namespace npsnet::collision {

void ground_contact(const world::World& w, int e, const Vec3& point, double speed_mps, world::Changes& out) {
  const world::Kind& k = w.kinds[w.ents.kind[e]];
  world::CollisionRecord rec;
  rec.a = e, rec.b = -1, rec.b_fixed = false, rec.point = point, rec.method = "terrain", rec.tier = "terrain";
  rec.closing_speed_mps = speed_mps;
  const Vec3& v = w.ents.vel[e];
  rec.angle_deg = v.norm() > 1e-9 ? rad2deg(std::asin(std::min(1.0, std::abs(v.z()) / v.norm()))) : 0.0;
  world::EntityChange ch;
  ch.entity = e;
  ch.set_vel = true;
  ch.cruise_mps = 0;
  if (speed_mps >= thesis::kQuickSpeedMps) {
    ch.to_state = static_cast<int>(k.states.size()) - 1;
    rec.result_a = world::Result::Kill;
  } else {
    rec.result_a = world::Result::Stop;
  }
  out.entities.push_back(ch);
  out.collisions.push_back(rec);
}

}  // namespace npsnet::collision
