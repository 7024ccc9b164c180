// heading_to_dir (core/math.hpp) of each entity slot's heading, a float in degrees, kept from
// tick to tick while that float keeps its bits. A vehicle on a straight leg keeps the same float
// heading tick after tick, so its direction comes from here instead of a sin and a cos.
//
// Contract:
//  * dir(e, h) returns heading_to_dir(h), bit for bit: the entry is a function of h's bits only
//    (-0 and +0 are kept apart), so whatever entity a slot later holds, a matching key gives the
//    sin and cos's own bits; a miss computes them and keeps them in slot e.
//  * One memo serves every stage of a tick that turns a heading into a direction (issue 13):
//    dynamics::step notes each moved ground vehicle's new heading, so collision's sweeps then
//    find it. Slots are written only by the stage's range that owns entity e (core/jobs.hpp).
//  * resize(n) before a stage reads slots [0, n); it only grows (0 = no entry yet).
#pragma once
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/math.hpp"

namespace npsnet::core {

class HeadingMemo {
 public:
  void resize(size_t n) {
    if (key_.size() < n) key_.resize(n, 0), dir_.resize(n);
  }
  size_t size() const { return key_.size(); }
  Vec2 dir(size_t e, float h) {
    const uint64_t key = (uint64_t{1} << 32) | std::bit_cast<uint32_t>(h);
    if (key_[e] == key) return dir_[e];
    const Vec2 d = heading_to_dir(h);
    key_[e] = key, dir_[e] = d;
    return d;
  }
  // Slot e's entry: its heading's bits with 1 << 32 (0: none) and its direction (tests).
  uint64_t key(size_t e) const { return key_[e]; }
  const Vec2& kept_dir(size_t e) const { return dir_[e]; }

 private:
  std::vector<uint64_t> key_;
  std::vector<Vec2> dir_;
};

}  // namespace npsnet::core
