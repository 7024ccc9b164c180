#include "dynamics/drive.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/dynamics.hpp"
#include "world/pose.hpp"

namespace npsnet::dynamics {
namespace {

using world::Mobility;

// Moves `v` towards `to` by at most `step`.
double approach(double v, double to, double step) { return v < to ? std::min(to, v + step) : std::max(to, v - step); }

// New signed speed along the heading of a ground vehicle or ship.
double surface_speed(double s, double throttle, const world::Kind& k, double limit, double coast, double dt) {
  if (throttle == 0) return approach(s, 0, coast * dt);
  const bool braking = (throttle > 0 && s < 0) || (throttle < 0 && s > 0);
  if (braking) return approach(s, 0, k.brake_mps2 * std::abs(throttle) * dt);  // stops at 0 this step
  const double top = throttle > 0 ? limit : -kReverseFraction * limit;
  return approach(s, top * std::abs(throttle), k.accel_mps2 * std::abs(throttle) * dt);
}

void drive_surface(world::World& w, int e, const Controls& c, double dt, bool has_fuel) {
  auto& ents = w.ents;
  const world::Kind& k = w.kinds[ents.kind[e]];
  const bool ship = k.mobility == Mobility::Ship;
  double heading = ents.heading_deg[e];
  const Vec2 f0 = heading_to_dir(heading);
  const double limit = ents.max_mps[e];
  double s = std::clamp(ents.vel[e].head<2>().dot(f0), -kReverseFraction * limit, limit);  // a governor
  const double throttle = has_fuel ? c.throttle : std::min(0.0, c.throttle);  // brakes work dry
  s = surface_speed(s, throttle, k, limit, ship ? kShipCoastMps2 : kCoastMps2, dt);
  // steer: yaw rate = speed / radius (a reversing vehicle turns the other way)
  if (k.turn_radius_m > 0 && c.steer != 0) {
    double yaw = rad2deg(s * c.steer / k.turn_radius_m);
    if (!ship) yaw = std::clamp(yaw, -kGroundYawDps, kGroundYawDps);
    heading = wrap360(heading + yaw * dt);
  }
  const Vec2 f = heading_to_dir(heading);
  Vec3 next = ents.pos[e] + Vec3(f.x(), f.y(), 0) * (s * dt);
  next.x() = std::clamp(next.x(), 0.0, w.terrain.width_m());
  next.y() = std::clamp(next.y(), 0.0, w.terrain.depth_m());
  if (w.is_water(next.x(), next.y()) != ship) {  // the shore: stop there
    next = ents.pos[e];
    s = 0;
  }
  if (ship) next.z() = w.water_level_m;
  const Vec3 start = ents.pos[e];
  ents.pos[e] = next;
  ents.heading_deg[e] = static_cast<float>(heading);
  if (ship) ents.pitch_deg[e] = ents.roll_deg[e] = 0;
  else follow_terrain(w, e);
  ents.vel[e] = (ents.pos[e] - start) / dt;
  burn_fuel(w, e, std::abs(s), dt);
}

void drive_air(world::World& w, int e, const Controls& c, double dt, bool has_fuel, std::vector<Crash>& crashes) {
  auto& ents = w.ents;
  const world::Kind& k = w.kinds[ents.kind[e]];
  const double limit = ents.max_mps[e];
  const Vec3 start = ents.pos[e];
  const bool airborne = start.z() > w.terrain.height(start.x(), start.y()) + 1e-3;
  double heading = ents.heading_deg[e];
  double s = std::max(0.0, ents.vel[e].head<2>().dot(heading_to_dir(heading)));
  double vz = has_fuel ? c.climb * k.climb_mps : -kDryAirSinkMps;
  if (!has_fuel) s = approach(s, 0, k.brake_mps2 * dt);
  else if (c.throttle > 0) s = approach(s, limit, k.accel_mps2 * c.throttle * dt);
  else if (c.throttle < 0) s = approach(s, 0, k.brake_mps2 * -c.throttle * dt);
  if (std::hypot(s, vz) > limit) {  // the Table 2 limit holds for the whole velocity
    const double f = limit / std::hypot(s, vz);
    s *= f, vz *= f;
  }
  // bank follows the stick; the bank turns the craft
  const double bank = approach(ents.roll_deg[e], c.steer * kMaxBankDeg, kBankRateDps * dt);
  const double yaw = std::clamp(rad2deg(kGravity * std::tan(deg2rad(bank)) / std::max(s, kAirTurnMinSpeedMps)), -kAirYawDps,
                                kAirYawDps);
  heading = wrap360(heading + yaw * dt);
  const Vec2 f = heading_to_dir(heading);
  Vec3 next = start + Vec3(f.x() * s, f.y() * s, vz) * dt;
  next.x() = std::clamp(next.x(), 0.0, w.terrain.width_m());
  next.y() = std::clamp(next.y(), 0.0, w.terrain.depth_m());
  const double ground = w.terrain.height(next.x(), next.y());
  if (next.z() <= ground) {
    if (airborne) crashes.push_back({e, Vec3(next.x(), next.y(), ground), std::hypot(s, vz)});
    next.z() = ground;
    vz = std::max(0.0, vz);
  }
  ents.vel[e] = (next - start) / dt;
  ents.pos[e] = next;
  ents.heading_deg[e] = static_cast<float>(heading);
  ents.roll_deg[e] = static_cast<float>(bank);
  ents.pitch_deg[e] = static_cast<float>(rad2deg(std::atan2(vz, std::max(s, 1e-6))));
  if (s < 1e-6 && vz == 0) ents.pitch_deg[e] = 0;
  burn_fuel(w, e, std::hypot(s, vz), dt);
}

}  // namespace

void drive(world::World& w, int e, const Controls& c, double dt, std::vector<Crash>& crashes) {
  auto& ents = w.ents;
  const world::Kind& k = w.kinds[ents.kind[e]];
  if (ents.state[e] + 1 >= static_cast<int>(k.states.size())) {  // a wreck
    ents.vel[e].setZero();
    return;
  }
  const bool has_fuel = k.fuel_l <= 0 || ents.fuel_l[e] > 0;
  switch (k.mobility) {
    case Mobility::Ground:
    case Mobility::Ship: drive_surface(w, e, c, dt, has_fuel); break;
    case Mobility::Air: drive_air(w, e, c, dt, has_fuel, crashes); break;
    default: break;
  }
}

Aim aim_from(const world::World& w, int e) {
  const auto& ents = w.ents;
  const world::Kind& k = w.kinds[ents.kind[e]];
  const double h = deg2rad(ents.heading_deg[e]), p = deg2rad(ents.pitch_deg[e]);
  const Vec3 dir(std::sin(h) * std::cos(p), std::cos(h) * std::cos(p), std::sin(p));
  const Vec3 eye = ents.pos[e] + Vec3(0, 0, std::max(1.0, 0.8 * k.height_m));
  Aim best;
  double best_cos = std::cos(deg2rad(kAimConeDeg)), best_d = kAimRangeM;
  for (size_t o = 0; o < ents.size(); ++o) {
    if (static_cast<int>(o) == e || !ents.active[o]) continue;
    const world::Kind& ko = w.kinds[ents.kind[o]];
    if (ko.mobility == Mobility::Munition || ents.state[o] + 1 >= static_cast<int>(ko.states.size())) continue;
    const Vec3 c = world::entity_centre(w, o);
    const Vec3 to = c - eye;
    const double d = to.norm();
    if (d < 1e-6 || d > kAimRangeM) continue;
    const double cs = to.dot(dir) / d;
    // within the cone, or the line of the nose passes within the target's sphere
    const bool on_line = cs > 0 && (to - dir * to.dot(dir)).norm() < world::entity_radius(w, o);
    if ((cs >= best_cos || on_line) && d < best_d) best_d = d, best.target = static_cast<int>(o), best.point = c;
  }
  if (best.target >= 0) return best;
  constexpr double kStepM = 5.0;
  for (double d = kStepM; d <= kAimRangeM; d += kStepM) {
    const Vec3 q = eye + dir * d;
    if (!w.terrain.contains(q.x(), q.y())) break;
    if (q.z() <= w.terrain.height(q.x(), q.y())) return {Vec3(q.x(), q.y(), w.terrain.height(q.x(), q.y())), -1};
  }
  Vec3 end = eye + dir * kAimRangeM;
  end.x() = std::clamp(end.x(), 0.0, w.terrain.width_m());
  end.y() = std::clamp(end.y(), 0.0, w.terrain.depth_m());
  end.z() = w.terrain.height(end.x(), end.y());
  return {end, -1};
}

}  // namespace npsnet::dynamics
