// The crowd of the speed benchmarks (bench_broadphase, bench_budget_error --crowd): N vehicles
// (m1a1, bmp, hmmwv in turn) added to a world, every other one spread over the whole map, the
// others crowded in the 2 km square at its centre; random headings, 0-15 m/s along them. Seeded by
// N, so every benchmark that asks for N gets the same crowd. Stored in the order drawn (vehicle i
// at index i), or with `spatial`, the same vehicles stored in Z order of their 32 m cells, as a
// spatial order of the entities would keep them (neighbours near each other in memory).
#pragma once
#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "world/world.hpp"

namespace npsnet::bench {

inline void add_crowd(world::World& w, int n, bool spatial = false) {
  const double W = w.terrain.width_m(), D = w.terrain.depth_m();
  std::mt19937_64 rng(20261123u + static_cast<uint64_t>(n));
  std::uniform_real_distribution<double> u(0, 1);
  const char* kinds[] = {"m1a1", "bmp", "hmmwv"};
  const double cx = 0.5 * W, cy = 0.5 * D;  // the crowded 2 km square's centre
  struct Drawn {
    double x, y, heading, speed;
    int i;
    uint64_t z;  // Z-order (Morton) key of its 32 m cell
  };
  std::vector<Drawn> drawn;
  for (int i = 0; i < n; ++i) {
    double x, y;
    if (i % 2) x = cx + (u(rng) - 0.5) * 2000, y = cy + (u(rng) - 0.5) * 2000;
    else x = u(rng) * W, y = u(rng) * D;
    const double heading = u(rng) * 360, speed = u(rng) * 15;
    const auto gx = static_cast<uint32_t>(x / 32), gy = static_cast<uint32_t>(y / 32);
    uint64_t z = 0;
    for (int b = 0; b < 16; ++b) z |= (uint64_t{(gx >> b) & 1u} << (2 * b)) | (uint64_t{(gy >> b) & 1u} << (2 * b + 1));
    drawn.push_back({x, y, heading, speed, i, z});
  }
  if (spatial) std::stable_sort(drawn.begin(), drawn.end(), [](const Drawn& a, const Drawn& b) { return a.z < b.z; });
  for (const Drawn& d : drawn) {
    const int k = w.kinds.find(kinds[d.i % 3]);
    const int e = w.ents.add(std::string("v").append(std::to_string(d.i)), k, Vec3(d.x, d.y, w.terrain.height(d.x, d.y)),
                             static_cast<float>(d.heading), static_cast<float>(w.kinds[k].radius_m));
    const Vec2 dir = heading_to_dir(w.ents.heading_deg[e]);
    w.ents.vel[e] = Vec3(dir.x(), dir.y(), 0) * d.speed;
  }
}

}  // namespace npsnet::bench
