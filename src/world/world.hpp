// The world a node simulates: terrain, kinds and models, fixed objects with their 125 m
// gridsquare index, and the moving entities (vehicles and munitions) as contiguous arrays.
// Entities and fixed objects are referred to by index; nothing holds pointers across ticks.
// The world is changed in one place, world::apply (changes.hpp), from fire orders, reactions and
// collision outcomes; only the integrator (dynamics::step / drive) writes poses directly.
// Threading: a World belongs to the tick's thread; during a tick's parallel stages workers read
// it and write only the entity slots they were given; nothing here locks.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/constants.hpp"
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
  size_t size() const { return id.size(); }
  void add(std::string id_, int kind_, const Vec3& p, float heading, float radius);
  bool valid() const;  // invariant: every array has size() entries
};

// Gridsquare index of fixed objects (thesis p. 8-9: 125 m gridsquares, a list per gridsquare).
// CSR layout: objects of cell c are items[start[c] .. start[c+1]). An object is listed in every
// gridsquare its bounding sphere overlaps (this removes the thesis's Figure 9 border miss);
// `home_only` lists it only in the gridsquare holding its centre (the thesis's behaviour).
class GridIndex {
 public:
  void build(const FixedObjects& objs, double width_m, double depth_m, double cell_m,
             bool home_only = false);
  int cols() const { return cols_; }
  int rows() const { return rows_; }
  double cell_m() const { return cell_; }
  int cell_of(double x, double y) const;  // clamped to the map
  // Invariant: offsets ascend, every listing names an object of `objs`, each object listed in
  // exactly the gridsquares build() gave it.
  bool valid(const FixedObjects& objs) const;
  std::pair<const uint32_t*, const uint32_t*> objects_in(int cell) const {
    return {items_.data() + start_[cell], items_.data() + start_[cell + 1]};
  }

  struct CellRect {
    int i0, j0, i1, j1;  // inclusive gridsquare columns / rows, clamped to the map
  };
  // Gridsquares the square [x - r, x + r] x [y - r, y + r] overlaps.
  CellRect cells_of(double x, double y, double r) const;
  // Calls f(object index) once for every fixed object listed in a gridsquare that the square
  // [x - r, x + r] x [y - r, y + r] overlaps (an object listed in several is reported once).
  template <class F>
  void for_each_near(const FixedObjects& objs, double x, double y, double r, F&& f) const {
    const CellRect q = cells_of(x, y, r);
    for (int j = q.j0; j <= q.j1; ++j)
      for (int i = q.i0; i <= q.i1; ++i) {
        auto [first, last] = objects_in(j * cols_ + i);
        for (auto it = first; it != last; ++it) {
          const CellRect o = cells_of(objs.pos[*it].x(), objs.pos[*it].y(), home_only_ ? 0.0 : objs.radius_m[*it]);
          if (i == std::max(o.i0, q.i0) && j == std::max(o.j0, q.j0)) f(static_cast<int>(*it));
        }
      }
  }

 private:
  int cols_ = 0, rows_ = 0;
  double cell_ = 125;
  bool home_only_ = false;
  std::vector<uint32_t> start_, items_;
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
  std::vector<std::vector<Vec2>> route;      // waypoints (set once at load; not touched per tick)
  std::vector<int32_t> leg;                  // index of the waypoint being steered to
  std::vector<uint8_t> loop_route;           // 1 = start over after the last waypoint
  std::vector<float> flee_until;             // autonomous: fleeing until this time (s)
  std::vector<float> calm_until;             // autonomous: no new reaction before this time (s)
  std::vector<uint8_t> driven;               // 1 = a player drives it (dynamics/drive.hpp), not its route
  size_t size() const { return id.size(); }
  int add(std::string id_, int kind_, const Vec3& p, float heading, float radius);
  bool valid() const;  // invariant: every array has size() entries
};

struct World {
  Terrain terrain;
  ModelLibrary models;
  KindTable kinds;
  FixedObjects fixed;
  GridIndex grid;
  Entities ents;
  double water_level_m = -1e9;  // ships sail where the terrain is below it
  double t = 0;                 // scenario time, s
  int64_t frame = 0;

  // Invariants (asserted in debug builds, as Box2D validates its broad phase): array sizes
  // match, kind, state, owner and target indices in range, the grid lists every object.
  bool valid() const;
  bool is_water(double x, double y) const { return terrain.height(x, y) < water_level_m; }
  const Kind& kind_of_entity(size_t i) const { return kinds[ents.kind[i]]; }
  bool is_munition(size_t i) const { return kind_of_entity(i).mobility == Mobility::Munition; }
};

}  // namespace npsnet::world
