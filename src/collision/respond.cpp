// Collision response, thesis Figure 8 (p. 22) and Figure 7 (bounce), constants in
// core/constants.hpp. One CollisionRecord per contact, with an outcome for each side.
#include <algorithm>
#include <cmath>

#include "collision/collision.hpp"
#include "core/constants.hpp"
#include "world/pose.hpp"

namespace npsnet::collision {

using world::Mobility;
using world::Result;

double impact_angle_deg(double heading_a, double heading_b) { return wrap360(heading_b - heading_a); }

bool in_kill_band(double a) {
  const double h = thesis::kBandHalfWidthDeg;
  return (a >= 90 - h && a <= 90 + h) || (a >= 180 - h && a <= 180 + h) || (a <= h) || (a >= 360 - h) ||
         (a >= 270 - h && a <= 270 + h);
}

int fixed_damage_level(double momentum, double resistance) {
  const double p = momentum / resistance;
  if (p >= thesis::kFixedMomentumHi) return 3;
  if (p >= thesis::kFixedMomentumMed) return 2;
  if (p >= thesis::kFixedMomentumLow) return 1;
  return 0;
}

namespace {

int last_state(const world::Kind& k) { return static_cast<int>(k.states.size()) - 1; }

// Munition contact: "the only response is an explosion" (p. 21).
void munition_contact(const world::World& w, const Contact& c, int mun, int other, world::Changes& out) {
  world::CollisionRecord rec;
  rec.a = c.a, rec.b = c.b, rec.b_fixed = c.b_fixed, rec.point = c.point, rec.method = c.method;
  rec.closing_speed_mps = w.ents.vel[mun].norm();
  rec.angle_deg = c.b_fixed ? 0 : impact_angle_deg(w.ents.heading_deg[c.a], w.ents.heading_deg[c.b]);
  (mun == c.a ? rec.result_a : rec.result_b) = Result::Explode;
  if (c.b_fixed) rec.result_b = Result::DestroyFixed;
  else (other == c.a ? rec.result_a : rec.result_b) = Result::Kill;
  out.collisions.push_back(rec);
  detonate(w, mun, c.point, c.b_fixed ? -1 : other, out);
  if (c.b_fixed) out.fixed.push_back({c.b, last_state(w.kinds[w.fixed.kind[c.b]])});
}

void vehicle_vs_fixed(const world::World& w, const Contact& c, world::Changes& out) {
  const auto& ents = w.ents;
  const world::Kind& kv = w.kinds[ents.kind[c.a]];
  const world::Kind& kf = w.kinds[w.fixed.kind[c.b]];
  const double speed = ents.vel[c.a].norm();
  world::CollisionRecord rec;
  rec.a = c.a, rec.b = c.b, rec.b_fixed = true, rec.point = c.point, rec.method = c.method;
  rec.closing_speed_mps = std::max(0.0, ents.vel[c.a].dot(c.normal));
  rec.angle_deg = impact_angle_deg(ents.heading_deg[c.a], dir_to_heading(c.normal.head<2>()));
  // Fixed object: damage graded by the vehicle's momentum (p. 20: "based upon the speed and mass
  // of the colliding object"), against constant1 > constant2 > constant3.
  const int level = fixed_damage_level(kv.mass_kg * speed, kf.resistance);
  const int cur = w.fixed.state[c.b], last = last_state(kf);
  const int to = level == 0 ? cur : std::min(last, level == 3 ? last : std::max(cur + 1, std::min(level, last)));
  if (to > cur) {
    out.fixed.push_back({c.b, to});
    rec.result_b = to == last ? Result::DestroyFixed : Result::DamageFixed;
  }
  // Mobile object: "if large and moving quickly, kill mobile object; if small or moving slowly,
  // continue on course, damage fixed object, decrease speed" (Figure 8). A large object still
  // standing stops the vehicle (it cannot drive on through a building), and when the object took
  // two or more levels the vehicle is damaged too (p. 14: "a tank hitting a house").
  const bool large = kf.mass_kg >= thesis::kLargeFixedMassKg;
  const bool quick = speed >= thesis::kQuickSpeedMps;
  world::EntityChange ch;
  ch.entity = c.a;
  if (large && quick) {
    ch.to_state = last_state(kv);
    ch.set_vel = true;
    ch.cruise_mps = 0;
    rec.result_a = Result::Kill;
  } else if (large && to < last) {
    ch.set_vel = true;
    ch.cruise_mps = 0;
    if (level >= 2) ch.to_state = std::min(last_state(kv), ents.state[c.a] + 1);
    // back off so the spheres no longer touch
    const double gap = world::entity_radius(w, c.a) + world::fixed_radius(w, c.b) -
                       (world::fixed_centre(w, c.b) - world::entity_centre(w, c.a)).norm();
    ch.shift = -Vec3(c.normal.x(), c.normal.y(), 0).normalized() * (std::max(0.0, gap) + 0.05);
    rec.result_a = Result::Stop;
  } else if (to > cur) {
    ch.set_vel = true;
    ch.vel = ents.vel[c.a] * thesis::kFixedHitSpeedKept;
    ch.cruise_mps = static_cast<float>(ents.cruise_mps[c.a] * thesis::kFixedHitSpeedKept);
    rec.result_a = Result::Slowed;
  }
  if (ch.set_vel || ch.to_state >= 0) out.entities.push_back(ch);
  out.collisions.push_back(rec);
}

void vehicle_vs_vehicle(const world::World& w, const Contact& c, world::Changes& out) {
  const auto& ents = w.ents;
  const int a = c.a, b = c.b;
  const world::Kind& ka = w.kinds[ents.kind[a]];
  const world::Kind& kb = w.kinds[ents.kind[b]];
  world::CollisionRecord rec;
  rec.a = a, rec.b = b, rec.point = c.point, rec.method = c.method;
  const Vec3 rel = ents.vel[a] - ents.vel[b];
  const double closing = std::max(0.0, rel.dot(c.normal));
  rec.closing_speed_mps = closing;
  rec.angle_deg = impact_angle_deg(ents.heading_deg[a], ents.heading_deg[b]);
  world::EntityChange ca, cb;
  ca.entity = a, cb.entity = b;
  ca.set_vel = cb.set_vel = true;
  if (in_kill_band(rec.angle_deg)) {
    ca.cruise_mps = cb.cruise_mps = 0;  // vel zero
    if (closing > thesis::kKillClosingSpeedMps) {
      ca.to_state = last_state(ka), cb.to_state = last_state(kb);
      rec.result_a = rec.result_b = Result::Kill;
    } else {
      rec.result_a = rec.result_b = Result::Stop;
    }
  } else {
    // Figure 7: bounce off each other, diminish the speed of both. An impulse along the contact
    // normal with restitution e conserves momentum and loses energy; the bodies are separated
    // (in inverse proportion to mass) so they do not touch again next tick.
    const double ma = ka.mass_kg, mb = kb.mass_kg;
    const double vn = rel.dot(c.normal);
    const double e = thesis::kBounceRestitution;
    const double j = vn > 0 ? (1 + e) * vn / (1 / ma + 1 / mb) : 0.0;
    Vec3 va = ents.vel[a] - (j / ma) * c.normal;
    Vec3 vb = ents.vel[b] + (j / mb) * c.normal;
    // Ground vehicles stay on the ground: keep the horizontal part.
    if (ka.mobility == Mobility::Ground) va.z() = 0;
    if (kb.mobility == Mobility::Ground) vb.z() = 0;
    ca.vel = va, cb.vel = vb;
    ca.cruise_mps = static_cast<float>(va.norm());
    cb.cruise_mps = static_cast<float>(vb.norm());
    const double overlap = world::entity_radius(w, a) + world::entity_radius(w, b) -
                           (world::entity_centre(w, b) - world::entity_centre(w, a)).norm();
    const double push = std::max(0.0, overlap) + 0.05;
    Vec3 nh(c.normal.x(), c.normal.y(), ka.mobility == Mobility::Air || kb.mobility == Mobility::Air ? c.normal.z() : 0);
    nh = nh.norm() > 1e-9 ? Vec3(nh.normalized()) : Vec3::UnitX();
    ca.shift = -nh * push * (mb / (ma + mb));
    cb.shift = nh * push * (ma / (ma + mb));
    rec.result_a = rec.result_b = Result::Bounce;
  }
  if (!ents.local[a]) ca.set_vel = false;  // remote entities are moved by their owner
  if (!ents.local[b]) cb.set_vel = false;
  out.entities.push_back(ca);
  out.entities.push_back(cb);
  out.collisions.push_back(rec);
}

}  // namespace

void respond(const world::World& w, const std::vector<Contact>& contacts, world::Changes& out) {
  for (const Contact& c : contacts) {
    const bool mun_a = w.kinds[w.ents.kind[c.a]].mobility == Mobility::Munition;
    const bool mun_b = !c.b_fixed && w.kinds[w.ents.kind[c.b]].mobility == Mobility::Munition;
    if (mun_a) munition_contact(w, c, c.a, c.b, out);
    else if (mun_b) munition_contact(w, c, c.b, c.a, out);
    else if (c.b_fixed) vehicle_vs_fixed(w, c, out);
    else vehicle_vs_vehicle(w, c, out);
  }
}

void detonate(const world::World& w, int munition, const Vec3& point, int hit, world::Changes& out) {
  const auto& ents = w.ents;
  const world::Kind& km = w.kinds[ents.kind[munition]];
  world::EntityChange spent;
  spent.entity = munition;
  spent.deactivate = true;
  spent.set_vel = true;
  out.entities.push_back(spent);
  world::DetonationRecord rec;
  rec.munition = munition, rec.target = hit, rec.point = point;
  rec.result = hit >= 0 ? "entity_impact" : "ground_impact";
  out.detonations.push_back(rec);
  if (hit >= 0) {
    // "the same round striking a tank would destroy the tank and have no effect on the ground"
    world::EntityChange k;
    k.entity = hit;
    k.to_state = last_state(w.kinds[ents.kind[hit]]);
    k.set_vel = true;
    k.cruise_mps = 0;
    out.entities.push_back(k);
  } else {
    const double agl = point.z() - w.terrain.height(point.x(), point.y());
    if (agl < km.crater_radius_m) out.craters.push_back({point, km.crater_radius_m, km.crater_depth_m});
  }
  // Blast: damage falls with distance: inner third destroys, middle third two levels, outer one.
  const double R = km.blast_radius_m;
  if (R <= 0) return;
  auto levels = [&](double d) { return d < R / 3 ? 3 : d < 2 * R / 3 ? 2 : d < R ? 1 : 0; };
  const int c0 = w.grid.cell_of(point.x() - R, point.y() - R), c1 = w.grid.cell_of(point.x() + R, point.y() + R);
  for (int j = c0 / w.grid.cols(); j <= c1 / w.grid.cols(); ++j)
    for (int i = c0 % w.grid.cols(); i <= c1 % w.grid.cols(); ++i) {
      auto [first, last] = w.grid.objects_in(j * w.grid.cols() + i);
      for (auto it = first; it != last; ++it) {
        const int o = static_cast<int>(*it);
        const int lv = levels((w.fixed.pos[o] - point).norm());
        if (lv == 0) continue;
        const int ls = last_state(w.kinds[w.fixed.kind[o]]);
        if (w.kinds[w.fixed.kind[o]].resistance > 100) continue;  // rock
        out.fixed.push_back({o, lv == 3 ? ls : std::min(ls, w.fixed.state[o] + lv)});
      }
    }
  for (int e = 0; e < static_cast<int>(ents.size()); ++e) {
    if (e == munition || e == hit || !ents.active[e]) continue;
    const world::Kind& k = w.kinds[ents.kind[e]];
    if (k.mobility == Mobility::Munition) continue;
    const int lv = levels((world::entity_centre(w, e) - point).norm());
    if (lv == 0) continue;
    world::EntityChange ch;
    ch.entity = e;
    ch.to_state = lv == 3 ? last_state(k) : std::min(last_state(k), ents.state[e] + 1);
    out.entities.push_back(ch);
  }
}

}  // namespace npsnet::collision
