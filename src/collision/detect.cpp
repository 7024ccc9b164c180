// Method dispatch and the thesis detection (ch. III.C): fixed objects from the gridsquare list
// below the threshold height, then moving objects through L1 (100 m window), L2 (spheres) and
// L3 (rays + Haines). The continuous method is in continuous.cpp.
#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <string_view>

#include "collision/collision.hpp"
#include "core/constants.hpp"
#include "core/radix_sort.hpp"
#include "core/stopwatch.hpp"
#include "world/pose.hpp"

namespace npsnet::collision {

void Detector::detect(const world::World& w, std::vector<Contact>& out) {
  assert(w.valid());
  const auto t0 = std::chrono::steady_clock::now();
  times_ = PassTimes{};
  touching_.clear();
  candidates_.clear();
  // Last tick's keys, sorted, or past kEpisodeIndexMin of them (59,000 in the 100,000-vehicle
  // crowd) bucketed by lower index (index_episodes); the thesis's few pairs need no index.
  if (opt_.method == Method::Thesis || previous_.size() < kEpisodeIndexMin) {
    core::radix_sort(previous_, sort_scratch_);
    lo_start_.clear();
  } else {
    index_episodes(w.ents.size());
  }
  if (opt_.method == Method::Thesis) detect_thesis(w);
  else detect_continuous(w);

  // One event per contact episode: report only pairs not touching last tick.
  for (const Contact& k : candidates_) {
    if (was_in_contact(contact_key(k.a, k.b, k.b_fixed))) continue;
    out.push_back(k);
    ++stats_.contacts;
  }
  previous_.swap(touching_);
  times_.total = core::ms_since(t0);
}

void Detector::index_episodes(size_t n) {
  // A counting sort of the moving pairs' keys by the bucket of their lower index (one pass to
  // count, one to place: each bucket keeps last tick's order), then the fixed contacts' keys (top
  // bit), sorted. Bucket b counted at b + 2: after the running sums lo_start_[b + 1] is where b
  // starts, and placing moves it on to where b + 1 starts, which leaves lo_start_[b] at b's start.
  const size_t buckets = episode_bucket(n) + 1;  // the last: lower indices from n on (none asked)
  lo_start_.assign(buckets + 2, 0);
  auto bucket = [n](uint64_t key) { return episode_bucket(std::min<uint64_t>((key >> 31) & 0xffffffffu, n)); };
  size_t fixed = 0;
  for (const uint64_t key : previous_) {
    if (key >> 63) ++fixed;
    else ++lo_start_[bucket(key) + 2];
  }
  for (size_t b = 1; b < lo_start_.size(); ++b) lo_start_[b] += lo_start_[b - 1];
  const size_t moving = previous_.size() - fixed;
  sort_scratch_.resize(previous_.size());
  size_t f = moving;
  for (const uint64_t key : previous_) {
    if (key >> 63) sort_scratch_[f++] = key;
    else sort_scratch_[lo_start_[bucket(key) + 1]++] = key;
  }
  lo_start_.pop_back();  // lo_start_[buckets]: the moving keys' end, where the fixed keys start
  std::sort(sort_scratch_.begin() + static_cast<std::ptrdiff_t>(moving), sort_scratch_.end());
  previous_.swap(sort_scratch_);
}

bool Detector::was_in_contact(uint64_t key) const {
  if (lo_start_.empty()) return std::binary_search(previous_.begin(), previous_.end(), key);
  if (!(key >> 63)) return moving_key_was(key);
  const size_t lo = lo_start_.size() - 1;  // (the fixed keys follow the last bucket)
  return std::binary_search(previous_.begin() + lo_start_[lo], previous_.end(), key);
}

void Detector::detect_thesis(const world::World& w) {
  const auto& ents = w.ents;
  const int n = static_cast<int>(ents.size());

  // 1. Fixed objects (p. 9-10): only below the threshold height, from the gridsquare's list.
  for (int e = 0; e < n; ++e) {
    if (!ents.active[e]) continue;
    const Vec3 c = world::entity_centre(w, e);
    const double agl = ents.pos[e].z() - w.terrain.height(ents.pos[e].x(), ents.pos[e].y());
    if (agl > thesis::kFixedCheckThresholdHeightM) continue;
    const double r = world::entity_radius(w, e);
    w.grid.for_each_home(w.grid.cell_of(ents.pos[e].x(), ents.pos[e].y()), [&](int o) {
      ++stats_.fixed_tests;
      const Vec3 fc = world::fixed_centre(w, o);
      const double rr = r + world::fixed_radius(w, o);
      if ((fc - c).squaredNorm() >= rr * rr) return;
      const uint64_t key = contact_key(e, o, true);
      touching_.push_back(key);
      Contact k;
      k.a = e, k.b = o, k.b_fixed = true, k.hit = true;
      const Vec3 d = fc - c;
      k.normal = d.norm() > 1e-9 ? Vec3(d.normalized()) : Vec3::UnitX();
      k.point = c + k.normal * std::min(r, d.norm());
      k.method = "sphere-fixed";
      k.tier = "sphere";
      candidates_.push_back(k);
    });
  }

  // 2. Moving objects. L1 as a sweep over x: pairs with |dx| and |dy| both within 100 m.
  order_.clear();
  for (int e = 0; e < n; ++e)
    if (ents.active[e]) order_.push_back(static_cast<uint32_t>(e));
  std::sort(order_.begin(), order_.end(), [&](uint32_t a, uint32_t b) { return ents.pos[a].x() < ents.pos[b].x(); });
  const double win = thesis::kFirstLevelWindowM;
  for (size_t i = 0; i < order_.size(); ++i) {
    const int a = static_cast<int>(order_[i]);
    for (size_t j = i + 1; j < order_.size(); ++j) {
      const int b = static_cast<int>(order_[j]);
      if (ents.pos[b].x() - ents.pos[a].x() > win) break;
      if (std::abs(ents.pos[b].y() - ents.pos[a].y()) > win) continue;
      ++stats_.l1_pairs;
      // A munition never meets its own shooter, nor another munition.
      if (ents.owner[a] == b || ents.owner[b] == a) continue;
      if (w.is_munition(a) && w.is_munition(b)) continue;
      // L2: centre distance < sum of radii.
      const Vec3 ca = world::entity_centre(w, a), cb = world::entity_centre(w, b);
      const double rr = world::entity_radius(w, a) + world::entity_radius(w, b);
      if ((cb - ca).squaredNorm() >= rr * rr) continue;
      ++stats_.l2_pairs;
      // L3: rays + Haines, from either side. Munitions are points on the scale of a vehicle:
      // their sphere touching is contact.
      Vec3 p;
      ++stats_.l3_tests;
      bool real;
      const char* method = "L3-haines";
      if (w.is_munition(a) || w.is_munition(b)) {
        real = true;
        p = w.is_munition(a) ? ca : cb;
        method = "L2-munition";
      } else {
        real = l3_real(w, a, b, p) || l3_real(w, b, a, p);
      }
      if (!real) {  // only the spheres touched: tried again next tick
        ++stats_.l3_rejects;
        continue;
      }
      const int lo = std::min(a, b), hi = std::max(a, b);
      touching_.push_back(contact_key(lo, hi, false));
      Contact k;
      k.a = lo, k.b = hi, k.hit = true;
      const Vec3 d = (lo == a ? cb - ca : ca - cb);
      k.normal = d.norm() > 1e-9 ? Vec3(d.normalized()) : Vec3::UnitX();
      k.point = p;
      k.method = method;
      k.tier = method == std::string_view("L3-haines") ? "mesh" : "sphere";  // L3: the polygons
      candidates_.push_back(k);
    }
  }

}

}  // namespace npsnet::collision
