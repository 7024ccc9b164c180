#include "world/world.hpp"

#include <algorithm>
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
  id.push_back(std::move(id_));
  kind.push_back(static_cast<int16_t>(kind_));
  state.push_back(0);
  pos.push_back(p);
  vel.push_back(Vec3::Zero());
  heading_deg.push_back(heading);
  pitch_deg.push_back(0);
  roll_deg.push_back(0);
  radius_m.push_back(radius);
  cruise_mps.push_back(0);
  max_mps.push_back(0);
  active.push_back(1);
  local.push_back(1);
  snapshots.push_back(1);
  autonomous.push_back(0);
  target.push_back(-1);
  aim.push_back(p);
  owner.push_back(-1);
  rounds.push_back(0);
  fuel_l.push_back(0);
  node.push_back(1);
  route.emplace_back();
  leg.push_back(0);
  loop_route.push_back(0);
  flee_until.push_back(-1);
  calm_until.push_back(-1);
  driven.push_back(0);
  return static_cast<int>(id.size() - 1);
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
                   fuel_l.size(), node.size(), route.size(), leg.size(), loop_route.size(), flee_until.size(),
                   calm_until.size()})
    if (s != n) return false;
  return true;
}

bool World::valid() const {
  if (!ents.valid() || !fixed.valid()) return false;
  const int ne = static_cast<int>(ents.size());
  auto kind_ok = [&](int k, int state) { return k >= 0 && k < kinds.size() && state < static_cast<int>(kinds[k].states.size()); };
  for (int e = 0; e < ne; ++e)
    if (!kind_ok(ents.kind[e], ents.state[e]) || ents.owner[e] < -1 || ents.owner[e] >= ne || ents.target[e] < -1 ||
        ents.target[e] >= ne)
      return false;
  for (size_t o = 0; o < fixed.size(); ++o)
    if (!kind_ok(fixed.kind[o], fixed.state[o])) return false;
  return (grid.cols() == 0 && fixed.size() == 0) || grid.valid(fixed.pos, fixed.reach_m);
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
}

}  // namespace npsnet::world
