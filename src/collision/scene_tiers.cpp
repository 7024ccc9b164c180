// The scene-aware auto tier (collision.hpp): which tier each pair that needs a narrow phase gets
// this tick, from the scene (driven, snapshotted, seen) and the budget of modelled time.
#include <algorithm>

#include "collision/collision.hpp"
#include "world/pose.hpp"

namespace npsnet::collision {

ViewVolume ViewVolume::box(const Vec3& lo, const Vec3& hi) {
  ViewVolume v;
  v.eye = 0.5 * (lo + hi);
  const Vec3 half = 0.5 * (hi - lo);
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector4d p = Eigen::Vector4d::Zero();
    p[k] = 1, p[3] = half[k];  // x_k - eye_k >= -half_k
    v.planes[2 * k] = p;
    p[k] = -1;                 // eye_k - x_k >= -half_k
    v.planes[2 * k + 1] = p;
  }
  return v;
}

void Detector::allocate_tiers(const world::World& w) {
  // Required: a driven or snapshotted vehicle (set when the pair was made), or a body seen by a viewer.
  for (Pending& q : pending_) {
    const int b = q.b;
    bool req = q.required;
    for (size_t v = 0; v < views_.size() && !req; ++v) {
      const ViewVolume& vv = views_[v];
      req = vv.sphere_inside(swept_[q.ia].c1, swept_[q.ia].r_bound) ||
            (q.b_fixed ? vv.sphere_inside(world::fixed_centre(w, b), fixed_r_[b])
                         : vv.sphere_inside(swept_[q.ib].c1, swept_[q.ib].r_bound));
    }
    q.required = req;
  }
  // Most important first: required, then the faster closing, then the id order. Sorted by
  // copies of those keys side by side (a comparison that read two Pendings, each on lines of
  // its own, missed the cache; 10,000 pairs a tick in the 100,000-vehicle crowd).
  pending_order_.resize(pending_.size());
  size_t required = 0;
  for (uint32_t i = 0; i < pending_order_.size(); ++i) {
    const Pending& q = pending_[i];
    pending_order_[i] = {q.closing, q.rank_a, q.rank_b, i, q.required, q.b_fixed};
    required += q.required;
  }
  auto more_important = [](const Importance& x, const Importance& y) {
    if (x.required != y.required) return x.required;
    if (x.closing != y.closing) return x.closing > y.closing;
    if (x.rank_a != y.rank_a) return x.rank_a < y.rank_a;
    if (x.b_fixed != y.b_fixed) return x.b_fixed < y.b_fixed;
    return x.rank_b < y.rank_b;
  };
  // Every pair gets at least the sphere tier, which is never lowered: its cost for all of them is
  // set aside first, and the rest of the budget pays for raising pairs above it, most important
  // first (a raise to tier t costs kTierCostUs[t] - the sphere's). So the modelled narrow phase
  // fits the budget whenever the sphere tier alone does; past that, only the required pairs raise.
  constexpr double kSphereUs = kTierCostUs[static_cast<int>(Tier::Sphere)];
  auto raise_us = [](Tier t) { return kTierCostUs[static_cast<int>(t)] - kSphereUs; };
  // Only a prefix needs its order: past the required pairs, a pair either is raised (charged at
  // least kCheapest) or finds no raise fits; from then on the budget left is below kCheapest, so
  // every pair after it gets the sphere tier whatever its place (choices_ lists them in no
  // particular order). The prefix: the required pairs and as many as the budget could raise at
  // kCheapest, sorted (nth_element, then sort), and sorted further if it runs out first.
  constexpr double kCheapest = kTierCostUs[static_cast<int>(Tier::Box)] - kSphereUs;
  static_assert(kCheapest > 0 && kTierCostUs[static_cast<int>(Tier::Box)] <= kTierCostUs[static_cast<int>(Tier::Hull)] &&
                kTierCostUs[static_cast<int>(Tier::Hull)] <= kTierCostUs[static_cast<int>(Tier::Mesh)]);
  const auto first = pending_order_.begin();
  const size_t n = pending_order_.size();
  size_t sorted = 0;  // pending_order_[0, sorted) is in order, and before every later one
  auto sort_to = [&](size_t k) {
    k = std::min(k, n);
    if (k < n) std::nth_element(first + sorted, first + k, pending_order_.end(), more_important);
    std::sort(first + sorted, first + k, more_important);
    sorted = k;
  };
  double left_us = opt_.budget_ms * 1000.0 - kSphereUs * static_cast<double>(n);
  times_.charged = kSphereUs * static_cast<double>(n) / 1000.0;
  sort_to(required + static_cast<size_t>(left_us > 0 ? std::min(left_us / kCheapest, 1e9) : 0.0) + 16);
  for (size_t i = 0; i < n; ++i) {
    if (i == sorted && (i < required || left_us >= kCheapest)) sort_to(2 * sorted);
    const Importance& o = pending_order_[i];
    Pending& q = pending_[o.pending];
    Tier t = q.exact;
    if (!q.required)
      while (t > Tier::Sphere && raise_us(t) > left_us) t = static_cast<Tier>(static_cast<int>(t) - 1);
    q.tier = t;
    left_us -= raise_us(t);
    times_.charged += raise_us(t) / 1000.0;
    if (t < q.exact) ++stats_.tier_lowered;
    choices_.push_back({q.a, q.b, q.b_fixed, q.required, q.exact, t});
  }
}

}  // namespace npsnet::collision
