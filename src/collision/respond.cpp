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

// A continuous contact moves a body back to the time of impact, then on with velocity `to`.
Vec3 rewind(const Contact& c, const Vec3& from, const Vec3& to) {
  return c.dt_s > 0 ? Vec3((to - from) * c.dt_s * (1 - c.fraction)) : Vec3::Zero();
}

// Munition contact: "the only response is an explosion" (p. 21).
void munition_contact(const world::World& w, const Contact& c, int mun, int other, world::Changes& out) {
  world::CollisionRecord rec;
  rec.a = c.a, rec.b = c.b, rec.b_fixed = c.b_fixed, rec.point = c.point, rec.method = c.method, rec.tier = c.tier;
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
  rec.a = c.a, rec.b = c.b, rec.b_fixed = true, rec.point = c.point, rec.method = c.method, rec.tier = c.tier;
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
    ch.shift = rewind(c, ents.vel[c.a], Vec3::Zero());
    rec.result_a = Result::Kill;
  } else if (large && to < last) {
    ch.set_vel = true;
    ch.cruise_mps = 0;
    if (level >= 2) ch.to_state = std::min(last_state(kv), ents.state[c.a] + 1);
    // back off so the spheres no longer touch (continuous: from where they first touched)
    const double gap = c.dt_s > 0 ? 0.0
                                  : world::entity_radius(w, c.a) + world::fixed_radius(w, c.b) -
                                        (world::fixed_centre(w, c.b) - world::entity_centre(w, c.a)).norm();
    Vec3 nh(c.normal.x(), c.normal.y(), 0);
    nh = nh.norm() > 1e-9 ? Vec3(nh.normalized()) : Vec3::UnitX();
    ch.shift = rewind(c, ents.vel[c.a], Vec3::Zero()) - nh * (std::max(0.0, gap) + 0.05);
    rec.result_a = Result::Stop;
  } else if (to > cur) {
    ch.set_vel = true;
    ch.vel = ents.vel[c.a] * thesis::kFixedHitSpeedKept;
    ch.shift = rewind(c, ents.vel[c.a], ch.vel);
    ch.cruise_mps = static_cast<float>(ents.cruise_mps[c.a] * thesis::kFixedHitSpeedKept);
    rec.result_a = Result::Slowed;
  }
  if (ch.set_vel || ch.to_state >= 0) out.entities.push_back(ch);
  out.collisions.push_back(rec);
}

// Sequential impulse sweeps over all bouncing contacts of the tick, in contact order.
constexpr int kImpulseSweeps = 8;

// The contact normal the bounce works along: horizontal unless an aircraft takes part.
Vec3 bounce_normal(const world::World& w, const Contact& c) {
  const bool air = w.kinds[w.ents.kind[c.a]].mobility == Mobility::Air || w.kinds[w.ents.kind[c.b]].mobility == Mobility::Air;
  Vec3 n(c.normal.x(), c.normal.y(), air ? c.normal.z() : 0);
  return n.norm() > 1e-9 ? Vec3(n.normalized()) : Vec3::UnitX();
}

// Figure 8 for two vehicles in an angle band (stop or kill); false when outside every band
// (a bounce, solved with the others in solve_bounces).
bool vehicle_vs_vehicle_band(const world::World& w, const Contact& c, world::Changes& out, world::CollisionRecord& rec) {
  const auto& ents = w.ents;
  const int a = c.a, b = c.b;
  const world::Kind& ka = w.kinds[ents.kind[a]];
  const world::Kind& kb = w.kinds[ents.kind[b]];
  rec.a = a, rec.b = b, rec.point = c.point, rec.method = c.method, rec.tier = c.tier;
  const Vec3 rel = ents.vel[a] - ents.vel[b];
  rec.closing_speed_mps = std::max(0.0, rel.dot(c.normal));
  rec.angle_deg = impact_angle_deg(ents.heading_deg[a], ents.heading_deg[b]);
  if (!in_kill_band(rec.angle_deg)) {
    rec.result_a = rec.result_b = Result::Bounce;
    return false;
  }
  world::EntityChange ca, cb;
  ca.entity = a, cb.entity = b;
  ca.set_vel = cb.set_vel = true;
  ca.cruise_mps = cb.cruise_mps = 0;  // vel zero
  ca.shift = rewind(c, ents.vel[a], Vec3::Zero());
  cb.shift = rewind(c, ents.vel[b], Vec3::Zero());
  if (rec.closing_speed_mps > thesis::kKillClosingSpeedMps) {
    ca.to_state = last_state(ka), cb.to_state = last_state(kb);
    rec.result_a = rec.result_b = Result::Kill;
  } else {
    rec.result_a = rec.result_b = Result::Stop;
  }
  // Remote entities are moved and damaged by their owner (it shows its decision in its appearance).
  if (!ents.local[a]) ca.set_vel = false, ca.shift = Vec3::Zero(), ca.to_state = -1;
  if (!ents.local[b]) cb.set_vel = false, cb.shift = Vec3::Zero(), cb.to_state = -1;
  out.entities.push_back(ca);
  out.entities.push_back(cb);
  return true;
}

// Figure 7: "bounce off each other, diminish the speed of both", for every bouncing contact of
// the tick together. Impulses along the contact normals with restitution e, each equal and
// opposite (momentum conserved), swept kImpulseSweeps times over the contacts in their sorted
// order (deterministic, independent of where the entities are stored). Then one change per body:
// the final velocity, and the move back to the time of impact and on (continuous), or the
// separation push in inverse proportion to mass (thesis).
void solve_bounces(const world::World& w, const std::vector<const Contact*>& bounces, world::Changes& out,
                   RespondScratch& s) {
  if (bounces.empty()) return;
  const auto& ents = w.ents;
  std::vector<int>& body = s.body;
  body.clear();
  for (const Contact* c : bounces) body.push_back(c->a), body.push_back(c->b);
  std::sort(body.begin(), body.end());
  body.erase(std::unique(body.begin(), body.end()), body.end());
  auto slot = [&](int e) { return static_cast<size_t>(std::lower_bound(body.begin(), body.end(), e) - body.begin()); };
  std::vector<Vec3>& v = s.v;
  std::vector<Vec3>& shift = s.shift;
  std::vector<double>& first_toi = s.first_toi;
  std::vector<double>& dt = s.dt;
  v.resize(body.size());
  shift.assign(body.size(), Vec3::Zero());
  first_toi.assign(body.size(), 2.0);
  dt.assign(body.size(), 0.0);
  for (size_t i = 0; i < body.size(); ++i) v[i] = ents.vel[body[i]];
  for (int sweep = 0; sweep < kImpulseSweeps; ++sweep) {
    for (const Contact* c : bounces) {
      const size_t ia = slot(c->a), ib = slot(c->b);
      const double ma = w.kinds[ents.kind[c->a]].mass_kg, mb = w.kinds[ents.kind[c->b]].mass_kg;
      const Vec3 n = bounce_normal(w, *c);
      const double j = bounce_impulse(v[ia], v[ib], ma, mb, n);
      if (j <= 0) continue;  // separating already
      v[ia] -= (j / ma) * n;
      v[ib] += (j / mb) * n;
    }
  }
  for (const Contact* c : bounces) {
    for (int side = 0; side < 2; ++side) {
      const size_t i = slot(side ? c->b : c->a);
      if (c->fraction < first_toi[i]) first_toi[i] = c->fraction, dt[i] = c->dt_s;
    }
    if (c->dt_s > 0) continue;
    // Thesis contacts (found at the end of the tick): push the pair apart.
    const double ma = w.kinds[ents.kind[c->a]].mass_kg, mb = w.kinds[ents.kind[c->b]].mass_kg;
    const double overlap = world::entity_radius(w, c->a) + world::entity_radius(w, c->b) -
                           (world::entity_centre(w, c->b) - world::entity_centre(w, c->a)).norm();
    const double push = std::max(0.0, overlap) + 0.05;
    const Vec3 nh = bounce_normal(w, *c);
    shift[slot(c->a)] -= nh * push * (mb / (ma + mb));
    shift[slot(c->b)] += nh * push * (ma / (ma + mb));
  }
  for (size_t i = 0; i < body.size(); ++i) {
    const int ent = body[i];
    world::EntityChange ch;
    ch.entity = ent;
    Vec3 vi = v[i];
    // Ground vehicles stay on the ground: keep the horizontal part.
    if (w.kinds[ents.kind[ent]].mobility != Mobility::Air) vi.z() = 0;
    ch.set_vel = ents.local[ent] != 0;  // remote entities are moved by their owner
    ch.vel = vi;
    ch.cruise_mps = static_cast<float>(vi.norm());
    if (dt[i] > 0) shift[i] += (vi - ents.vel[ent]) * dt[i] * (1 - first_toi[i]);
    ch.shift = ents.local[ent] ? shift[i] : Vec3::Zero();
    out.entities.push_back(ch);
  }
}

}  // namespace

double bounce_impulse(const Vec3& va, const Vec3& vb, double ma, double mb, const Vec3& n) {
  const double vn = (va - vb).dot(n);
  if (vn <= 0) return 0;
  return (1 + thesis::kBounceRestitution) * vn / (1 / ma + 1 / mb);
}

void respond(const world::World& w, const std::vector<Contact>& contacts, world::Changes& out) {
  RespondScratch s;
  respond(w, contacts, out, s);
}

void respond(const world::World& w, const std::vector<Contact>& contacts, world::Changes& out, RespondScratch& s) {
  // Bounces first (solved together), so that a stop or kill of the same body this tick wins.
  std::vector<const Contact*>& bounces = s.bounces;
  bounces.clear();
  for (const Contact& c : contacts) {
    const bool mun_a = w.kinds[w.ents.kind[c.a]].mobility == Mobility::Munition;
    const bool mun_b = !c.b_fixed && w.kinds[w.ents.kind[c.b]].mobility == Mobility::Munition;
    if (mun_a || mun_b || c.b_fixed) continue;
    if (!in_kill_band(impact_angle_deg(w.ents.heading_deg[c.a], w.ents.heading_deg[c.b]))) bounces.push_back(&c);
  }
  solve_bounces(w, bounces, out, s);
  for (const Contact& c : contacts) {
    const bool mun_a = w.kinds[w.ents.kind[c.a]].mobility == Mobility::Munition;
    const bool mun_b = !c.b_fixed && w.kinds[w.ents.kind[c.b]].mobility == Mobility::Munition;
    if (mun_a) munition_contact(w, c, c.a, c.b, out);
    else if (mun_b) munition_contact(w, c, c.b, c.a, out);
    else if (c.b_fixed) vehicle_vs_fixed(w, c, out);
    else {
      world::CollisionRecord rec;
      vehicle_vs_vehicle_band(w, c, out, rec);  // band: changes; bounce: already solved
      out.collisions.push_back(rec);
    }
  }
}

void detonate(const world::World& w, int munition, const Vec3& point, int hit, world::Changes& out) {
  world::DetonationRecord rec;
  rec.munition = munition, rec.kind = w.ents.kind[munition], rec.shooter = w.ents.owner[munition];
  rec.round = w.ents.id[munition];
  rec.target = hit, rec.point = point;
  rec.result = hit >= 0 ? "entity_impact" : "ground_impact";
  detonate(w, rec, out);
}

void detonate(const world::World& w, const world::DetonationRecord& d, world::Changes& out) {
  const auto& ents = w.ents;
  const world::Kind& km = w.kinds[d.kind];
  const int munition = d.munition, hit = d.target;
  const Vec3& point = d.point;
  if (munition >= 0) {
    world::EntityChange spent;
    spent.entity = munition;
    spent.deactivate = true;
    spent.set_vel = true;
    out.entities.push_back(spent);
  }
  out.detonations.push_back(d);
  if (hit >= 0) {
    // "the same round striking a tank would destroy the tank and have no effect on the ground"
    // (its damage is its owner's to decide: a remote target is left to its node)
    world::EntityChange k;
    k.entity = hit;
    k.to_state = last_state(w.kinds[ents.kind[hit]]);
    k.set_vel = true;
    k.cruise_mps = 0;
    if (ents.local[hit] && d.hit_destroys) out.entities.push_back(k);
  } else if (d.crater) {
    const double agl = point.z() - w.terrain.height(point.x(), point.y());
    if (agl < km.crater_radius_m) out.craters.push_back({point, km.crater_radius_m, km.crater_depth_m});
  }
  // Blast: damage falls with distance: inner third destroys, middle third two levels, outer one;
  // each round of a burst (quantity) adds its levels.
  const double R = d.blast ? km.blast_radius_m : 0.0;
  if (R <= 0) return;
  const int q = std::max(1, d.quantity);
  auto levels = [&](double d) { return d < R / 3 ? 3 : d < 2 * R / 3 ? 2 : d < R ? 1 : 0; };
  if (d.decides_fixed) w.grid.for_each_near(point.x(), point.y(), R, [&](int o) {
    const int lv = levels((w.fixed.pos[o] - point).norm());
    const world::Kind& k = w.kinds[w.fixed.kind[o]];
    const int ls = last_state(k);
    if (lv == 0 || w.fixed.state[o] >= ls) return;  // out of reach, or nothing left to damage (a rock)
    out.fixed.push_back({o, lv == 3 ? ls : std::min(ls, w.fixed.state[o] + lv * q)});
  });
  for (int e = 0; e < static_cast<int>(ents.size()); ++e) {
    if (e == munition || e == hit || !ents.active[e] || !ents.local[e]) continue;  // remote: its owner decides
    const world::Kind& k = w.kinds[ents.kind[e]];
    if (k.mobility == Mobility::Munition) continue;
    const int lv = levels((world::entity_centre(w, e) - point).norm());
    if (lv == 0) continue;
    world::EntityChange ch;
    ch.entity = e;
    ch.to_state = lv == 3 ? last_state(k) : std::min(last_state(k), ents.state[e] + q);
    out.entities.push_back(ch);
  }
}

}  // namespace npsnet::collision
