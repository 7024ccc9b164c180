// Particle effects at a point, driven by scenario time t (s): an explosion (white flash, a
// fireball that grows and cools over ~1.6 s, then a smoke column rising for ~10 s) and a fire
// (flickering flames and a smoke column for its duration, then ~8 s of dying smoke). Every
// particle's state is a pure function of (effect, particle number, age), so a frame rendered
// from a past world state (a snapshot's "imminent" frame) shows the effect as it was then, and
// an effect not yet started (t < start) shows nothing.
#pragma once
#include <cstdint>
#include <vector>

#include "core/math.hpp"

namespace npsnet::render {

struct Particle {  // matches particle.vert
  float x, y, z, size;  // world m, diameter m
  float r, g, b, a;     // premultiplied colour, alpha
};

class Effects {
 public:
  void add_explosion(const Vec3& at, double t, float scale);
  void add_fire(const Vec3& at, double t, double seconds);
  // Particles alive at time t, smoke first then flames (drawn in that order). Effects over for
  // longer than `keep_s` before t are dropped.
  const std::vector<Particle>& particles(double t, double keep_s = 30.0);
  size_t effect_count() const { return effects_.size(); }

 private:
  struct Effect {
    Vec3 at;
    double t0, duration;
    float scale;
    uint32_t seed;
    bool fire;
  };
  std::vector<Effect> effects_;
  std::vector<Particle> smoke_, flame_, out_;
  uint32_t next_seed_ = 0x9E3779B9u;
};

}  // namespace npsnet::render
