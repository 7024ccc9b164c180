// The continuous method (collision.hpp): swept spheres in the broad phase, analytic time of
// impact, shape tiers up to what the pair needs, border objects from every gridsquare. Here the
// shapes, the passes of a tick (detect_continuous), their lanes and an entity's fixed objects;
// the tests of one moving pair and the narrow phase are in pair_tests.cpp.
#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "collision/collision.hpp"
#include "core/prefetch.hpp"
#include "core/stopwatch.hpp"
#include "world/pose.hpp"

namespace npsnet::collision {
namespace {

// Whether three floats (an orientation, a model centre) are the same, bit for bit (-0 is not
// +0). Float by float: the entity pass's orientation is made from three stores just before, and
// memcmp's 8-byte load of two of them stalled on stores that could not be forwarded (10 % of the
// pass's samples).
bool same_bits(const float* x, const float* y) {
  for (int k = 0; k < 3; ++k)
    if (std::bit_cast<uint32_t>(x[k]) != std::bit_cast<uint32_t>(y[k])) return false;
  return true;
}

// Rejects an entity whose position, velocity or orientation is NaN or infinite.
void check_finite(const world::Entities& ents, int e) {
  if (!finite(ents.pos[e]) || !finite(ents.vel[e]) || !std::isfinite(ents.heading_deg[e]) ||
      !std::isfinite(ents.pitch_deg[e]) || !std::isfinite(ents.roll_deg[e]))
    throw std::invalid_argument("collision: entity '" + ents.id[e] +
                                "': position, velocity or orientation is not finite (NaN or infinite)");
}

}  // namespace

std::vector<Shape> make_shapes(const world::World& w) {
  std::vector<Shape> shapes;
  for (int i = 0; i < w.models.size(); ++i) shapes.push_back(make_shape(w.models[i]));
  // Standing trunks: the states a kind gives a trunk radius collide as that cylinder.
  for (int k = 0; k < w.kinds.size(); ++k) {
    const world::Kind& kd = w.kinds[k];
    for (size_t s = 0; s < kd.trunk_radius_by_state.size() && s < kd.models.size(); ++s)
      if (kd.trunk_radius_by_state[s] > 0) shapes[kd.models[s]] = make_trunk(w.models[kd.models[s]], kd.trunk_radius_by_state[s]);
  }
  return shapes;
}

void Detector::prepare_shapes(const world::World& w) {
  if (static_cast<int>(shapes_.size()) == w.models.size()) return;
  shapes_ = make_shapes(w);
}

bool Detector::test_pair(const world::World& w, int a, int b, Contact& k) {
  const auto& ents = w.ents;
  for (int e : {a, b}) check_finite(ents, e);
  if (opt_.method == Method::Thesis) {
    // L2 then L3 at the end of the tick, as detect_thesis.
    const Vec3 ca = world::entity_centre(w, a), cb = world::entity_centre(w, b);
    const double rr = world::entity_radius(w, a) + world::entity_radius(w, b);
    if ((cb - ca).squaredNorm() >= rr * rr) return false;
    Vec3 p;
    if (!l3_real(w, a, b, p) && !l3_real(w, b, a, p)) return false;
    k.a = a, k.b = b, k.hit = true, k.point = p, k.fraction = 1, k.dt_s = 0, k.method = "L3-haines";
    k.tier = tier_name(Tier::Mesh);  // the thesis L3 decides on the polygons
    const Vec3 d = cb - ca;
    k.normal = d.norm() > 1e-9 ? Vec3(d.normalized()) : Vec3::UnitX();
    return true;
  }
  prepare_shapes(w);
  if (turn_.size() < ents.size()) turn_.resize(ents.size());
  for (int e : {a, b}) turn_[e].start = Hpr{ents.heading_deg[e], ents.pitch_deg[e], ents.roll_deg[e]};  // no turn known
  Vec3 c0[2], c1[2];
  double rs[2], rb[2];
  SweptTags t[2];  // (the tier's part: rank and required are not asked here)
  for (int s = 0; s < 2; ++s) {
    const int e = s ? b : a;
    c1[s] = world::entity_centre(w, e);
    c0[s] = c1[s] - ents.vel[e] * opt_.dt_s;
    rs[s] = world::entity_radius(w, e);
    const Tier top = opt_.tier != Tier::Auto ? opt_.tier : top_tier(w.kinds[ents.kind[e]]);
    t[s] = SweptTags::make(0, top, w.is_munition(e), false, false);
    const Shape& sh = shapes_[w.kinds[ents.kind[e]].models[ents.state[e]]];
    rb[s] = top == Tier::Sphere ? rs[s] : std::max(rs[s], sh.bound_radius * 1.0001 + 1e-3);
  }
  Lane& L = lane(0);
  const Tier tier = pair_tier(t[0], t[1]);
  const Trace h = pair_sweep(tier, c0[0], c1[0], rs[0], rb[0], c0[1], c1[1], rs[1], rb[1], L);
  const bool hit = h.hit && pair_hit(w, a, b, h, tier, k, L);
  merge_lanes(1);
  return hit;
}

Vec3 Detector::centre_end(const world::World& w, int e, Turn& t) {
  const auto& ents = w.ents;
  const Hpr now{ents.heading_deg[e], ents.pitch_deg[e], ents.roll_deg[e]};
  const Vec3f& c = w.kinds[ents.kind[e]].centre_by_state[ents.state[e]];
  if (!t.turned || !same_bits(t.prev.data(), now.data()) || !same_bits(t.centre.data(), c.data())) {
    t.offset = world::pose_rotation(memo().dir(static_cast<size_t>(e), now[0]), now[1], now[2]) * c.cast<double>();
    t.centre = c, t.prev = now, t.turned = 1;
  }
  return ents.pos[e] + t.offset;
}

void Detector::rank_ids(const world::World& w) {
  if (ranked_created_ != w.ents.created || ranked_lineage_ != w.ents.lineage.v ||
      rank_.ranks().size() != w.ents.size()) {  // ids made or reclaimed
    made_.clear();
    if (w.ents.made_since(ranked_lineage_, ranked_created_, made_)) rank_.update(w.ents.id, made_);
    else rank_.update(w.ents.id);
    ranked_created_ = w.ents.created, ranked_lineage_ = w.ents.lineage.v;
  }
  if (fixed_rank_.ranks().size() != w.fixed.size()) fixed_rank_.update(w.fixed.id);
}

Detector::Lane& Detector::lane(int c) {
  if (static_cast<int>(lanes_.size()) <= c) lanes_.resize(c + 1);
  return lanes_[c];
}

void Detector::merge_lanes(int k) {
  for (int c = 0; c < k; ++c) {
    Lane& L = lanes_[c];
    candidates_.insert(candidates_.end(), L.candidates.begin(), L.candidates.end());
    touching_.insert(touching_.end(), L.touching.begin(), L.touching.end());
    pending_.insert(pending_.end(), L.pending.begin(), L.pending.end());
    L.candidates.clear(), L.touching.clear(), L.pending.clear();
    DetectStats& s = L.stats;
    stats_.fixed_tests += s.fixed_tests, stats_.l1_pairs += s.l1_pairs, stats_.l2_pairs += s.l2_pairs;
    stats_.l3_tests += s.l3_tests, stats_.l3_rejects += s.l3_rejects, stats_.contacts += s.contacts;
    for (int t = 0; t < 5; ++t) stats_.tier_decided[t] += s.tier_decided[t];
    stats_.sweep_pairs += s.sweep_pairs, stats_.sweep_hits += s.sweep_hits, stats_.tier_lowered += s.tier_lowered;
    s = DetectStats{};
  }
}

namespace {
// Items per chunk below which a stage stays on one thread (a chunk claimed by a worker that is
// spinning, core/jobs.hpp, costs well under a microsecond; one item here, 0.3-1 us).
constexpr size_t kEntityGrain = 128, kPairGrain = 256, kPendingGrain = 4;
// Ranges a thread (core/jobs.hpp), claimed as threads come free: the long entity pass, and the
// pairs whose costs differ most (a pending pair's narrow phase: a sphere sweep or a mesh).
constexpr int kEntityChunksPerThread = 4, kPairChunksPerThread = 4, kPendingChunksPerThread = 8;
// A pending pair's bodies' sweeps, last read in the pair loop, asked of the cache kPendingAhead
// pairs early (the pair loop's own look-ahead: pair_tests.cpp).
constexpr size_t kPendingAhead = 4;
// The entity pass writes each entity's Swept, tags and box, which the pair loop and the broad
// phase read last tick on whichever thread had the pair: asked for kEntityAhead entities early.
constexpr size_t kEntityAhead = 8;
}  // namespace

void Detector::fixed_contacts(const world::World& w, size_t i, Lane& L) {
  const auto& ents = w.ents;
  const double dt = opt_.dt_s;
  const int e = static_cast<int>(order_[i]);
  const world::Kind& ke = w.kinds[ents.kind[e]];
  const Box& b = boxes_[i];
  const Swept& sw = swept_[i];
  auto test = [&](int o, float) {
    const float x = fixed_x_[o], y = fixed_y_[o], r = fixed_r_[o];
    if (x + r < b.lo[0] || x - r > b.hi[0] || y + r < b.lo[1] || y - r > b.hi[1]) return;
    ++L.stats.fixed_tests;
    const world::Kind& ko = w.kinds[w.fixed.kind[o]];
    const Tier tier = opt_.tier != Tier::Auto ? opt_.tier : std::min(top_tier(ke), top_tier(ko));
    const Vec3 fc = world::fixed_centre(w, o);  // live: craters re-seat objects
    const double rs = world::fixed_radius(w, o);
    const bool sphere = tier == Tier::Sphere || sw.tags.munition;
    const Trace h = sphere_sweep_checked(sw.c0, sw.c1, sphere ? sw.r_sphere : sw.r_bound, fc, fc,
                                 sphere ? rs : std::max<double>(rs, r));
    ++L.stats.sweep_pairs;
    if (!h.hit) {
      ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];
      return;
    }
    ++L.stats.sweep_hits;
    const uint64_t key = contact_key(e, static_cast<int>(o), true);
    const bool continuing = was_in_contact(key);
    if (continuing) {  // the episode goes on; detect() would drop its contact (moving pairs: the same)
      ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];
      L.touching.push_back(key);
      return;
    }
    Contact k;
    k.a = e, k.b = static_cast<int>(o), k.b_fixed = true, k.dt_s = dt;
    if (sphere) {
      ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];
      static_cast<Trace&>(k) = h;
      k.method = continuous_method_name(Tier::Sphere, true);
      k.tier = tier_name(Tier::Sphere);
    } else if (opt_.tier == Tier::Auto) {  // allocate_tiers gives it its tier first
      Pending& q = L.pending.emplace_back();
      q.a = e, q.b = static_cast<int>(o), q.b_fixed = true, q.exact = tier, q.t_in = h.fraction, q.t_out = h.exit_fraction;
      q.ia = static_cast<uint32_t>(i), q.ib = static_cast<uint32_t>(o), q.closing = closing_travel(sw, fc, fc);
      q.rank_a = sw.tags.rank, q.rank_b = fixed_rank_.ranks()[o], q.required = sw.tags.required;
      return;
    } else if (!narrow(w, e, static_cast<int>(o), true, tier, h.fraction, h.exit_fraction, k, L)) {
      return;
    }
    L.touching.push_back(key);
    L.candidates.push_back(k);
  };
  // The objects near: kept from an earlier tick while the swept box stays in their box (near_).
  FixedNear& nb = near_[e];
  if (!(nb.lo[0] <= b.lo[0] && nb.lo[1] <= b.lo[1] && nb.hi[0] >= b.hi[0] && nb.hi[1] >= b.hi[1])) {
    const float m = kNearMarginM + 0.5f * std::max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1]);
    nb.lo[0] = b.lo[0] - m, nb.lo[1] = b.lo[1] - m, nb.hi[0] = b.hi[0] + m, nb.hi[1] = b.hi[1] + m;
    nb.n = 0;
    w.grid.query_listed(nb.lo[0], nb.lo[1], nb.hi[0], nb.hi[1], [&](uint32_t k, const world::GridItem&) {
      if (nb.n < kNearListed) nb.listed[nb.n] = k;
      ++nb.n;
    });
  }
  if (nb.n > static_cast<uint32_t>(kNearListed)) {  // many near: the grid's query of the swept box
    w.grid.query(b.lo[0], b.lo[1], b.hi[0], b.hi[1], test);
    return;
  }
  for (uint32_t t = 0; t < nb.n; ++t) {
    const world::GridItem& it = w.grid.listing(nb.listed[t]);
    if (world::FixedGrid::overlaps(it, b.lo[0], b.lo[1], b.hi[0], b.hi[1])) test(static_cast<int>(it.id), it.r);
  }
}

void Detector::detect_continuous(const world::World& w) {
  prepare_shapes(w);
  rank_ids(w);
  const auto& ents = w.ents;
  const int n = static_cast<int>(ents.size());
  const double dt = opt_.dt_s;
  // Active entities, their sweeps and swept boxes. Reject non-finite input before any use.
  turn_.resize(n);
  memo().resize(n);
  // (Every slot written, the count advanced only for an active one: no push_back's size stored
  // per entity, no branch but for the rare inactive one.)
  order_.resize(n);
  size_t m = 0;
  for (int e = 0; e < n; ++e) {
    const bool on = ents.active[e] != 0;
    order_[m] = static_cast<uint32_t>(e);
    m += on;
    if (!on) turn_[e].ok = 0;
  }
  order_.resize(m);
  if (static_cast<uint64_t>(n) >> SweptTags::kRankBits)
    throw std::length_error("collision: more than " + std::to_string((1u << SweptTags::kRankBits) - 1) + " entities");
  swept_.resize(m), boxes_.resize(m), travel_.resize(m);

  // Fixed objects: the world's grid (world/fixed_grid.hpp) lists each by its reach; each is
  // tested here by its sphere (or its models' bound, when a tier above the sphere may be asked),
  // centred where it stood when indexed (x, y do not change; craters only re-seat z). Taken
  // again, with the objects kept near each entity dropped, for every new build of the grid.
  if (fixed_generation_ != w.grid.generation()) {
    near_.clear();
    fixed_x_.resize(w.fixed.size()), fixed_y_.resize(w.fixed.size()), fixed_r_.resize(w.fixed.size());
    for (size_t o = 0; o < w.fixed.size(); ++o) {
      const Vec3 c = world::fixed_centre(w, o);
      fixed_x_[o] = static_cast<float>(c.x()), fixed_y_[o] = static_cast<float>(c.y());
      const world::Kind& k = w.kinds[w.fixed.kind[o]];
      const Tier top = opt_.tier != Tier::Auto ? opt_.tier : top_tier(k);
      fixed_r_[o] = static_cast<float>(world::fixed_radius(w, o));
      if (top != Tier::Sphere) {
        prepare_shapes(w);
        for (int mi : k.models) fixed_r_[o] = std::max(fixed_r_[o], static_cast<float>(shapes_[mi].bound_radius * 1.0001 + 1e-3));
      }
    }
    fixed_generation_ = w.grid.generation();
  }
  near_.resize(n);
  // One pass over the entities, in ranges on the pool: each entity's sweep and swept box, then
  // its fixed-object tests into its range's lane (check_finite first: the pool rethrows the
  // lowest range's error, so the first bad entity in index order is named, as on one thread).
  // (flatten: check_finite, centre_end and fixed_contacts with its grid query inline into this loop.)
  // fn(chunk, begin, end) over [0, count) in ranges, each into lane `chunk`, merged in order.
  auto in_lanes = [&](size_t count, size_t grain, int per_thread, auto&& fn) {
    lane(jobs_ ? std::max(jobs_->threads(), jobs_->chunks(count, grain, per_thread)) - 1 : 0);
    merge_lanes(core::run_chunks(jobs_, count, grain, fn, per_thread));
  };
  auto t = std::chrono::steady_clock::now();
  auto lap = [&t](double& into) {
    into = core::ms_since(t);
    t = std::chrono::steady_clock::now();
  };
  const auto& ranks = rank_.ranks();
  in_lanes(m, kEntityGrain, kEntityChunksPerThread, [&](int c, size_t i0, size_t i1) __attribute__((flatten)) {
    for (size_t i = i0; i < i1; ++i) {
      if (i + kEntityAhead < i1) {  // lines the other thread read last tick, to be written
        core::prefetch_write(&swept_[i + kEntityAhead]), core::prefetch_write(&boxes_[i + kEntityAhead]);
      }
      const int e = static_cast<int>(order_[i]);
      check_finite(ents, e);
      Swept& sw = swept_[i];
      Turn& tu = turn_[e];
      // Turning: the start orientation is the last tick's end (same kind, active then), read
      // before centre_end makes prev this tick's end. (Each written only when its bits change: a
      // vehicle parked, or going straight on the level, stores nothing here, and its line is not
      // written back.)
      const Hpr now{ents.heading_deg[e], ents.pitch_deg[e], ents.roll_deg[e]};
      const Hpr& start = tu.ok && tu.kind == ents.kind[e] ? tu.prev : now;
      if (!same_bits(tu.start.data(), start.data())) tu.start = start;
      if (tu.kind != ents.kind[e]) tu.kind = ents.kind[e];
      if (!tu.ok) tu.ok = 1;
      sw.c1 = centre_end(w, e, tu);
      sw.c0 = sw.c1 - ents.vel[e] * dt;
      if (!finite(sw.c0))
        throw std::invalid_argument("collision: entity '" + ents.id[e] + "': velocity * dt overflows");
      sw.r_sphere = static_cast<float>(world::entity_radius(w, e));
      sw.e = static_cast<uint32_t>(e);
      const world::Kind& kd = w.kinds[ents.kind[e]];
      const Tier top = opt_.tier != Tier::Auto ? opt_.tier : top_tier(kd);
      sw.tags = SweptTags::make(ranks[e], top, kd.mobility == world::Mobility::Munition, ents.driven[e] || ents.snapshots[e],
                                ents.owner[e] >= 0);
      const Shape& s = shapes_[kd.models[ents.state[e]]];
      sw.r_bound = top == Tier::Sphere ? sw.r_sphere : std::max(sw.r_sphere, static_cast<float>(s.bound_radius * 1.0001 + 1e-3));
      // The model's centre turns about its origin: it strays from the straight sweep by at most
      // turn * |centre| (the turn bounded by the sum of the three angles' changes).
      if (top != Tier::Sphere && tu.start != now) {
        double turn = 0;
        for (int k = 0; k < 3; ++k) {
          const double a = double(now[k]) - tu.start[k];
          turn += std::abs(wrap180(a));
        }
        sw.r_bound += static_cast<float>(turn * kPi / 180 * s.sphere_centre.norm());
      }
      boxes_[i] = swept_box(sw.c0, sw.c1, sw.r_bound);
      travel_[i] = {static_cast<float>(sw.c1.x() - sw.c0.x()), static_cast<float>(sw.c1.y() - sw.c0.y())};
      fixed_contacts(w, i, lanes_[c]);
    }
  });
  lap(times_.entities);

  // Moving pairs: the fat boxes kept from the last tick (pair_cache.hpp; entities keep their
  // index), then the analytic sweep, then the tiers.
  moving_.pairs(boxes_, order_, ents.size(), pairs_, jobs_, &travel_);
  lap(times_.broad);
  in_lanes(pairs_.size(), kPairGrain, kPairChunksPerThread,
           [&](int c, size_t p0, size_t p1) { pair_contacts(w, p0, p1, lanes_[c]); });
  lap(times_.pairs);

  // Auto tier: the pairs that need a narrow phase get their tier from the scene and the budget
  // (scene_tiers.cpp), then are decided.
  choices_.clear();
  if (!pending_.empty()) {
    allocate_tiers(w);
    in_lanes(pending_.size(), kPendingGrain, kPendingChunksPerThread, [&](int c, size_t p0, size_t p1) {
      for (size_t p = p0; p < p1; ++p) {
        if (p + kPendingAhead < p1) {  // its bodies' sweeps, last read in the pair loop long before
          const Pending& q = pending_[p + kPendingAhead];
          core::prefetch(&swept_[q.ia]);
          if (!q.b_fixed) core::prefetch(&swept_[q.ib]);
        }
        decide_pending(w, p, lanes_[c]);
      }
    });
    pending_.clear();
  }
  lap(times_.tiers);

  // Deterministic order: time of impact, then the id ranks (not the storage order).
  const auto& rank = rank_.ranks();
  const auto& fixed_rank = fixed_rank_.ranks();
  std::sort(candidates_.begin(), candidates_.end(), [&](const Contact& x, const Contact& y) {
    if (x.fraction != y.fraction) return x.fraction < y.fraction;
    if (rank[x.a] != rank[y.a]) return rank[x.a] < rank[y.a];
    if (x.b_fixed != y.b_fixed) return x.b_fixed < y.b_fixed;
    return x.b_fixed ? fixed_rank[x.b] < fixed_rank[y.b] : rank[x.b] < rank[y.b];
  });
}

}  // namespace npsnet::collision
