#include "render/effects.hpp"

#include <algorithm>
#include <cmath>

namespace npsnet::render {
namespace {

// Deterministic random in [0, 1) from (seed, particle, channel).
float rnd(uint32_t seed, uint32_t k, uint32_t ch) {
  uint32_t h = seed ^ (k * 0x85EBCA6Bu) ^ (ch * 0xC2B2AE35u);
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

constexpr float kWindX = 2.0f, kWindY = 0.8f;  // smoke drift, m/s
constexpr double kExplosionS = 12.0;            // flash + fireball + smoke
constexpr double kFireTailS = 8.0;              // smoke after a fire's flames die

void push(std::vector<Particle>& v, const Vec3& p, float size, float r, float g, float b, float a, float glow) {
  // premultiplied; `glow` < 1 makes a particle partly additive (flames)
  v.push_back({static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()), size, r * a, g * a,
               b * a, a * glow});
}

}  // namespace

void Effects::add_explosion(const Vec3& at, double t, float scale) {
  if (!at.allFinite() || !std::isfinite(t)) return;
  effects_.push_back({at, t, kExplosionS, std::clamp(scale, 0.05f, 50.0f), next_seed_, false});
  next_seed_ = next_seed_ * 1664525u + 1013904223u;
}

void Effects::add_fire(const Vec3& at, double t, double seconds) {
  if (!at.allFinite() || !std::isfinite(t) || !(seconds > 0)) return;
  effects_.push_back({at, t, std::min(seconds, 3600.0) + kFireTailS, 1.0f, next_seed_, true});
  next_seed_ = next_seed_ * 1664525u + 1013904223u;
}

const std::vector<Particle>& Effects::particles(double t, double keep_s) {
  effects_.erase(std::remove_if(effects_.begin(), effects_.end(),
                                [&](const Effect& e) { return t > e.t0 + e.duration + keep_s; }),
                 effects_.end());
  smoke_.clear();
  flame_.clear();
  for (const Effect& e : effects_) {
    const double age = t - e.t0;
    if (age < 0 || age > e.duration) continue;
    const float s = e.scale;
    const auto a = static_cast<float>(age);
    if (!e.fire) {
      if (a < 0.25f) {  // flash
        const float k = 1.0f - a / 0.25f;
        push(flame_, e.at + Vec3(0, 0, 2.0 * s), 22.0f * s * (0.4f + 0.6f * k), 1.0f, 0.97f, 0.85f, k, 0.4f);
      }
      for (uint32_t k = 0; k < 22; ++k) {  // fireball
        const float life = 1.2f + 0.6f * rnd(e.seed, k, 0);
        if (a > life) continue;
        const float u = a / life;
        const float th = 6.2831853f * rnd(e.seed, k, 1), ph = 1.3f * rnd(e.seed, k, 2);
        const float reach = (4.0f + 5.0f * rnd(e.seed, k, 3)) * s * (1.0f - std::exp(-a * 5.0f));
        const Vec3 dir(std::cos(ph) * std::cos(th), std::cos(ph) * std::sin(th), std::sin(ph) + 0.2f);
        const Vec3 p = e.at + dir * reach + Vec3(0, 0, (1.0 + 2.5 * a) * s);
        const float hot = 1.0f - u;
        push(flame_, p, (3.0f + 4.0f * u) * s, 1.0f, 0.35f + 0.55f * hot * hot, 0.08f + 0.3f * hot * hot * hot,
             0.95f * (1.0f - u * u), 0.55f);
      }
      for (uint32_t k = 0; k < 26; ++k) {  // smoke column
        const float start = 0.3f + 1.5f * rnd(e.seed, k, 4);
        const float life = 6.0f + 5.0f * rnd(e.seed, k, 5);
        const float b = a - start;
        if (b < 0 || b > life) continue;
        const float u = b / life;
        const float rise = (2.5f + 3.0f * rnd(e.seed, k, 6)) * std::sqrt(s);
        const Vec3 p = e.at + Vec3((rnd(e.seed, k, 7) - 0.5f) * 4.0f * s + kWindX * b,
                                   (rnd(e.seed, k, 8) - 0.5f) * 4.0f * s + kWindY * b, 2.0f * s + rise * b);
        const float grey = 0.16f + 0.28f * u;
        push(smoke_, p, (3.0f + 10.0f * u) * s, grey, grey, grey * 0.95f,
             0.75f * std::min(1.0f, b * 3.0f) * (1.0f - u), 1.0f);
      }
    } else {
      const float burn = static_cast<float>(e.duration - kFireTailS);
      const float fade = a < burn ? 1.0f : std::max(0.0f, 1.0f - (a - burn) / 1.0f);
      if (fade > 0)
        for (uint32_t k = 0; k < 14; ++k) {  // flames: each cycles up and out every 0.5-0.9 s
          const float period = 0.5f + 0.4f * rnd(e.seed, k, 0);
          const float u = std::fmod(a / period + rnd(e.seed, k, 1), 1.0f);
          const float th = 6.2831853f * rnd(e.seed, k, 2);
          const float rr = 1.2f * rnd(e.seed, k, 3) * (1.0f - u);
          const Vec3 p = e.at + Vec3(rr * std::cos(th), rr * std::sin(th), 0.3 + 3.5 * u);
          push(flame_, p, 2.2f * (1.0f - 0.6f * u), 1.0f, 0.45f + 0.45f * (1.0f - u), 0.1f,
               0.9f * (1.0f - u) * fade, 0.5f);
        }
      for (uint32_t k = 0; k < 22; ++k) {  // smoke: a continuous column while burning
        const float period = 6.0f + 3.0f * rnd(e.seed, k, 4);
        const float born = period * rnd(e.seed, k, 5);  // phase of the emission
        const float cycle = std::floor((a + born) / period);
        const float emit_time = cycle * period - born;  // when this puff left the fire
        if (emit_time < 0 || emit_time > burn) continue;
        const float b = a - emit_time, u = b / period;
        const Vec3 p = e.at + Vec3((rnd(e.seed, k, 6) - 0.5f) * 1.5f + kWindX * b,
                                   (rnd(e.seed, k, 7) - 0.5f) * 1.5f + kWindY * b, 3.0 + 3.5 * b);
        const float grey = 0.12f + 0.25f * u;
        push(smoke_, p, 2.5f + 9.0f * u, grey, grey, grey, 0.65f * (1.0f - u) * std::min(1.0f, b * 2.0f), 1.0f);
      }
    }
  }
  out_.clear();
  out_.insert(out_.end(), smoke_.begin(), smoke_.end());
  out_.insert(out_.end(), flame_.begin(), flame_.end());
  return out_;
}

}  // namespace npsnet::render
