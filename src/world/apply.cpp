#include <algorithm>
#include <cassert>
#include <cstdio>

#include "world/changes.hpp"

namespace npsnet::world {

const char* result_name(Result r) {
  switch (r) {
    case Result::None: return "none";
    case Result::Slowed: return "slowed";
    case Result::Bounce: return "bounce";
    case Result::Stop: return "stop";
    case Result::Kill: return "kill";
    case Result::Explode: return "explode";
    case Result::DamageFixed: return "damage_fixed";
    case Result::DestroyFixed: return "destroy_fixed";
  }
  return "?";
}

namespace {
int launch(World& w, const Launch& l) {
  auto& ents = w.ents;
  assert(l.shooter >= 0 && l.shooter < static_cast<int>(ents.size()) && l.kind >= 0 && l.kind < w.kinds.size());
  ents.rounds[l.shooter] -= 1;
  char id[16];
  std::snprintf(id, sizeof id, "m%d", static_cast<int>(ents.created % 100000000));
  const float heading = static_cast<float>(dir_to_heading(l.vel.head<2>()));
  const float radius = static_cast<float>(w.kinds[l.kind].radius_m);
  const bool reclaim = l.slot >= 0 && l.slot < static_cast<int>(ents.size()) && !ents.active[l.slot] &&
                       w.is_munition(static_cast<size_t>(l.slot));
  int m = l.slot;
  if (reclaim) ents.reset(m, id, l.kind, l.muzzle, heading, radius);
  else m = ents.add(id, l.kind, l.muzzle, heading, radius);
  ents.vel[m] = l.vel;
  ents.target[m] = l.target;
  ents.aim[m] = l.aim;
  ents.owner[m] = l.shooter;
  ents.snapshots[m] = ents.snapshots[l.shooter];
  ents.node[m] = ents.node[l.shooter];
  ents.local[m] = ents.local[l.shooter];
  return m;
}
void mirror(World& w, const Mirror& m) {
  auto& ents = w.ents;
  if (m.op == Mirror::Op::Join) {
    assert(m.entity == static_cast<int>(ents.size()) && m.kind >= 0 && m.kind < w.kinds.size());
    if (m.kind < 0 || m.kind >= w.kinds.size()) return;
    const int e = ents.add(m.name, m.kind, Vec3::Zero(), 0.f, static_cast<float>(w.kinds[m.kind].radius_m));
    ents.node[e] = -1, ents.local[e] = 0, ents.active[e] = 0, ents.autonomous[e] = 0;
    return;
  }
  const int e = m.entity;
  assert(e >= 0 && e < static_cast<int>(ents.size()) && !ents.local[e]);
  if (e < 0 || e >= static_cast<int>(ents.size())) return;
  switch (m.op) {
    case Mirror::Op::Activate:
      ents.local[e] = 0, ents.active[e] = 1, ents.autonomous[e] = 0, ents.force[e] = m.force;
      break;
    case Mirror::Op::Deactivate: ents.active[e] = 0, ents.vel[e].setZero(); break;
    case Mirror::Op::Pose:
      ents.pos[e] = m.pos, ents.vel[e] = m.vel;
      ents.heading_deg[e] = m.heading_deg, ents.pitch_deg[e] = m.pitch_deg, ents.roll_deg[e] = m.roll_deg;
      break;
    case Mirror::Op::Join: break;
  }
}
}  // namespace

void apply(World& w, const Changes& c, Applied& out) {
  assert(w.valid_state());
  auto& ents = w.ents;
  for (const auto& m : c.mirrors) mirror(w, m);
  for (const auto& ch : c.entities) {
    const int e = ch.entity;
    assert(e >= 0 && e < static_cast<int>(ents.size()));
    if (e < 0 || e >= static_cast<int>(ents.size())) continue;
    if (ch.to_kind >= 0 && ch.to_kind < w.kinds.size()) ents.kind[e] = static_cast<int16_t>(ch.to_kind);
    const Kind& k = w.kinds[ents.kind[e]];
    const int last = static_cast<int>(k.states.size()) - 1;
    if (ch.owner_state && ch.to_state >= 0 && std::min(ch.to_state, last) != ents.state[e]) {
      const int to = std::min(ch.to_state, last);
      out.damage.push_back({false, e, ents.state[e], to});
      ents.state[e] = static_cast<uint8_t>(to);
      if (to == last && k.mobility != Mobility::Munition) out.killed.push_back(e);
    } else if (!ch.owner_state && ch.to_state > ents.state[e]) {
      const int to = std::min(ch.to_state, last);
      out.damage.push_back({false, e, ents.state[e], to});
      ents.state[e] = static_cast<uint8_t>(to);
      if (to == last && k.mobility != Mobility::Munition) {
        out.killed.push_back(e);
        ents.vel[e].setZero();
        ents.cruise_mps[e] = 0;
      }
    }
    ents.pos[e] += ch.shift;
    if (ch.set_vel) ents.vel[e] = ch.vel;
    if (ch.cruise_mps >= 0) ents.cruise_mps[e] = ch.cruise_mps;
    if (ch.set_vel && ch.vel.head<2>().norm() > 1e-3 && k.mobility != Mobility::Munition)
      ents.heading_deg[e] = static_cast<float>(dir_to_heading(ch.vel.head<2>()));
    if (ch.deactivate) ents.active[e] = 0;
    if (ch.heading_deg >= 0) ents.heading_deg[e] = ch.heading_deg;
    if (ch.flee_until >= 0) ents.flee_until[e] = ch.flee_until;
    if (ch.calm_until >= 0) ents.calm_until[e] = ch.calm_until;
  }
  for (const auto& ch : c.fixed) {
    const int o = ch.object;
    assert(o >= 0 && o < static_cast<int>(w.fixed.size()));
    if (o < 0 || o >= static_cast<int>(w.fixed.size())) continue;
    const int last = static_cast<int>(w.kinds[w.fixed.kind[o]].states.size()) - 1;
    const int to = std::min(ch.to_state, last);
    if (to > w.fixed.state[o]) {
      out.damage.push_back({true, o, w.fixed.state[o], to});
      w.fixed.state[o] = static_cast<uint8_t>(to);
    }
  }
  for (const auto& cr : c.craters) {
    const PostRect r = w.terrain.crater(cr.point.x(), cr.point.y(), cr.radius_m, cr.depth_m);
    if (r.empty()) continue;
    out.terrain_patches.push_back(r);
    // Fixed objects standing in the bowl settle onto the new ground (vehicles follow the terrain).
    w.grid.for_each_near(cr.point.x(), cr.point.y(), cr.radius_m, [&](int o) {
      w.fixed.pos[o].z() = w.terrain.height(w.fixed.pos[o].x(), w.fixed.pos[o].y());
    });
  }
  for (const auto& l : c.launches) out.launched.push_back(launch(w, l));
  assert(w.valid_state());
}

}  // namespace npsnet::world
