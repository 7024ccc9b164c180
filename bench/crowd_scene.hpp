// The crowd of the speed benchmarks (bench_broadphase, bench_budget_error --crowd): N vehicles
// (m1a1, bmp, hmmwv in turn) added to a world, every other one spread over the whole map, the
// others crowded in the 2 km square at its centre; random headings, 0-15 m/s along them. Seeded by
// N, so every benchmark that asks for N gets the same crowd.
#pragma once
#include <random>
#include <string>

#include "world/world.hpp"

namespace npsnet::bench {

inline void add_crowd(world::World& w, int n) {
  const double W = w.terrain.width_m(), D = w.terrain.depth_m();
  std::mt19937_64 rng(20261123u + static_cast<uint64_t>(n));
  std::uniform_real_distribution<double> u(0, 1);
  const char* kinds[] = {"m1a1", "bmp", "hmmwv"};
  const double cx = 0.5 * W, cy = 0.5 * D;  // the crowded 2 km square's centre
  for (int i = 0; i < n; ++i) {
    double x, y;
    if (i % 2) x = cx + (u(rng) - 0.5) * 2000, y = cy + (u(rng) - 0.5) * 2000;
    else x = u(rng) * W, y = u(rng) * D;
    const int k = w.kinds.find(kinds[i % 3]);
    const int e = w.ents.add(std::string("v").append(std::to_string(i)), k, Vec3(x, y, w.terrain.height(x, y)),
                             static_cast<float>(u(rng) * 360), static_cast<float>(w.kinds[k].radius_m));
    const Vec2 d = heading_to_dir(w.ents.heading_deg[e]);
    w.ents.vel[e] = Vec3(d.x(), d.y(), 0) * (u(rng) * 15);
  }
}

}  // namespace npsnet::bench
