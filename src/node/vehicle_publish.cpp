// Publishing the local vehicles (net_bridge.hpp "Local vehicles", "Net out cost", "Threading"):
// each tick, the Entity States the DR thresholds, a damage change or a cell change call for, in
// round robin past the per-tick cap; the deactivation Entity States of leave(). The dead-reckoning
// anchors (dr_bound.hpp) keep most vehicles out of ECEF.
#include <algorithm>
#include <cmath>

#include "core/prefetch.hpp"
#include "node/dis_mapping.hpp"
#include "node/net_bridge.hpp"
#include "node/pdu_build.hpp"

namespace npsnet::node {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
// Entity State datagrams one tick sends at most (one PDU each); the rest go on the next ticks.
// A receiver drains its socket once a tick: 128 datagrams fit its default receive buffer
// (Linux rmem_default 208 KiB), where the 517 first Entity States of the default scenario did not.
constexpr size_t kMaxDatagramsPerTick = 128;
// Published acceleration (ours, not the standard's): low-pass time constant (s), and the speed
// (m/s) below which a vehicle is at rest and sends none.
constexpr double kAccelTauS = 0.5;
constexpr double kAtRestMps = 0.05;
// A new entity's first Entity State, and one whose damage changed, is sent again kAnnounceRepeats
// times kAnnounceGapS apart (besides DR updates and heartbeats): one lost datagram no longer hides
// a parked vehicle, or its new damage, for a whole 5 s heartbeat (issue 11). Ours, within DIS:
// a simulation may always send an Entity State before its heartbeat is due.
constexpr int kAnnounceRepeats = 2;
constexpr double kAnnounceGapS = 0.5;
// Exact DR tests made ahead per pool round (with worker threads): what the cap leaves room for
// (plus the first deferred; nearly every vehicle the bound cannot clear is sent: about 129 tests
// a tick for the 128 sent in a 20,000-vehicle crowd), at least kMinTestBatch, at most
// kMaxTestBatch; at least kTestGrain tests a thread (one test: about 6,300 instructions).
constexpr size_t kMinTestBatch = 16, kMaxTestBatch = 512, kTestGrain = 4;
// Vehicles ahead whose publisher and anchor the local pass asks of the cache (a hint).
constexpr size_t kPublishAhead = 4;

}  // namespace

void NetBridge::publish_vehicles() {
  const auto& w = sim_.world();
  const double dt = sim_.dt();
  const double t = w.t + dt;  // the time of the state: dynamics has stepped, w.t not yet
  const size_t n = own_.size();
  size_t sent_now = 0, first_deferred = n;
  // Every vehicle in the local frame, on the tick's threads: the published acceleration (the
  // velocity change per tick, low-pass filtered over kAccelTauS, zero at rest: a tank stopping in
  // one tick is not sent as |a| = 100 m/s^2), the yaw rate, and whether its Entity State is surely
  // not due (dr_bound.hpp).
  const double alpha = dt / (kAccelTauS + dt);
  auto local = [&](int c, size_t i0, size_t i1) {
    std::vector<std::uint32_t>& due = due_[c];  // this range's vehicles not skipped, ascending
    std::vector<std::uint32_t>& altered = altered_[c];  // of those, the changed ones
    // (Every vehicle's place written, the count advanced only for one listed: at 100,000 vehicles
    // past the send cap nearly all are, and a push_back's end pointer stored and read back on
    // each was a quarter of this pass.)
    due.resize(i1 - i0), altered.clear();
    std::uint32_t* listed = due.data();
    size_t n_listed = 0;
    for (size_t i = i0; i < i1; ++i) {
      // What the bound reads of the publisher and the anchor (quick_: two lines a vehicle, where
      // the two were seven; 12.8 MB at 100,000, more than the cache) asked for kPublishAhead
      // vehicles early: the hardware's own fetching missed them among this loop's many arrays.
      if (i + kPublishAhead < i1) core::prefetch_object(&quick_[i + kPublishAhead]);
      const int e = own_[i];
      const Vec3& v = w.ents.vel[e];
      const DrQuick& quick = quick_[i];
      if (quick.has_sent) accel_[i] += ((v - prev_vel_[i]) / dt - accel_[i]) * alpha;
      if (!quick.has_sent || v.norm() < kAtRestMps) accel_[i].setZero();
      prev_vel_[i] = v;
      yaw_rate_[i] = static_cast<float>(wrap180(w.ents.heading_deg[e] - prev_heading_[i]) * kDeg / dt);
      prev_heading_[i] = w.ents.heading_deg[e];
      // Left out of `due` (the serial loop never sees it): removed, or no damage / group change
      // and surely not due (what the loop would find for itself; its sends change only vehicle
      // i's own fields). The changed ones are also listed in `altered`: past the cap the loop
      // jumps from one to the next without reading the others.
      if (removed_[i]) {
        changed_[i] = 0;
        continue;
      }
      const bool changed = quick.has_sent && (damage_appearance(w.kinds[w.ents.kind[e]], w.ents.state[e]) !=
                                                       sent_appearance_[i] ||
                                                   group_at(w.ents.pos[e]) != sent_group_[i]);
      const bool quiet = opt_.dr_prefilter && dr_quiet(quick, w, e, t);
      const bool repeat = announce_left_[i] > 0 && t >= announce_at_[i] - 1e-9;  // kAnnounceRepeats
      changed_[i] = changed;
      listed[n_listed] = static_cast<std::uint32_t>(i);
      n_listed += !(quiet && !repeat && !changed);
      if (changed) altered.push_back(static_cast<std::uint32_t>(i));
    }
    due.resize(n_listed);
  };
  if (due_.size() < static_cast<size_t>(core::Jobs::kMaxChunks))
    due_.resize(core::Jobs::kMaxChunks), altered_.resize(core::Jobs::kMaxChunks);
  const int ranges = core::run_chunks(sim_.jobs(), n, 128, local, 4);  // 4 a thread: claimed as threads come free
  // Round robin from where the last tick's cap stopped, so no vehicle waits more than a few ticks;
  // removed vehicles and those the exact test would pass over are not looked at. The ranges'
  // lists, in range order, are every vehicle not skipped in ascending order: from the first at
  // or past the start, then from the beginning (what a walk from the start round would give).
  // altered_at_: the places in order_ of the changed vehicles, ascending (past the cap the loop
  // looks at no others).
  order_.clear(), altered_at_.clear();
  const std::uint32_t start = n ? static_cast<std::uint32_t>(rr_ % n) : 0;
  for (int pass = 0; pass < 2; ++pass)
    for (int c = 0; c < ranges; ++c) {
      const auto& due = due_[c];
      const auto cut = std::lower_bound(due.begin(), due.end(), start);
      const auto from = pass == 0 ? cut : due.begin(), to = pass == 0 ? due.end() : cut;
      for (const std::uint32_t i : altered_[c])
        if ((i >= start) == (pass == 0))
          altered_at_.push_back(order_.size() + (std::lower_bound(from, to, i) - from));
      order_.insert(order_.end(), from, to);
    }
  // With worker threads, the exact tests of the next vehicles in that order (a batch,
  // kMaxTestBatch) run on the pool, each into its own slot: test_vehicle, which reads the world
  // and vehicle i's own fields only and writes the slot (the exact state and its anchor, whether
  // the vehicle is to be sent and, for that outcome, its next publisher, anchor and Entity
  // State). The loop takes a vehicle's slot when it reaches it: what it would compute there.
  // Results the loop does not reach (past the cap) are dropped, nothing else touched. Not once
  // the cap defers all but changes. Without workers the loop tests each vehicle itself.
  core::Jobs* jobs = sim_.jobs();
  size_t tested0 = 0, tested1 = 0;  // positions in order_ whose tests are in tested_
  size_t next_altered = 0;            // into altered_at_
  for (size_t p = 0; p < order_.size(); ++p) {
    const size_t i = order_[p];
    // A damage change, or a move into another cell's group (announced there at once): changed_.
    const bool changed = changed_[i];
    const bool capped = (!pack_ || aoi_) && sent_now >= kMaxDatagramsPerTick;
    const bool deferring = capped && first_deferred != n && opt_.dr_prefilter;
    if (deferring && !changed) {  // deferred whatever it says; so are the rest but the changed
      while (next_altered < altered_at_.size() && altered_at_[next_altered] <= p) ++next_altered;
      if (next_altered == altered_at_.size()) break;
      p = altered_at_[next_altered] - 1;
      continue;
    }
    const int e = own_[i];
    if (jobs && !deferring && p >= tested1) {
      const size_t room = (!pack_ || aoi_) && opt_.dr_prefilter
                              ? (sent_now < kMaxDatagramsPerTick ? kMaxDatagramsPerTick - sent_now : 0) + 1
                              : kMaxTestBatch;
      tested0 = p, tested1 = std::min(order_.size(), p + std::clamp(room, kMinTestBatch, kMaxTestBatch));
      if (tested_.size() < tested1 - tested0) tested_.resize(tested1 - tested0);
      jobs->for_chunks(tested1 - tested0, kTestGrain, [&](int, size_t q0, size_t q1) {
        for (size_t q = q0; q < q1; ++q) test_vehicle(order_[tested0 + q], t, tested_[q]);
      });
    }
    const bool ahead = p >= tested0 && p < tested1;
    Tested& r = ahead ? tested_[p - tested0] : tested_here_;
    if (!ahead) test_vehicle(i, t, r);
    ++exact_tests_;
    // Not sent (not due: as test_vehicle made it; deferred, or the send failed: made here): the
    // anchor's errors are against the believed pose the publisher keeps. Sent: the new one's.
    auto keep_anchor = [&] {
      anchors_[i] = r.anchor;
      if (pubs_[i].has_sent()) dr_rebase(r.state, pubs_[i], t, anchors_[i]);
      quick_[i] = dr_quick(anchors_[i], pubs_[i]);
    };
    if (!r.send) {
      anchors_[i] = r.next_anchor, quick_[i] = r.next_quick;
      continue;
    }
    if (capped && !changed) {  // a damage change never waits
      if (first_deferred == n) first_deferred = i;
      keep_anchor();
      continue;
    }
    // One PDU a datagram, or (pack_ without aoi_) several to a datagram of at most 1400 octets.
    const std::uint32_t group = group_at(w.ents.pos[e]);
    if (!(pack_ && !aoi_ ? pack(r.es) : session_->send_to(group, r.es))) {
      keep_anchor();
      continue;
    }
    if (!pubs_[i].has_sent() || changed) announce_left_[i] = kAnnounceRepeats;  // new or changed: repeat it soon
    else if (r.repeat) --announce_left_[i];
    announce_at_[i] = t + kAnnounceGapS;
    pubs_[i] = r.next_pub;  // marked sent
    anchors_[i] = r.next_anchor, quick_[i] = r.next_quick;
    digest_entity_state(r.es);
    sent_appearance_[i] = r.es.appearance;
    sent_group_[i] = group;
    ++sent_now;
    if (w.kinds[w.ents.kind[e]].mobility == world::Mobility::Ground) ++ground_es_sent_;
  }
  if (first_deferred != n) rr_ = first_deferred;
  flush_batch();
}

void NetBridge::test_vehicle(size_t i, double t, Tested& r) const {
  const auto& w = sim_.world();
  const int e = own_[i];
  r.anchor = anchors_[i];
  r.state = exact_state(w, e, r.anchor);
  r.state.acceleration = r.anchor.jac * accel_[i];
  r.state.angular_velocity = Eigen::Vector3d(0, 0, yaw_rate_[i]);
  r.repeat = announce_left_[i] > 0 && t >= announce_at_[i] - 1e-9;  // kAnnounceRepeats
  r.send = changed_[i] || r.repeat;
  r.next_anchor = r.anchor;
  if (!r.send) {  // the DR test decides; when it says None its errors are the new anchor's
    const net::DrPublisher::Test test = pubs_[i].test(r.state, t);
    r.send = test.reason != net::DrPublisher::Reason::None;
    if (!r.send) {
      dr_rebase(r.state, test, t, r.next_anchor);  // (None: the publisher has sent)
      r.next_quick = dr_quick(r.next_anchor, pubs_[i]);
      return;
    }
  }
  r.next_pub = pubs_[i];
  r.next_pub.mark_sent(r.state, t);
  dr_rebase(r.state, r.next_pub, t, r.next_anchor);
  r.next_quick = dr_quick(r.next_anchor, r.next_pub);
  const std::uint32_t app = damage_appearance(w.kinds[w.ents.kind[e]], w.ents.state[e]);
  fill_entity_state(w, e, own_id(e), r.state, pubs_[i].algorithm(), app, static_cast<std::uint8_t>(opt_.exercise), t, r.es);
  r.es.header.protocol_version = static_cast<std::uint8_t>(opt_.dis_version);  // packed datagrams too
}

void NetBridge::digest_entity_state(const net::EntityStatePdu& es) {
  auto mix = [&](const void* p, size_t len) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t k = 0; k < len; ++k) es_digest_ = (es_digest_ ^ b[k]) * 1099511628211ull;
  };
  mix(&es.entity_id.entity, sizeof es.entity_id.entity);
  mix(&es.location, sizeof es.location);
  mix(&es.linear_velocity, sizeof es.linear_velocity);
  mix(&es.orientation, sizeof es.orientation);
  mix(&es.dead_reckoning.linear_acceleration, sizeof es.dead_reckoning.linear_acceleration);
  mix(&es.dead_reckoning.angular_velocity, sizeof es.dead_reckoning.angular_velocity);
  mix(&es.appearance, sizeof es.appearance);
  mix(&es.header.timestamp, sizeof es.header.timestamp);
}

bool NetBridge::pack(const net::EntityStatePdu& es) {
  if (batch_.add(es)) return true;
  flush_batch();
  if (batch_.add(es)) return true;
  ++session_->counters().send_failures;  // cannot happen for our PDUs (no variable parameters)
  return false;
}

void NetBridge::flush_batch() {
  if (!batch_.empty()) session_->send(batch_);
  batch_.clear();
}

void NetBridge::send_deactivation(int e) {
  const auto& w = sim_.world();
  const std::uint32_t app = damage_appearance(w.kinds[w.ents.kind[e]], w.ents.state[e]) | net::kAppearanceDeactivated;
  fill_entity_state(w, e, own_id(e), entity_truth(w, e), net::DrAlgorithm::Static, app,
                    static_cast<std::uint8_t>(opt_.exercise), w.t, es_);
  session_->send_to(group_at(w.ents.pos[e]), es_);
}

void NetBridge::leave() {
  for (size_t i = 0; i < own_.size(); ++i)
    if (!removed_[i]) send_deactivation(own_[i]);
}

}  // namespace npsnet::node
