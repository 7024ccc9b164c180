// Test worlds: a flat (or sloped) terrain with the bundled kinds and models, and helpers to
// place vehicles and fixed objects. Header-only, shared by the room tests.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>

#include "support/dirs.hpp"
#include "dynamics/dynamics.hpp"
#include "world/changes.hpp"
#include "support/scratch.hpp"
#include "world/pose.hpp"
#include "world/scenario.hpp"

namespace npsnet::test {

inline std::filesystem::path source(const std::string& rel) { return std::filesystem::path(npsnet::dirs::source()) / rel; }

// An id made of a prefix and a number, "v" and 12 -> "v12". Appended: GCC 12 warns falsely
// (-Wstringop-overflow, -Wrestrict) where "v" + std::to_string(12) is inlined.
inline std::string numbered(std::string_view prefix, long long i) {
  std::string s(prefix);
  return s.append(std::to_string(i));
}

// A 2 km square at 10 m posts; height = base + slope_x * x.
// The default scenario with a background crowd of `vehicles` (seed `seed`) placed and driving in
// the square [lo, hi] of the local frame: the crowd of the threading and net-out tests.
inline world::Scenario default_with_crowd(int vehicles, uint64_t seed, const Vec2& lo, const Vec2& hi) {
  world::Scenario s = world::load_scenario(source("scenarios/default.toml"));
  s.background_vehicles = vehicles;
  s.background_seed = seed;
  s.background_area = std::make_pair(lo, hi);
  return s;
}

inline world::World flat_world(double base = 100.0, double slope_x = 0.0) {
  world::World w;
  const int n = 201;
  std::vector<float> h(static_cast<size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) h[static_cast<size_t>(j) * n + i] = static_cast<float>(base + slope_x * i * 10.0);
  w.terrain = world::Terrain(n, n, 10.0, std::move(h), {35.98, -121.25, 0});
  w.kinds = world::KindTable::load(world::default_kinds_file(), w.models);
  w.water_level_m = -1000;
  return w;
}

inline int add_vehicle(world::World& w, const std::string& id, const std::string& kind, double x, double y,
                       double heading, double speed_mps) {
  const int k = w.kinds.find(kind);
  const int e = w.ents.add(id, k, Vec3(x, y, w.terrain.height(x, y)), static_cast<float>(heading),
                           static_cast<float>(w.kinds[k].radius_m));
  const Vec2 d = heading_to_dir(heading);
  w.ents.vel[e] = Vec3(d.x(), d.y(), 0) * speed_mps;
  w.ents.cruise_mps[e] = static_cast<float>(speed_mps);
  w.ents.max_mps[e] = static_cast<float>(std::max(speed_mps, kmh2mps(w.kinds[k].max_speed_kmh)));
  w.ents.rounds[e] = w.kinds[k].rounds;
  w.ents.fuel_l[e] = static_cast<float>(w.kinds[k].fuel_l);  // a full tank, as build_world gives
  return e;
}

inline int add_fixed(world::World& w, const std::string& id, const std::string& kind, double x, double y) {
  const int k = w.kinds.find(kind);
  w.fixed.add(id, k, Vec3(x, y, w.terrain.height(x, y)), 0.0f, static_cast<float>(w.kinds[k].radius_m));
  return static_cast<int>(w.fixed.size() - 1);
}

// dynamics::fire decided and applied (as the node's tick does): the munition's index, or -1.
inline int fire(world::World& w, int shooter, int munition_kind, const Vec3& target_point, int target) {
  const auto l = dynamics::fire(w, shooter, munition_kind, target_point, target);
  if (!l) return -1;
  world::Changes c;
  c.launches.push_back(*l);
  world::Applied a;
  world::apply(w, c, a);
  return a.launched.at(0);
}

inline void index_fixed(world::World& w) { w.index_fixed(); }

inline std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const auto dir = npsnet::test::scratch_dir();
  std::filesystem::create_directories(dir);
  const auto p = dir / name;
  std::ofstream(p) << text;
  return p;
}

}  // namespace npsnet::test
