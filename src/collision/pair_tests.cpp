// The continuous method's tests of one moving pair (collision.hpp; continuous.cpp's passes run
// them): its sweep and contact, a pending pair decided at its tier, and the narrow phase of the
// shapes' tiers (for fixed objects too).
#include <algorithm>
#include <cmath>

#include "collision/collision.hpp"
#include "core/prefetch.hpp"
#include "world/pose.hpp"

namespace npsnet::collision {
namespace {

// The pairs lie in no spatial order: what a pair reads of its two bodies is asked of the cache
// kPairAhead pairs early (prefetch_pair), so their misses overlap instead of stalling in turn:
// its bodies' Swept lines twice as far ahead, lo_start_ kPairAhead, the episode keys half as
// far (each stage reads what the one before asked for).
constexpr size_t kPairAhead = 8;

// A moving body's radius in its pair's sweep: its sphere's at the sphere tier, else its bound's
// (a tier above may be asked).
double swept_radius(Tier tier, double r_sphere, double r_bound) { return tier == Tier::Sphere ? r_sphere : r_bound; }

}  // namespace

Motion Detector::motion(const world::World& w, int e) const {
  const auto& ents = w.ents;
  Motion m;
  m.end.rot = world::pose_rotation(ents.heading_deg[e], ents.pitch_deg[e], ents.roll_deg[e]);
  m.end.pos = ents.pos[e];
  m.move = ents.vel[e] * opt_.dt_s;  // displacement over the tick
  const Hpr& s = turn_[e].start;
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
  k.method = continuous_method_name(tier, b_fixed);
  k.tier = tier_name(tier);
  return true;
}

Trace Detector::pair_sweep(Tier tier, const Vec3& c0a, const Vec3& c1a, double rsa, double rba, const Vec3& c0b,
                           const Vec3& c1b, double rsb, double rbb, Lane& L, bool hit_only) {
  ++L.stats.sweep_pairs;
  const Trace h = sphere_sweep_checked(c0a, c1a, swept_radius(tier, rsa, rba), c0b, c1b, swept_radius(tier, rsb, rbb), hit_only);
  if (!h.hit) ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];
  else ++L.stats.sweep_hits;
  return h;
}

bool Detector::pair_hit(const world::World& w, int a, int b, const Trace& h, Tier tier, Contact& k, Lane& L,
                        Pending* defer) {
  k.a = a, k.b = b, k.b_fixed = false, k.dt_s = opt_.dt_s;
  if (tier == Tier::Sphere) {
    ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];
    static_cast<Trace&>(k) = h;
    k.method = w.is_munition(a) || w.is_munition(b) ? "continuous-munition" : continuous_method_name(Tier::Sphere, false);
    k.tier = tier_name(Tier::Sphere);
    return true;
  }
  if (defer) {  // auto tier: allocate_tiers gives it its tier first
    defer->a = a, defer->b = b, defer->b_fixed = false;
    defer->exact = tier, defer->t_in = h.fraction, defer->t_out = h.exit_fraction;
    return false;
  }
  return narrow(w, a, b, false, tier, h.fraction, h.exit_fraction, k, L);
}

void Detector::prefetch_pair(size_t p, int stage) const {
  const auto [i, j] = pairs_[p];
  if (stage == 0) {
    core::prefetch(&swept_[i]), core::prefetch(&swept_[j]);
    return;
  }
  const uint32_t ea = swept_[i].e, eb = swept_[j].e;
  const size_t lo = episode_bucket(std::min(ea, eb));
  if (stage == 1) {
    if (!lo_start_.empty()) core::prefetch(&lo_start_[lo]);
  } else if (!lo_start_.empty() && lo_start_[lo] < previous_.size()) {
    core::prefetch(&previous_[lo_start_[lo]]);
  }
}

void Detector::pair_contact(const world::World& w, size_t p, Lane& L) {
  const auto [i, j] = pairs_[p];
  const Swept* sa = &swept_[i];
  const Swept* sb = &swept_[j];
  int a = static_cast<int>(sa->e), b = static_cast<int>(sb->e);
  const SweptTags* ta = &sa->tags;
  const SweptTags* tb = &sb->tags;
  if ((ta->owned && w.ents.owner[a] == b) || (tb->owned && w.ents.owner[b] == a)) return;  // a round never meets its shooter
  if (ta->munition && tb->munition) return;
  size_t ia = i, ib = j;
  // Canonical order by id rank, so that the answer does not depend on where entities are stored.
  if (tb->rank < ta->rank) std::swap(a, b), std::swap(ia, ib), std::swap(sa, sb), std::swap(ta, tb);
  // A running episode goes on while the bounds meet (its key) but reports nothing: detect() would
  // drop its contact, so none is made and its sweep asks only whether they meet (in a crowd of
  // overlapping vehicles, most of the pairs).
  const bool continuing = was_touching(a, b);
  const Tier tier = pair_tier(*ta, *tb);
  const Trace h = pair_sweep(tier, sa->c0, sa->c1, sa->r_sphere, sa->r_bound, sb->c0, sb->c1, sb->r_sphere,
                             sb->r_bound, L, continuing);
  if (!h.hit) return;
  if (continuing) {
    ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];  // decided by its bounds: the sphere tier
    L.touching.push_back(contact_key(a, b, false));
    return;
  }
  Contact k;
  Pending q;
  q.a = -1;
  if (!pair_hit(w, a, b, h, tier, k, L, opt_.tier == Tier::Auto ? &q : nullptr)) {
    if (q.a >= 0) {  // deferred to allocate_tiers
      q.ia = static_cast<uint32_t>(ia), q.ib = static_cast<uint32_t>(ib), q.closing = closing_travel(*sa, sb->c0, sb->c1);
      q.rank_a = ta->rank, q.rank_b = tb->rank, q.required = ta->required || tb->required;
      L.pending.push_back(q);
    }
    return;
  }
  L.touching.push_back(contact_key(a, b, false));
  L.candidates.push_back(k);
}

// (here, with prefetch_pair and pair_contact, so that both inline into the loop: three calls of
// prefetch_pair a pair were a third of the pair loop's samples in the 100,000-vehicle crowd)
[[gnu::flatten]] void Detector::pair_contacts(const world::World& w, size_t p0, size_t p1, Lane& L) {
  for (size_t p = p0; p < p1; ++p) {
    if (p + 2 * kPairAhead < p1) prefetch_pair(p + 2 * kPairAhead, 0);
    if (p + kPairAhead < p1) prefetch_pair(p + kPairAhead, 1);
    if (p + kPairAhead / 2 < p1) prefetch_pair(p + kPairAhead / 2, 2);
    pair_contact(w, p, L);
  }
}

void Detector::decide_pending(const world::World& w, size_t p, Lane& L) {
  const Pending& q = pending_[p];
  Contact k;
  k.a = q.a, k.b = q.b, k.b_fixed = q.b_fixed, k.dt_s = opt_.dt_s;
  if (q.tier == Tier::Sphere) {  // the thesis spheres swept: what the sphere tier finds
    const int b = k.b;
    const Swept& sa = swept_[q.ia];
    const Vec3 cb0 = k.b_fixed ? world::fixed_centre(w, b) : swept_[q.ib].c0;
    const Vec3 cb1 = k.b_fixed ? cb0 : swept_[q.ib].c1;
    const double rb = k.b_fixed ? world::fixed_radius(w, b) : swept_[q.ib].r_sphere;
    const Trace h = sphere_sweep_checked(sa.c0, sa.c1, sa.r_sphere, cb0, cb1, rb);
    ++L.stats.tier_decided[static_cast<int>(Tier::Sphere)];
    if (!h.hit) return;
    static_cast<Trace&>(k) = h;
    k.method = continuous_method_name(Tier::Sphere, k.b_fixed);
    k.tier = tier_name(Tier::Sphere);
  } else if (!narrow(w, k.a, k.b, k.b_fixed, q.tier, q.t_in, q.t_out, k, L)) {
    return;
  }
  L.touching.push_back(contact_key(k.a, k.b, k.b_fixed));
  L.candidates.push_back(k);
}

}  // namespace npsnet::collision
