#include "world/world.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace npsnet::world {

void FixedObjects::add(std::string id_, int kind_, const Vec3& p, float heading, float radius) {
  id.push_back(std::move(id_));
  kind.push_back(static_cast<int16_t>(kind_));
  state.push_back(0);
  pos.push_back(p);
  heading_deg.push_back(heading);
  radius_m.push_back(radius);
  reach_m.push_back(radius);
}

int Entities::add(std::string id_, int kind_, const Vec3& p, float heading, float radius) {
  const size_t n = id.size() + 1;
  id.resize(n), kind.resize(n), state.resize(n), pos.resize(n), vel.resize(n), heading_deg.resize(n);
  pitch_deg.resize(n), roll_deg.resize(n), radius_m.resize(n), cruise_mps.resize(n), max_mps.resize(n);
  active.resize(n), local.resize(n), snapshots.resize(n), autonomous.resize(n), target.resize(n), aim.resize(n);
  owner.resize(n), rounds.resize(n), fuel_l.resize(n), node.resize(n), force.resize(n), route.resize(n), leg.resize(n);
  loop_route.resize(n), flee_until.resize(n), calm_until.resize(n), driven.resize(n);
  const int e = static_cast<int>(n - 1);
  reset(e, std::move(id_), kind_, p, heading, radius);
  return e;
}

void Entities::reset(int e, std::string id_, int kind_, const Vec3& p, float heading, float radius) {
  const size_t i = static_cast<size_t>(e);
  id[i] = std::move(id_);
  kind[i] = static_cast<int16_t>(kind_);
  state[i] = 0;
  pos[i] = p;
  vel[i] = Vec3::Zero();
  heading_deg[i] = heading;
  pitch_deg[i] = roll_deg[i] = 0;
  radius_m[i] = radius;
  cruise_mps[i] = max_mps[i] = 0;
  active[i] = local[i] = snapshots[i] = 1;
  autonomous[i] = 0;
  target[i] = owner[i] = -1;
  aim[i] = p;
  rounds[i] = 0;
  fuel_l[i] = 0;
  node[i] = 1;
  force[i] = 1;
  route[i].clear();
  leg[i] = 0;
  loop_route[i] = 0;
  flee_until[i] = calm_until[i] = -1;
  driven[i] = 0;
  made_slot_[static_cast<size_t>(created % kMadeMemory)] = static_cast<uint32_t>(e);
  ++created;
}

bool Entities::made_since(uint64_t lineage_then, int64_t created_then, std::vector<uint32_t>& out) const {
  if (lineage_then != lineage.v || created_then < 0 || created_then > created || created - created_then > kMadeMemory)
    return false;
  for (int64_t k = created_then; k < created; ++k) out.push_back(made_slot_[static_cast<size_t>(k % kMadeMemory)]);
  return true;
}

bool FixedObjects::valid() const {
  const size_t n = id.size();
  return kind.size() == n && state.size() == n && pos.size() == n && heading_deg.size() == n && radius_m.size() == n &&
         reach_m.size() == n;
}

bool Entities::valid() const {
  const size_t n = id.size();
  for (size_t s : {kind.size(), state.size(), pos.size(), vel.size(), heading_deg.size(), pitch_deg.size(),
                   roll_deg.size(), radius_m.size(), cruise_mps.size(), max_mps.size(), active.size(), local.size(),
                   snapshots.size(), autonomous.size(), target.size(), aim.size(), owner.size(), rounds.size(),
                   fuel_l.size(), node.size(), force.size(), route.size(), leg.size(), loop_route.size(), flee_until.size(),
                   calm_until.size()})
    if (s != n) return false;
  return true;
}

bool World::valid() const {
  return valid_state() && ((grid.cols() == 0 && fixed.size() == 0) || grid.valid(fixed.pos, fixed.reach_m));
}

bool World::valid_state() const {
  if (!ents.valid() || !fixed.valid()) return false;
  const int ne = static_cast<int>(ents.size());
  auto kind_ok = [&](int k, int state) { return k >= 0 && k < kinds.size() && state < static_cast<int>(kinds[k].states.size()); };
  for (int e = 0; e < ne; ++e)
    if (!kind_ok(ents.kind[e], ents.state[e]) || ents.owner[e] < -1 || ents.owner[e] >= ne || ents.target[e] < -1 ||
        ents.target[e] >= ne)
      return false;
  for (size_t o = 0; o < fixed.size(); ++o)
    if (!kind_ok(fixed.kind[o], fixed.state[o])) return false;
  return true;
}

void World::index_fixed() {
  for (size_t o = 0; o < fixed.size(); ++o) {
    const Kind& k = kinds[fixed.kind[o]];
    const Vec3f c0 = k.centre_by_state.empty() ? Vec3f::Zero() : k.centre_by_state[0];
    float r = fixed.radius_m[o];
    for (int m : k.models) r = std::max(r, models[m].true_radius * 1.001f + 0.01f);  // tiers' bound + margin
    fixed.reach_m[o] = std::hypot(c0.x(), c0.y()) + r + 0.01f;
  }
  grid.build(fixed.pos, fixed.reach_m, terrain.width_m(), terrain.depth_m(), thesis::kGridsquareM);
  assert(valid());
}

}  // namespace npsnet::world
