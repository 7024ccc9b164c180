// Collision detection and response. Two methods, chosen per scenario (collision_method):
//
// "thesis" (Osborne 1991, ch. III.C-D), the reference:
//  fixed objects: only below the threshold height, from the entity's gridsquare list, bounding
//    spheres (p. 9-10);
//  moving objects: L1 |dx| and |dy| both within 100 m (p. 11), L2 centre distance < sum of
//    radii, L3 two rays + Haines' crossings test (p. 15-19, Figure 6): real when the other's
//    polygon on the line of centres lies inside this object's sphere, else retried next tick.
//
// "continuous" (issue 6, the node's default), which removes the thesis's chapter V limits:
//  every body sweeps its sphere from (end centre - velocity * dt) to its end centre; the broad
//    phase works on the swept boxes (fixed objects: the world's 125 m grid, world/fixed_grid.hpp,
//    listing each object in every gridsquare its reach overlaps, queried over the swept box;
//    moving: fat boxes in a hashed grid, kept from tick to tick, pair_cache.hpp; the pairs in
//    any order, since every result below is sorted);
//  the narrow phase solves the swept-sphere time of impact analytically (sweep.hpp), then goes
//    up the pair's shape tiers (sphere -> oriented box -> convex hull -> polygon mesh, shapes.hpp)
//    only while the cheaper tier cannot decide;
//  contacts are sorted by (time of impact, entity ids) and resolved together (respond()).
//  A contact episode, once begun, goes on while the pair's bounding spheres (the model's bound
//  above the sphere tier) still meet in the tick; only then may a new episode begin.
//
// Both: response as Figure 8 (p. 22) with the constants of core/constants.hpp; detect() reports
// only the first tick of each contact episode and reuses its buffers (no allocation per tick
// once warm). Positions in the local frame, metres; speeds m/s; times s unless a "fraction".
// Non-finite positions or velocities are rejected with std::invalid_argument naming the entity.
// Threading: detect and respond read a const World; a Detector (its buffers, the contact episodes
// of last tick) belongs to one thread. Given a core::Jobs (set_jobs), detect fans out to its
// workers: the per-entity sweeps (each writes its own slots), the fixed-object tests per range of
// entities, the moving broad phase's passes (pair_cache.hpp) and the narrow phase per range of
// pairs, each range into its own lane (contacts, pair keys, stats, shape scratch); the lanes are
// merged in range order, so contacts, events and stats are the same bytes for any thread count.
// The world is changed only by world::apply of respond's Changes.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "collision/broadphase.hpp"
#include "collision/id_rank.hpp"
#include "collision/pair_cache.hpp"
#include "collision/shapes.hpp"
#include "collision/sweep.hpp"
#include "collision/trace.hpp"
#include "core/constants.hpp"
#include "core/heading_memo.hpp"
#include "core/jobs.hpp"
#include "world/changes.hpp"
#include "world/world.hpp"

namespace npsnet::collision {

// A contact is the trace of a pair over the tick: fraction = time of impact in [0, 1] of the
// dt_s the sweep spanned (thesis: 1, found at the end of the tick, dt_s = 0), point (local
// frame), normal (unit, from a towards b), started_inside (touching at the start of the tick).
struct Contact : Trace {
  int a = -1, b = -1;     // entity indices; b is a fixed-object index when b_fixed
  bool b_fixed = false;
  double dt_s = 0;        // the tick the fraction refers to (s); 0 = thesis
  const char* method = "";
  const char* tier = "";  // the tier that decided it (tier_name)
};
// The key of a contact episode (moving pairs unordered; fixed contacts flagged in the top bit).
inline uint64_t contact_key(int a, int b, bool b_fixed) {
  const uint64_t lo = static_cast<uint32_t>(b_fixed ? a : std::min(a, b));
  const uint64_t hi = static_cast<uint32_t>(b_fixed ? b : std::max(a, b));
  return (b_fixed ? (1ull << 63) : 0) | (lo << 31) | hi;
}

// The names of both live in world/collision_names.hpp (the files that name them are read there).
using Method = world::CollisionMethod;
// Shape tiers, cheapest first. Auto: each pair goes up to the highest tier both kinds declare
// (top_tier) and stops at the first tier that decides it. Capsule is accepted as a name for Box.
using Tier = world::ShapeTier;
Method parse_method(const std::string& s);  // "thesis" | "continuous"; throws std::invalid_argument
Tier parse_tier(const std::string& s);      // "auto" | "sphere" | "capsule" | "box" | "hull" | "mesh"
inline const char* tier_name(Tier t) { return world::shape_tier_name(t); }
// The continuous method's name for a contact its tier t decided (the event log's `method`).
inline const char* continuous_method_name(Tier t, bool fixed) {
  switch (t) {
    case Tier::Box: return fixed ? "continuous-box-fixed" : "continuous-box";
    case Tier::Hull: return fixed ? "continuous-hull-fixed" : "continuous-hull";
    case Tier::Mesh: return fixed ? "continuous-mesh-fixed" : "continuous-mesh";
    default: return fixed ? "continuous-sphere-fixed" : "continuous-sphere";
  }
}
// The highest tier a kind declares: its `tiers` list in models/kinds.toml when it has one; else
// fixed objects and munitions are spheres (the thesis's bounding spheres, p. 9 and p. 15) and
// vehicles go up to their polygon mesh (the thesis's L3 polygons, p. 15).
Tier top_tier(const world::Kind& k);
// The collision shape of every model of the world (index = model), as the continuous method
// uses them: make_shape, or make_trunk for the states a kind gives a trunk radius.
std::vector<Shape> make_shapes(const world::World& w);

struct Options {
  Method method = Method::Continuous;
  Tier tier = Tier::Auto;
  double dt_s = thesis::kDefaultDtS;  // the tick the continuous sweep spans (s)
  double budget_ms = world::kDefaultCollisionBudgetMs;  // auto tier: modelled narrow phase per tick (ms)
};

// ---- scene-aware auto tier (issue 13) ---------------------------------------------------------
// With tier auto (continuous method), each tick the pairs whose bounding spheres meet outside a
// running episode (the pairs that need a narrow phase) are given a tier:
//  * required pairs get their exact tier (min of both kinds' top_tier): a pair with a
//    player-driven vehicle (ents.driven), a snapshotted vehicle (ents.snapshots: its collisions
//    make imminent/result snapshots), or either body's bounding sphere inside a viewer's view
//    volume (set_views);
//  * every pair gets at least the sphere tier (the thesis spheres swept), so a pair is never
//    skipped and every contact the sphere tier finds is reported; its modelled cost for all the
//    pairs is set aside from the budget (budget_ms, scenario key collision_budget_ms) first;
//  * the others, most important first (closing speed, then id order), get the highest tier up
//    to their exact one whose raise (its kTierCostUs less the sphere's) fits what is left, after
//    the required pairs' raises; else the sphere tier. The least important pairs are lowered
//    first, and the modelled cost of all fits the budget whenever the sphere tier's alone does.
// The cost model is fixed (not timed), so the choice, the events and the world are the same on
// every run and thread count. Every contact names the tier that decided it (Contact::tier).
// Modelled cost of one pair's narrow phase at each tier (us; index = Tier): the time per pair of
// bench/bench_accuracy.cpp (README, accuracy table: sphere 0.24, box 27.1, hull 49.5, mesh 164).
inline constexpr double kTierCostUs[5] = {0.0, 0.24, 27.1, 49.5, 164.0};
// A viewer's view volume in the local frame (m): p is inside when, for all six planes (n, d),
// n . (p - eye) + d >= 0 (render::ViewMath's planes, eye-relative, n unit).
struct ViewVolume {
  Vec3 eye{0, 0, 0};
  std::array<Eigen::Vector4d, 6> planes{};
  bool sphere_inside(const Vec3& c, double r) const {
    for (const auto& p : planes)
      if (p.head<3>().dot(c - eye) + p[3] < -r) return false;
    return true;
  }
  static ViewVolume box(const Vec3& lo, const Vec3& hi);  // an axis-aligned box (tests)
};
// One pair's tier choice of the last tick (tests, benchmarks). tier_choices(): most important
// first until the budget is spent, the rest (all at the sphere tier) after them in no set order.
struct TierChoice {
  int a = -1, b = -1;
  bool b_fixed = false, required = false;
  Tier exact = Tier::Sphere, chosen = Tier::Sphere;
};
Options options_from(const std::string& method, const std::string& tier, double dt_s);

struct DetectStats {
  int64_t fixed_tests = 0, l1_pairs = 0, l2_pairs = 0, l3_tests = 0, l3_rejects = 0, contacts = 0;
  // continuous: pairs decided at each tier (index = Tier), swept-sphere hits
  int64_t tier_decided[5] = {0, 0, 0, 0, 0};
  int64_t sweep_pairs = 0, sweep_hits = 0;
  int64_t tier_lowered = 0;  // auto: pairs given a tier below their exact one by the budget
};

// Where the last detect's time went (ms): its passes by the steady clock, for benchmarks and
// reports only. No decision reads them (the budget is modelled, so results never depend on timing).
struct PassTimes {
  double total = 0;     // the whole detect
  double entities = 0;  // continuous: each body's sweep, swept box and fixed objects
  double broad = 0;     // the kept broad phase (PairCache::pairs)
  double pairs = 0;     // the moving pairs' sphere sweeps and episode look-ups
  double tiers = 0;     // allocate_tiers and the narrow phases it allowed: what the budget governs
  double charged = 0;   // those narrow phases as the budget charged them (kTierCostUs; modelled)
};

class Detector {
 public:
  explicit Detector(const Options& o = Options{}) : opt_(o) {}
  // Finds the contacts that begin this tick (new episodes) and appends them to `out`, sorted
  // by (time of impact, entity ids) so that the result does not depend on entity order.
  void detect(const world::World& w, std::vector<Contact>& out);
  const DetectStats& stats() const { return stats_; }
  const PassTimes& pass_times() const { return times_; }
  const Options& options() const { return opt_; }
  // Worker threads for detect (continuous method); nullptr (the default) = this thread only.
  // The pool must outlive the detector's use of it.
  void set_jobs(core::Jobs* jobs) { jobs_ = jobs; }
  // Heading directions shared with the tick's dynamics stage (core/heading_memo.hpp: the node's
  // one memo, so a vehicle's direction is worked out once a tick, by whichever stage meets its
  // heading first); nullptr (the default) = the detector's own. Kept until changed; the caller
  // keeps it alive. The same bits either way.
  void set_heading_memo(core::HeadingMemo* memo) { shared_memo_ = memo; }
  // A new tick length (s; positive and finite, else std::invalid_argument).
  void set_dt(double dt_s);
  // Scene-aware auto tier: the budget (ms, >= 0) and the viewers' view volumes this tick.
  void set_budget_ms(double ms) { opt_.budget_ms = ms; }
  void set_views(const std::vector<ViewVolume>& v) { views_ = v; }
  // Entity e was put somewhere else between ticks (a restored checkpoint): its next tick starts
  // from the orientation it has then, not from its last tick's (no turn over the move).
  void forget_turn(int e) {
    if (e >= 0 && static_cast<size_t>(e) < turn_.size()) turn_[e].ok = 0;
  }
  const std::vector<TierChoice>& tier_choices() const { return choices_; }
  // One pair of entities by this detector's method and tier, outside the episode bookkeeping
  // (benchmarks and tests): true with the contact (continuous: the first in the tick).
  bool test_pair(const world::World& w, int a, int b, Contact& k);
  // Calls f(q) for each moving entity q that was in contact with moving entity e in the last
  // detect (a running episode). O(pairs in contact), whatever the number of entities.
  template <class F>
  void each_partner(int e, F&& f) const {
    for (uint64_t key : previous_) {
      if (key >> 63) continue;  // a fixed object
      const int lo = static_cast<int>((key >> 31) & 0xffffffffu), hi = static_cast<int>(key & 0x7fffffffu);
      if (lo == e) f(hi);
      else if (hi == e) f(lo);
    }
  }

 private:
  void detect_thesis(const world::World& w);
  void detect_continuous(const world::World& w);
  void prepare_shapes(const world::World& w);
  // rank_.ranks()[e]: entity e's place in the order of ids (fixed_rank_ for fixed objects): contacts and
  // pairs are ordered by these integers, not by storage index nor by comparing strings.
  void rank_ids(const world::World& w);
  // A pair that needs a narrow phase (auto tier): decided after allocate_tiers gave it a tier.
  struct Pending {
    int a = -1, b = -1;     // the Contact's (b a fixed object when b_fixed); dt_s = opt_.dt_s
    bool b_fixed = false;
    Tier exact = Tier::Sphere, tier = Tier::Sphere;
    double t_in = 0, t_out = 1;  // the bound spheres' first touch and exit (fractions of the tick)
    uint32_t ia = 0, ib = 0;     // sweep slots of a and b (ib: unused for a fixed object)
    uint32_t rank_a = 0, rank_b = 0;  // their id ranks (rank_b: in fixed_rank_ when b is fixed)
    double closing = 0;          // how far they close over the tick (m): closing_travel
    bool required = false;       // set when made: a driven or snapshotted body; allocate_tiers adds the seen
  };
  // One thread's share of a detection: merged into candidates_, touching_, stats_ in range order.
  struct Lane {
    std::vector<uint64_t> touching;
    std::vector<Contact> candidates;
    DetectStats stats;
    ShapeScratch scratch;
    std::vector<Pending> pending;
  };
  Lane& lane(int c);
  void merge_lanes(int k);
  // The fixed objects near swept entity i (order_[i]); the moving pair pairs_[p]; the moving
  // pairs pairs_[p0, p1) in turn, each asked of the cache ahead (prefetch_pair).
  void fixed_contacts(const world::World& w, size_t i, Lane& L);
  void pair_contact(const world::World& w, size_t p, Lane& L);
  void pair_contacts(const world::World& w, size_t p0, size_t p1, Lane& L);
  // A hint (core/prefetch.hpp): the cache lines pair_contact(p) reads, in three stages, each
  // reading what the one before asked for: 0 the two bodies' Swept lines (tags in them); 1
  // lo_start_ of the lower entity index; 2 the episode keys lo_start_ points to.
  void prefetch_pair(size_t p, int stage) const;
  void allocate_tiers(const world::World& w);  // scene_tiers.cpp
  void decide_pending(const world::World& w, size_t p, Lane& L);
  // A moving pair, first its sweep at the tier it needs (pair_tier: the sphere for a munition):
  // of its spheres, or of its bounds when a tier above the sphere may be asked (counted).
  // hit_only: sphere_sweep's hit_only (a running episode needs only whether its bounds meet).
  static Trace pair_sweep(Tier tier, const Vec3& c0a, const Vec3& c1a, double rsa, double rba, const Vec3& c0b,
                          const Vec3& c1b, double rsb, double rbb, Lane& L, bool hit_only = false);
  // Then, after the sweep h hit, for a pair not in a running episode (one that is goes on while
  // its bounds meet, and needs no more): true with the contact k by that tier. `defer`: the
  // narrow phase is left for allocate_tiers (auto tier): false, with *defer filled.
  bool pair_hit(const world::World& w, int a, int b, const Trace& h, Tier tier, Contact& k, Lane& L,
                Pending* defer = nullptr);
  // Narrow phase of one moving pair (entities a, b) beyond the sweep: true with a contact.
  // Sweeps the posed shapes from the first touch of the bounding spheres ([t_in, t_out]) up to
  // `tier`, cheapest first; true with the time, point and normal of the first contact.
  bool narrow(const world::World& w, int a, int b, bool b_fixed, Tier tier, double t_in, double t_out, Contact& k,
              Lane& L);

  Options opt_;
  std::vector<uint32_t> order_;         // active entities sorted by x (L1 sweep)
  std::vector<uint64_t> touching_, previous_;  // pair keys in contact this / last tick
  std::vector<uint64_t> sort_scratch_;         // core::radix_sort's
  // Where each entity's episodes with moving partners lie in previous_: the keys whose lower
  // index is e are among previous_[lo_start_[b] .. lo_start_[b + 1]) (in no order), b =
  // episode_bucket(e), e >> kEpisodeBucketShift (the bucket of 4 entities); the fixed contacts' keys
  // after the last bucket (sorted). Made each tick when previous_ holds kEpisodeIndexMin keys or
  // more (else empty and previous_ sorted: a binary search is as quick), so that a pair's
  // look-up reads two lines, which prefetch_pair asks for ahead. (Four entities a bucket: the
  // index a quarter of the entities, 100 KB at 100,000, made in a quarter of the passes over
  // it; a bucket in the crowd holds 2-3 keys, on one line.)
  static constexpr size_t kEpisodeIndexMin = 4096;
  static constexpr int kEpisodeBucketShift = 2;
  static size_t episode_bucket(size_t lo) { return lo >> kEpisodeBucketShift; }
  std::vector<uint32_t> lo_start_;
  void index_episodes(size_t n);          // n: entity slots
  // Moving pair (a, b) in contact last tick (inline: the pair loop asks it of every pair).
  bool was_touching(int a, int b) const { return moving_key_was(contact_key(a, b, false)); }
  // A moving pair's contact_key among last tick's: in the bucket of its lower index (the key's
  // bits 31-62), or by binary search when there is no index.
  bool moving_key_was(uint64_t key) const {
    if (lo_start_.empty()) return std::binary_search(previous_.begin(), previous_.end(), key);
    const size_t lo = episode_bucket(static_cast<size_t>(key >> 31));
    for (uint32_t k = lo_start_[lo], end = lo_start_[lo + 1]; k < end; ++k)
      if (previous_[k] == key) return true;
    return false;
  }
  bool was_in_contact(uint64_t key) const;  // the pair of this contact_key, moving or fixed
  std::vector<Contact> candidates_;
  DetectStats stats_;
  PassTimes times_;
  // continuous
  // What the tiers ask of an entity, in 4 bytes of its Swept line.
  struct SweptTags {
    static constexpr int kRankBits = 26;  // detect_continuous throws past 2^26 entities
    uint32_t rank : kRankBits;  // rank_.ranks()[e]
    uint32_t top_ : 3;          // the tier it may be asked for: the forced tier, else its kind's top
    uint32_t munition : 1;
    uint32_t required : 1;      // driven by a player or snapshotted: its pairs get their exact tier
    uint32_t owned : 1;         // world.ents.owner[e] >= 0 (a munition's shooter)
    Tier top() const { return static_cast<Tier>(top_); }
    static SweptTags make(uint32_t rank, Tier top, bool munition, bool required, bool owned) {
      SweptTags t;
      t.rank = rank, t.top_ = static_cast<uint32_t>(top), t.munition = munition, t.required = required, t.owned = owned;
      return t;
    }
  };
  // Each active entity's sweep, by its slot i (order_[i]), in one cache line: all that a moving
  // pair reads of each of its bodies (the pairs come in no order, so each body costs the lines
  // it spans; it was 10 lines in 8 arrays, then 2: the tags had a line of their own).
  struct alignas(64) Swept {
    Vec3 c0, c1;              // sphere centre at the start and end of the tick
    float r_sphere, r_bound;  // thesis sphere radius; bound of the model (true radius)
    uint32_t e;               // its entity index
    SweptTags tags;
  };
  static_assert(sizeof(Swept) == 64);
  std::vector<Swept> swept_;
  // The tier a moving pair needs: the sphere when either is a munition, else the lower top tier.
  static Tier pair_tier(const SweptTags& a, const SweptTags& b) {
    return a.munition || b.munition ? Tier::Sphere : std::min(a.top(), b.top());
  }
  // A pending pair's closing, the key allocate_tiers ranks pairs by: the length of the sweep's
  // relative motion (m; relative_motion, sweep.hpp), |va - vb| dt up to rounding,
  // from the lines the pair loop has read (the velocities, a line of each body at random, were
  // read for every pair to serve the few left to allocate_tiers). b fixed: its travel is zero.
  static double closing_travel(const Swept& a, const Vec3& b0, const Vec3& b1) {
    return relative_motion(a.c0, a.c1, b0, b1).norm();
  }
  std::vector<Box> boxes_;              // swept boxes
  std::vector<PairCache::Travel> travel_;  // each sweep's x-y travel (m): PairCache's margins
  std::vector<std::pair<uint32_t, uint32_t>> pairs_;
  PairCache moving_;  // the moving bodies' broad phase, kept across ticks
  std::vector<float> fixed_x_, fixed_y_, fixed_r_;  // fixed objects' test circles (m)
  // The grid build (world::FixedGrid::generation) fixed_x_ ... and near_ were taken from (was:
  // the object count, which missed a grid built again over as many objects).
  uint64_t fixed_generation_ = std::numeric_limits<uint64_t>::max();
  // The fixed objects near each entity slot (fixed_contacts): the grid's listings
  // (FixedGrid::query_listed) for a box around its swept box, grown by kNearMarginM plus half
  // the box's size, kept while its swept box stays inside and the grid is the same build; the
  // listings the swept box overlaps are exactly those the grid's query of it gives (in another
  // order: every output is sorted). Past kNearListed listings none are kept (the grid is asked
  // each tick). Most vehicles have none near and skip the grid (its cells' loop, 7 % of a tick
  // at 100,000 vehicles). The default box holds nothing, so the first tick asks the grid.
  static constexpr int kNearListed = 3;
  static constexpr float kNearMarginM = 8.0f;
  struct FixedNear {
    float lo[2] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity()};
    float hi[2] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
    uint32_t n = 0;
    uint32_t listed[kNearListed] = {0, 0, 0};
  };
  std::vector<FixedNear> near_;  // by entity slot, listings of build fixed_generation_
  IdRank rank_, fixed_rank_;
  int64_t ranked_created_ = -1;  // the entity table ranked last (world::Entities::made_since)
  uint64_t ranked_lineage_ = 0;
  std::vector<uint32_t> made_;
  std::vector<Shape> shapes_;           // per model index
  // Per entity slot, one cache line, what the entity pass keeps from tick to tick:
  //  * turning during the tick: the orientation (heading, pitch, roll, deg) at the start of this
  //    tick = the end of the last one when the slot held the same kind and was active then (else
  //    the end's: no turn); prev, kind, ok keep this tick's end for the next;
  //  * the model's centre turned into the local frame, pose_rotation(prev) * centre (world::
  //    entity_centre less the position): made again only when the orientation or the centre
  //    (its kind's, for its state) changes bits, so a vehicle going straight on a plane of the
  //    terrain takes no sines (the same bits as making it each tick: a pure function's memo).
  using Hpr = std::array<float, 3>;
  struct alignas(64) Turn {
    Hpr start{}, prev{};
    int16_t kind = -1;
    uint8_t ok = 0;      // active last tick, prev its end
    uint8_t turned = 0;  // offset is pose_rotation(prev) * centre
    Vec3f centre{0, 0, 0};
    Vec3 offset{0, 0, 0};
  };
  static_assert(sizeof(Turn) == 64);
  std::vector<Turn> turn_;
  // world::entity_centre(w, e) at the end of the tick (e's heading direction from memo()), by
  // way of turn_[e]'s offset; prev is this tick's orientation after it.
  Vec3 centre_end(const world::World& w, int e, Turn& t);
  core::HeadingMemo own_memo_, *shared_memo_ = nullptr;
  core::HeadingMemo& memo() { return shared_memo_ ? *shared_memo_ : own_memo_; }
  Motion motion(const world::World& w, int e) const;  // entity e's motion over this tick
  core::Jobs* jobs_ = nullptr;
  std::vector<Lane> lanes_;
  std::vector<ViewVolume> views_;
  std::vector<Pending> pending_;        // this tick's, in lane order
  struct Importance {  // a pending pair's sort keys (allocate_tiers), by value
    double closing;
    uint32_t rank_a, rank_b;  // rank_b: in fixed_rank_ when b_fixed
    uint32_t pending;         // its index in pending_
    bool required, b_fixed;
  };
  std::vector<Importance> pending_order_;
  std::vector<TierChoice> choices_;
};

// ---- geometry (thesis Figures 4-6) ------------------------------------------------------------
// Haines' crossings test (Figure 6) on a polygon already projected to 2D and translated so the
// test point is the origin: a ray along +U' counts edge crossings; odd = inside. Points with
// V' = 0 count as positive, which puts points on edges and vertices consistently on one side.
bool haines_inside(const float* u, const float* v, int n);

// Every face of `m` whose plane the line origin + t*dir (dir unit, model space) crosses inside
// the polygon (Haines on the dominant-axis projection) with t in [tmin, tmax] (tmin < tmax; t
// may be negative: behind the origin); the one with the smallest t, as a Trace with fraction
// (t - tmin) / (tmax - tmin), point and face normal in model space, the face, and
// started_inside when that face is crossed from inside (its normal along dir). Degenerate faces
// (zero normal) and faces parallel to the ray are skipped.
Trace ray_model(const world::Model& m, const Vec3& origin, const Vec3& dir, double tmin, double tmax);

// Thesis L3 for the pair (a sphere of this object, b the other object's model at its pose):
// the first ray from ca toward cb gives P on a's sphere; the second from P toward cb finds b's
// polygon on that line; real when that point lies inside a's sphere (|t| <= ra from ca).
bool l3_real(const world::World& w, int a, int b, Vec3& point);

// ---- response (Figure 8) ----------------------------------------------------------------------
// Angle of impact from the two compass headings, in [0, 360).
double impact_angle_deg(double heading_a, double heading_b);
// True in the Figure 8 bands: [85,95], [175,185], [265,275], <= 5, >= 355 (edges included).
bool in_kill_band(double angle_deg);
// Damage levels a fixed object takes from a vehicle's momentum (kg m/s), Figure 8 constants
// scaled by the object's resistance: 0 none, 1 low, 2 med, 3 high.
int fixed_damage_level(double momentum, double resistance);

// Turns contacts into changes and collision records (one per contact), by Figure 8. Contacts
// are taken in (time of impact, ids) order; every bounce among them is solved together: a fixed
// number of sequential impulse sweeps over all bouncing contacts, each impulse equal and
// opposite (momentum conserved), then one velocity change per body. Continuous contacts
// (dt_s > 0) move the bodies back to the time of impact and on with their new velocities.
// Reused buffers of respond(): no allocation per call once warm.
struct RespondScratch {
  std::vector<const Contact*> bounces;
  std::vector<int> body;
  std::vector<Vec3> v, shift;
  std::vector<double> first_toi, dt;
};
void respond(const world::World& w, const std::vector<Contact>& contacts, world::Changes& out, RespondScratch& s);
void respond(const world::World& w, const std::vector<Contact>& contacts, world::Changes& out);  // own scratch
// A munition detonates at `point`: on an entity (`hit` >= 0) it kills it and leaves the ground
// untouched (p. 15); on the ground it makes a crater; either way objects and vehicles within the
// blast radius are damaged, more the nearer they are. Only entities of this node (ents.local)
// are damaged: a remote entity's damage is decided by its owner; fixed objects only when
// d.decides_fixed (this node's round: the firing node publishes the objects it changed).
void detonate(const world::World& w, int munition, const Vec3& point, int hit, world::Changes& out);
// The same for a detonation described by `d` (d.kind the munition kind, d.target the entity hit
// or -1); d.munition, when >= 0, is the local round spent by it; -1 for another node's round.
void detonate(const world::World& w, const world::DetonationRecord& d, world::Changes& out);
// Figure 7 bounce of two bodies a, b (velocities m/s, masses kg) along the unit normal n from a
// towards b, restitution thesis::kBounceRestitution: the impulse j (kg m/s) that moves a by
// -j/ma n and b by +j/mb n; 0 when they already separate along n.
double bounce_impulse(const Vec3& va, const Vec3& vb, double ma, double mb, const Vec3& n);

}  // namespace npsnet::collision
