// The continuous method (collision.hpp): swept spheres in the broad phase, analytic time of
// impact, shape tiers up to what the pair needs, border objects from every gridsquare.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "collision/collision.hpp"
#include "core/prefetch.hpp"
#include "world/pose.hpp"

namespace npsnet::collision {
namespace {

// Rejects an entity whose position, velocity or orientation is NaN or infinite.
void check_finite(const world::Entities& ents, int e) {
  if (!finite(ents.pos[e]) || !finite(ents.vel[e]) || !std::isfinite(ents.heading_deg[e]) ||
      !std::isfinite(ents.pitch_deg[e]) || !std::isfinite(ents.roll_deg[e]))
    throw std::invalid_argument("collision: entity '" + ents.id[e] +
                                "': position, velocity or orientation is not finite (NaN or infinite)");
}

const char* method_of(Tier t, bool fixed) {
  switch (t) {
    case Tier::Box: return fixed ? "continuous-box-fixed" : "continuous-box";
    case Tier::Hull: return fixed ? "continuous-hull-fixed" : "continuous-hull";
    case Tier::Mesh: return fixed ? "continuous-mesh-fixed" : "continuous-mesh";
    default: return fixed ? "continuous-sphere-fixed" : "continuous-sphere";
  }
}

// A moving body's radius in its pair's sweep: its sphere's at the sphere tier, else its bound's
// (a tier above may be asked).
double swept_radius(Tier tier, double r_sphere, double r_bound) { return tier == Tier::Sphere ? r_sphere : r_bound; }

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

Motion Detector::motion(const world::World& w, int e) const {
  const auto& ents = w.ents;
  Motion m;
  m.end.rot = world::pose_rotation(ents.heading_deg[e], ents.pitch_deg[e], ents.roll_deg[e]);
  m.end.pos = ents.pos[e];
  m.move = ents.vel[e] * opt_.dt_s;  // displacement over the tick
  const Hpr& s = start_hpr_[e];
  m.rot0 = s == Hpr{ents.heading_deg[e], ents.pitch_deg[e], ents.roll_deg[e]} ? m.end.rot
                                                                                : world::pose_rotation(s[0], s[1], s[2]);
  return m;
}

bool Detector::narrow(const world::World& w, int a, int b, bool b_fixed, Tier tier, double t_in, double t_out,
                      Contact& k, Lane& L) {
  const auto& ents = w.ents;
  const Shape& sa = shapes_[w.kinds[ents.kind[a]].models[ents.state[a]]];
  const Motion ma = motion(w, a);
  Motion mb;
  const Shape* sbp;
  if (b_fixed) {
    sbp = &shapes_[w.kinds[w.fixed.kind[b]].models[w.fixed.state[b]]];
    mb.end.rot = mb.rot0 = world::pose_rotation(w.fixed.heading_deg[b], 0, 0);
    mb.end.pos = w.fixed.pos[b];
  } else {
    sbp = &shapes_[w.kinds[ents.kind[b]].models[ents.state[b]]];
    mb = motion(w, b);
  }
  const Shape& sb = *sbp;
  const Vec3 &va = ma.move, &vb = mb.move;
  auto poses = [&](double t, Pose& pa, Pose& pb) { pa = ma.pose_at(t), pb = mb.pose_at(t); };
  const double rel = (va - vb).norm();
  // Neither turns: the straight search (cast_shapes); else the angular bound (cast_turning).
  const bool turning = ma.rot0 != ma.end.rot || mb.rot0 != mb.end.rot;
  const Trace toi = turning ? cast_turning(sa, ma, sb, mb, tier, t_in, t_out, L.scratch, L.stats.tier_decided)
                            : cast_shapes(sa, ma.end, va, sb, mb.end, vb, tier, t_in, t_out, L.scratch,
                                          L.stats.tier_decided);
  if (!toi.hit) return false;
  const double hi = toi.fraction;
  Pose pa, pb;
  poses(hi, pa, pb);
  const Vec3 ca = pa.rot * sa.sphere_centre + pa.pos, cb = pb.rot * sb.sphere_centre + pb.pos;
  const Vec3 d = cb - ca;
  k.normal = d.norm() > 1e-9 ? Vec3(d.normalized()) : (rel > 0 ? Vec3((vb - va).normalized()) : Vec3::UnitX());
  Vec3 p;
  // On the meeting triangles' intersection: at hi, or a few millimetres of travel later when
  // the surfaces only touch there.
  bool met = false;
  // (travel: the fastest a point of either body moves, the turn's included)
  const double travel = turning ? rel + sa.pivot_radius * ma.angle() + sb.pivot_radius * mb.angle() : rel;
  for (int i = 0; i < 8 && !met; ++i) {
    const double t = std::min(1.0, hi + i * 0.002 / std::max(travel, 1e-9));
    Pose qa, qb;
    poses(t, qa, qb);
    met = mesh_overlap(sa, qa, sb, qb, L.scratch, &p);
  }
  if (met) {
    k.point = p;
  } else {
    // Box or hull contact without the surfaces meeting: the ray from each centre to the other
    // (thesis L3's first ray, Haines on the polygon), midway between the two surface points.
    const Trace hb = ray_model(w.models[w.kinds[b_fixed ? w.fixed.kind[b] : ents.kind[b]]
                                             .models[b_fixed ? w.fixed.state[b] : ents.state[b]]],
                                pb.rot.transpose() * (ca - pb.pos), pb.rot.transpose() * k.normal, 0, d.norm());
    const Trace ha = ray_model(w.models[w.kinds[ents.kind[a]].models[ents.state[a]]],
                                pa.rot.transpose() * (cb - pa.pos), -(pa.rot.transpose() * k.normal), 0, d.norm());
    const Vec3 qa = ha.hit ? Vec3(pa.rot * ha.point + pa.pos) : ca;
    const Vec3 qb = hb.hit ? Vec3(pb.rot * hb.point + pb.pos) : cb;
    k.point = 0.5 * (qa + qb);
  }
  k.hit = true;
  k.fraction = hi;
  k.started_inside = toi.started_inside;
  k.method = method_of(tier, b_fixed);
  k.tier = tier_name(tier);
  return true;
}

Trace Detector::pair_sweep(const world::World& w, int a, int b, const Vec3& c0a, const Vec3& c1a, double rsa, double rba,
                           const Vec3& c0b, const Vec3& c1b, double rsb, double rbb, Tier& tier, Lane& L,
                           bool hit_only) const {
  const auto& ents = w.ents;
  tier = w.is_munition(a) || w.is_munition(b) ? Tier::Sphere
         : opt_.tier != Tier::Auto            ? opt_.tier
                                               : std::min(top_tier(w.kinds[ents.kind[a]]), top_tier(w.kinds[ents.kind[b]]));
  ++L.stats.sweep_pairs;
  const Trace h = sphere_sweep(c0a, c1a, swept_radius(tier, rsa, rba), c0b, c1b, swept_radius(tier, rsb, rbb), hit_only);
  if (!h.hit) ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];
  else ++L.stats.sweep_hits;
  return h;
}

bool Detector::pair_hit(const world::World& w, int a, int b, const Trace& h, Tier tier, Contact& k, Lane& L,
                        Pending* defer) {
  const auto& ents = w.ents;
  k.a = a, k.b = b, k.b_fixed = false, k.dt_s = opt_.dt_s;
  if (tier == Tier::Sphere) {
    ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];
    static_cast<Trace&>(k) = h;
    k.method = w.is_munition(a) || w.is_munition(b) ? "continuous-munition" : method_of(Tier::Sphere, false);
    k.tier = tier_name(Tier::Sphere);
    return true;
  }
  if (defer) {  // auto tier: allocate_tiers gives it its tier first
    defer->k = k, defer->exact = tier, defer->t_in = h.fraction, defer->t_out = h.exit_fraction;
    defer->closing = (ents.vel[a] - ents.vel[b]).norm();
    return false;
  }
  return narrow(w, a, b, false, tier, h.fraction, h.exit_fraction, k, L);
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
  if (start_hpr_.size() < ents.size()) start_hpr_.resize(ents.size());
  for (int e : {a, b}) start_hpr_[e] = Hpr{ents.heading_deg[e], ents.pitch_deg[e], ents.roll_deg[e]};  // no turn known
  Vec3 c0[2], c1[2];
  double rs[2], rb[2];
  for (int s = 0; s < 2; ++s) {
    const int e = s ? b : a;
    c1[s] = world::entity_centre(w, e);
    c0[s] = c1[s] - ents.vel[e] * opt_.dt_s;
    rs[s] = world::entity_radius(w, e);
    const Tier top = opt_.tier != Tier::Auto ? opt_.tier : top_tier(w.kinds[ents.kind[e]]);
    const Shape& sh = shapes_[w.kinds[ents.kind[e]].models[ents.state[e]]];
    rb[s] = top == Tier::Sphere ? rs[s] : std::max(rs[s], sh.bound_radius * 1.0001 + 1e-3);
  }
  Lane& L = lane(0);
  Tier tier;
  const Trace h = pair_sweep(w, a, b, c0[0], c1[0], rs[0], rb[0], c0[1], c1[1], rs[1], rb[1], tier, L);
  const bool hit = h.hit && pair_hit(w, a, b, h, tier, k, L);
  merge_lanes(1);
  return hit;
}

Vec3 Detector::centre_end(const world::World& w, int e) {
  const auto& ents = w.ents;
  const world::Kind& k = w.kinds[ents.kind[e]];
  return ents.pos[e] + world::pose_rotation(memo().dir(static_cast<size_t>(e), ents.heading_deg[e]), ents.pitch_deg[e], ents.roll_deg[e]) *
                           k.centre_by_state[ents.state[e]].cast<double>();
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
// The pairs lie in no spatial order: what a pair reads of its two bodies is asked of the cache
// kPairAhead pairs early (prefetch_pair), so their misses overlap instead of stalling in turn:
// its entity indices twice as far ahead, the episode keys half as far (each stage reads what
// the one before asked for).
constexpr size_t kPairAhead = 8;
}  // namespace

void Detector::fixed_contacts(const world::World& w, size_t i, Lane& L) {
  const auto& ents = w.ents;
  const double dt = opt_.dt_s;
  const int e = static_cast<int>(order_[i]);
  const world::Kind& ke = w.kinds[ents.kind[e]];
  const Box& b = boxes_[i];
  auto test = [&](int o, float) {
    const float x = fixed_x_[o], y = fixed_y_[o], r = fixed_r_[o];
    if (x + r < b.lo[0] || x - r > b.hi[0] || y + r < b.lo[1] || y - r > b.hi[1]) return;
    ++L.stats.fixed_tests;
    const world::Kind& ko = w.kinds[w.fixed.kind[o]];
    const Tier tier = opt_.tier != Tier::Auto ? opt_.tier : std::min(top_tier(ke), top_tier(ko));
    const Vec3 fc = world::fixed_centre(w, o);  // live: craters re-seat objects
    const double rs = world::fixed_radius(w, o);
    const bool sphere = tier == Tier::Sphere || w.is_munition(e);
    const Trace h = sphere_sweep(c0_[i], c1_[i], sphere ? r_sphere_[i] : r_bound_[i], fc, fc,
                                 sphere ? rs : std::max<double>(rs, r));
    ++L.stats.sweep_pairs;
    if (!h.hit) {
      ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];
      return;
    }
    ++L.stats.sweep_hits;
    const uint64_t key = contact_key(e, static_cast<int>(o), true);
    const bool continuing = std::binary_search(previous_.begin(), previous_.end(), key);
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
      k.method = method_of(Tier::Sphere, true);
      k.tier = tier_name(Tier::Sphere);
    } else if (opt_.tier == Tier::Auto) {  // allocate_tiers gives it its tier first
      Pending& q = L.pending.emplace_back();
      q.k = k, q.exact = tier, q.t_in = h.fraction, q.t_out = h.exit_fraction;
      q.ia = static_cast<uint32_t>(i), q.ib = static_cast<uint32_t>(o), q.closing = ents.vel[e].norm();
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

void Detector::prefetch_pair(const world::World& w, size_t p, int stage) const {
  const auto [i, j] = pairs_[p];
  if (stage == 0) {
    core::prefetch(&order_[i]), core::prefetch(&order_[j]);
    return;
  }
  const uint32_t lo = std::min(order_[i], order_[j]);
  if (stage == 2) {
    if (!lo_start_.empty() && lo_start_[lo] < previous_.size()) core::prefetch(&previous_[lo_start_[lo]]);
    return;
  }
  for (const uint32_t s : {i, j}) {
    core::prefetch_object(&c0_[s]), core::prefetch_object(&c1_[s]);  // a Vec3 may span two lines
    core::prefetch(&r_sphere_[s]), core::prefetch(&r_bound_[s]);
    const uint32_t e = order_[s];
    core::prefetch(&w.ents.owner[e]), core::prefetch(&w.ents.kind[e]), core::prefetch(&rank_.ranks()[e]);
    core::prefetch_object(&w.ents.vel[e]);  // a pair left to allocate_tiers: its closing speed
  }
  if (!lo_start_.empty()) core::prefetch(&lo_start_[lo]);
}

void Detector::pair_contact(const world::World& w, size_t p, Lane& L) {
  const auto& ents = w.ents;
  const auto [i, j] = pairs_[p];
  int a = static_cast<int>(order_[i]), b = static_cast<int>(order_[j]);
  size_t ia = i, ib = j;
  if (ents.owner[a] == b || ents.owner[b] == a) return;  // a round never meets its shooter
  if (w.is_munition(a) && w.is_munition(b)) return;
  // Canonical order by id rank, so that the answer does not depend on where entities are stored.
  if (rank_.ranks()[b] < rank_.ranks()[a]) std::swap(a, b), std::swap(ia, ib);
  Tier tier;
  if (!pair_sweep(w, a, b, c0_[ia], c1_[ia], r_sphere_[ia], r_bound_[ia], c0_[ib], c1_[ib], r_sphere_[ib], r_bound_[ib],
                  tier, L, true)
           .hit)
    return;
  // A running episode goes on while the bounds meet (its key) but reports nothing: detect() would
  // drop its contact, so none is made (in a crowd of overlapping vehicles, most of the pairs).
  if (was_touching(a, b)) {
    ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];  // decided by its bounds: the sphere tier
    L.touching.push_back(contact_key(a, b, false));
    return;
  }
  const Trace h = sphere_sweep(c0_[ia], c1_[ia], swept_radius(tier, r_sphere_[ia], r_bound_[ia]), c0_[ib], c1_[ib],
                               swept_radius(tier, r_sphere_[ib], r_bound_[ib]));  // the whole trace
  Contact k;
  Pending q;
  q.k.a = -1;
  if (!pair_hit(w, a, b, h, tier, k, L, opt_.tier == Tier::Auto ? &q : nullptr)) {
    if (q.k.a >= 0) {  // deferred to allocate_tiers
      q.ia = static_cast<uint32_t>(ia), q.ib = static_cast<uint32_t>(ib);
      L.pending.push_back(q);
    }
    return;
  }
  L.touching.push_back(contact_key(a, b, false));
  L.candidates.push_back(k);
}

void Detector::decide_pending(const world::World& w, size_t p, Lane& L) {
  const Pending& q = pending_[p];
  Contact k = q.k;
  if (q.tier == Tier::Sphere) {  // the thesis spheres swept: what the sphere tier finds
    const int b = k.b;
    const Vec3 cb0 = k.b_fixed ? world::fixed_centre(w, b) : c0_[q.ib];
    const Vec3 cb1 = k.b_fixed ? cb0 : c1_[q.ib];
    const double rb = k.b_fixed ? world::fixed_radius(w, b) : r_sphere_[q.ib];
    const Trace h = sphere_sweep(c0_[q.ia], c1_[q.ia], r_sphere_[q.ia], cb0, cb1, rb);
    ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];
    if (!h.hit) return;
    static_cast<Trace&>(k) = h;
    k.method = method_of(Tier::Sphere, k.b_fixed);
    k.tier = tier_name(Tier::Sphere);
  } else if (!narrow(w, k.a, k.b, k.b_fixed, q.tier, q.t_in, q.t_out, k, L)) {
    return;
  }
  L.touching.push_back(contact_key(k.a, k.b, k.b_fixed));
  L.candidates.push_back(k);
}

void Detector::detect_continuous(const world::World& w) {
  prepare_shapes(w);
  rank_ids(w);
  const auto& ents = w.ents;
  const int n = static_cast<int>(ents.size());
  const double dt = opt_.dt_s;
  // Active entities, their sweeps and swept boxes. Reject non-finite input before any use.
  order_.clear();
  start_hpr_.resize(n), prev_hpr_.resize(n), prev_kind_.resize(n, -1), prev_ok_.resize(n, 0);
  memo().resize(n);
  for (int e = 0; e < n; ++e) {
    if (!ents.active[e]) {
      prev_ok_[e] = 0;
      continue;
    }
    order_.push_back(static_cast<uint32_t>(e));
  }
  const size_t m = order_.size();
  c0_.resize(m), c1_.resize(m), r_sphere_.resize(m), r_bound_.resize(m), boxes_.resize(m);

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
  in_lanes(m, kEntityGrain, kEntityChunksPerThread, [&](int c, size_t i0, size_t i1) __attribute__((flatten)) {
    for (size_t i = i0; i < i1; ++i) {
      const int e = static_cast<int>(order_[i]);
      check_finite(ents, e);
      c1_[i] = centre_end(w, e);
      c0_[i] = c1_[i] - ents.vel[e] * dt;
      if (!finite(c0_[i]))
        throw std::invalid_argument("collision: entity '" + ents.id[e] + "': velocity * dt overflows");
      r_sphere_[i] = static_cast<float>(world::entity_radius(w, e));
      const Tier top = opt_.tier != Tier::Auto ? opt_.tier : top_tier(w.kinds[ents.kind[e]]);
      const Shape& s = shapes_[w.kinds[ents.kind[e]].models[ents.state[e]]];
      r_bound_[i] = top == Tier::Sphere ? r_sphere_[i] : std::max(r_sphere_[i], static_cast<float>(s.bound_radius * 1.0001 + 1e-3));
      // Turning: the start orientation is the last tick's end (same kind, active then).
      const Hpr now{ents.heading_deg[e], ents.pitch_deg[e], ents.roll_deg[e]};
      start_hpr_[e] = prev_ok_[e] && prev_kind_[e] == ents.kind[e] ? prev_hpr_[e] : now;
      prev_hpr_[e] = now, prev_kind_[e] = ents.kind[e], prev_ok_[e] = 1;
      // The model's centre turns about its origin: it strays from the straight sweep by at most
      // turn * |centre| (the turn bounded by the sum of the three angles' changes).
      if (top != Tier::Sphere && start_hpr_[e] != now) {
        double turn = 0;
        for (int k = 0; k < 3; ++k) {
          const double a = double(now[k]) - start_hpr_[e][k];  // within a half turn remainder gives a itself
          turn += std::abs(std::abs(a) < 180 ? a : std::remainder(a, 360.0));
        }
        r_bound_[i] += static_cast<float>(turn * kPi / 180 * s.sphere_centre.norm());
      }
      boxes_[i] = swept_box(c0_[i], c1_[i], r_bound_[i]);
      fixed_contacts(w, i, lanes_[c]);
    }
  });

  // Moving pairs: the fat boxes kept from the last tick (pair_cache.hpp; entities keep their
  // index), then the analytic sweep, then the tiers.
  moving_.pairs(boxes_, order_, ents.size(), pairs_, jobs_);
  in_lanes(pairs_.size(), kPairGrain, kPairChunksPerThread, [&](int c, size_t p0, size_t p1) {
    for (size_t p = p0; p < p1; ++p) {
      if (p + 2 * kPairAhead < p1) prefetch_pair(w, p + 2 * kPairAhead, 0);
      if (p + kPairAhead < p1) prefetch_pair(w, p + kPairAhead, 1);
      if (p + kPairAhead / 2 < p1) prefetch_pair(w, p + kPairAhead / 2, 2);
      pair_contact(w, p, lanes_[c]);
    }
  });

  // Auto tier: the pairs that need a narrow phase get their tier from the scene and the budget
  // (scene_tiers.cpp), then are decided.
  choices_.clear();
  if (!pending_.empty()) {
    allocate_tiers(w);
    in_lanes(pending_.size(), kPendingGrain, kPendingChunksPerThread, [&](int c, size_t p0, size_t p1) {
      for (size_t p = p0; p < p1; ++p) decide_pending(w, p, lanes_[c]);
    });
    pending_.clear();
  }

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
