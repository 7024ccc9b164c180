// The world a node simulates: terrain, kinds and models, fixed objects with their 125 m
// gridsquare index, and the moving entities (vehicles and munitions) as contiguous arrays.
// Entities and fixed objects are referred to by index; nothing holds pointers across ticks.
// The world is changed in one place, world::apply (changes.hpp), from fire orders, reactions and
// collision outcomes; only the integrator (dynamics::step / drive) writes poses directly.
// Threading: a World belongs to the tick's thread; during a tick's parallel stages workers read
// it and write only the entity slots they were given; nothing here locks.
#pragma once
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "world/fixed_grid.hpp"
#include "world/kinds.hpp"
#include "world/terrain.hpp"

namespace npsnet::world {

// Fixed objects (trees, bushes, poles, buildings, towers, rocks ...), structure of arrays.
struct FixedObjects {
  std::vector<std::string> id;
  std::vector<int16_t> kind;       // KindTable index
  std::vector<uint8_t> state;      // index into Kind::states
  std::vector<Vec3> pos;           // base centre on the ground (local frame, m)
  std::vector<float> heading_deg;  // compass
  std::vector<float> radius_m;     // bounding radius (from the kind)
  std::vector<float> reach_m;      // from pos, how far in x, y any shape of any state reaches
                                   // (World::index_fixed; the grid lists objects by it)
  size_t size() const { return id.size(); }
  void add(std::string id_, int kind_, const Vec3& p, float heading, float radius);
  bool valid() const;  // invariant: every array has size() entries
};

// Moving entities: vehicles and munitions, structure of arrays. Dead ones stay (wrecks are
// still obstacles); munitions that detonated are marked inactive.
struct Entities {
  std::vector<std::string> id;
  std::vector<int16_t> kind;
  std::vector<uint8_t> state;        // index into Kind::states (0 intact ... last = wreck)
  std::vector<Vec3> pos;             // centre of the ground contact (local frame, m)
  std::vector<Vec3> vel;             // m/s
  std::vector<float> heading_deg, pitch_deg, roll_deg;
  std::vector<float> radius_m;
  std::vector<float> cruise_mps;     // wanted speed
  std::vector<float> max_mps;        // limit (Table 2 or scenario override)
  std::vector<uint8_t> active;       // 0 = munition spent / entity removed
  std::vector<uint8_t> local;        // 1 = driven by this node, 0 = remote (from the network)
  std::vector<uint8_t> snapshots;    // collisions of this entity are snapshotted
  std::vector<uint8_t> autonomous;
  std::vector<int32_t> target;       // munitions: entity index or -1
  std::vector<Vec3> aim;             // munitions: aim point; vehicles: current waypoint
  std::vector<int32_t> owner;        // munitions: shooter index; -1 otherwise
  std::vector<int32_t> rounds;
  std::vector<float> fuel_l;
  std::vector<int32_t> node;                 // the node that drives it (--node)
  std::vector<uint8_t> force;                // DIS Force ID: 1 friendly, 2 opposing, 3 neutral (0 other)
  std::vector<std::vector<Vec2>> route;      // waypoints (set once at load; not touched per tick)
  std::vector<int32_t> leg;                  // index of the waypoint being steered to
  std::vector<uint8_t> loop_route;           // 1 = start over after the last waypoint
  std::vector<float> flee_until;             // autonomous: fleeing until this time (s)
  std::vector<float> calm_until;             // autonomous: no new reaction before this time (s)
  std::vector<uint8_t> driven;               // 1 = a player drives it (dynamics/drive.hpp), not its route
  int64_t created = 0;                       // entities ever made (add or reset): ids change when it does
  // Which slots the last kMadeMemory entities made went to, for readers that follow the ids
  // (collision::IdRank): made_since(l, k, out) appends the slots of the entities made since
  // `created` was k and says true, or says false when that is more than kMadeMemory ago or l is
  // not this table's `lineage` (every copy of the table, or assignment to it, draws a new one).
  static constexpr int64_t kMadeMemory = 1024;
  struct Lineage {
    uint64_t v = draw();
    Lineage() = default;
    Lineage(const Lineage&) : v(draw()) {}
    Lineage& operator=(const Lineage&) { return v = draw(), *this; }
    static uint64_t draw() {
      static std::atomic<uint64_t> next{1};
      return next.fetch_add(1, std::memory_order_relaxed);
    }
  };
  Lineage lineage;
  bool made_since(uint64_t lineage_then, int64_t created_then, std::vector<uint32_t>& out) const;
  size_t size() const { return id.size(); }
  int add(std::string id_, int kind_, const Vec3& p, float heading, float radius);
  // Makes slot e a new entity, every field as add() sets it (a spent munition's slot, reclaimed).
  void reset(int e, std::string id_, int kind_, const Vec3& p, float heading, float radius);
  bool valid() const;  // invariant: every array has size() entries

 private:
  std::array<uint32_t, kMadeMemory> made_slot_{};  // entity number k (0-based) went to made_slot_[k % kMadeMemory]
};

struct World {
  Terrain terrain;
  ModelLibrary models;
  KindTable kinds;
  FixedObjects fixed;
  FixedGrid grid;  // the one index of fixed objects (fixed_grid.hpp): index_fixed() builds it
  Entities ents;
  double water_level_m = -1e9;  // ships sail where the terrain is below it
  double t = 0;                 // scenario time, s
  int64_t frame = 0;

  // Invariants (asserted in debug builds, as Box2D validates its broad phase): array sizes
  // match, kind, state, owner and target indices in range, the grid lists every object where
  // its reach says. valid_state() is the same without the grid, O(entities + objects): what
  // world::apply asserts, since apply never rebuilds the grid nor moves an object across the
  // plane (a crater only settles it in z); index_fixed() asserts the whole of valid().
  bool valid() const;
  bool valid_state() const;
  // Computes every fixed object's reach (its kind's models, every state, with the margin the
  // collision tiers use) and builds the grid; call after adding fixed objects.
  void index_fixed();
  // (Terrain::surely_above first: the same answer, most places without height()'s divisions.)
  bool is_water(double x, double y) const {
    return !terrain.surely_above(x, y, water_level_m) && terrain.height(x, y) < water_level_m;
  }
  const Kind& kind_of_entity(size_t i) const { return kinds[ents.kind[i]]; }
  bool is_munition(size_t i) const { return kind_of_entity(i).mobility == Mobility::Munition; }
};

}  // namespace npsnet::world
