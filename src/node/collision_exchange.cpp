// Collisions across nodes (net_bridge.hpp "Collisions across nodes", collision_outcome.hpp,
// repeat_ledger.hpp): the decider announces each one in a Collision PDU that states its outcome
// and repeats it (repeat_ledger.hpp); the colliding entity's owner applies it once, third nodes
// record it once, each when both entities are known here (a PDU waits for them one DIS timeout).
#include <algorithm>
#include <cmath>

#include "node/collision_outcome.hpp"
#include "node/net_bridge.hpp"
#include "node/pdu_build.hpp"

namespace npsnet::node {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
// Received values past these are corrupt or hostile: a speed (m/s) and the offset of a contact
// point from its entity (m).
constexpr double kMaxSpeedMps = 1e4;
constexpr double kMaxContactOffsetM = 1000.0;

Vec3 vv(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

void NetBridge::on_collision(const net::CollisionPdu& p, double arrival_s) {
  if (try_collision(p, arrival_s) != CollisionWait::Waits) return;
  const std::uint64_t key = repeat_key(p);
  for (const auto& c : waiting_collisions_)
    if (c.key == key) return;  // a repeat of one that waits already
  if (waiting_collisions_.size() >= kMaxWaitingCollisions) {
    waiting_collisions_.erase(waiting_collisions_.begin());  // the oldest gives up
    ++collisions_given_up_;
  }
  waiting_collisions_.push_back({p, key, arrival_s});
}

void NetBridge::retry_waiting_collisions() {
  if (waiting_collisions_.empty()) return;
  const double timeout_s = remotes_.thresholds().timeout_s;
  std::erase_if(waiting_collisions_, [&](const WaitingCollision& c) {
    if (try_collision(c.pdu, now_s_) != CollisionWait::Waits) return true;  // applied, or a repeat now
    if (now_s_ - c.first_s <= timeout_s) return false;
    ++collisions_given_up_;
    return true;
  });
}

NetBridge::CollisionWait NetBridge::try_collision(const net::CollisionPdu& p, double arrival_s) {
  world::World& w = sim_.world();
  auto& ents = w.ents;
  // Issued by one of our vehicles and not our datagram: our earlier process's collision, which
  // another node adopted and repeats (we were killed and restarted).
  const bool own_issuer = ours(p.issuing_entity_id);
  const net::EntityId& mine_id = own_issuer ? p.issuing_entity_id : p.colliding_entity_id;
  const net::EntityId& other_id = own_issuer ? p.colliding_entity_id : p.issuing_entity_id;
  // The colliding entity is ours (we apply the outcome to it), or a third node's copy (we only
  // record the collision and the damage of both copies, as their owners do).
  int own = -1;
  bool third = false;
  if (ours(mine_id)) {
    own = own_entity_of(mine_id);
    if (own < 0) return CollisionWait::Done;  // our id, none of our vehicles
  } else {
    own = remotes_.index_of(mine_id);
    if (own < 0 || !ents.active[own]) return CollisionWait::Waits;  // its Entity State may come
    third = true;
  }
  int other = remotes_.index_of(other_id);
  if (other >= 0 && !ents.active[other]) other = -1;
  const net::RemoteEntity* issuer = own_issuer ? nullptr : remotes_.find(p.issuing_entity_id);
  // A collision of our vehicle from before this process joined (past_collision) waits for the
  // other entity's Entity State, as any, but only for one DIS timeout after the join: then it is
  // applied without it (its node is dead too; a third node adopted the PDU).
  // (An NPSNET node's PDU: it states the outcome in octet 31.)
  const bool past = !third && (own_issuer || (p.padding != kOutcomeUnstated && dated_before_join(p.header.timestamp)));
  if (past && other < 0 && w.t - std::max(0.0, joined_t_) < remotes_.thresholds().timeout_s) return CollisionWait::Waits;
  if (!past && (other < 0 || !issuer)) return CollisionWait::Waits;
  // Applied once, whoever repeats it; until both entities are known here a repeat can still come.
  // A collision issued by a scenario vehicle of another NPSNET node (or of ours) is kept for adoption.
  const bool adoptable = own_issuer || (other >= 0 ? ents.node[other] >= 1 : p.padding != kOutcomeUnstated);
  if (!collisions_.received(p, arrival_s, adoptable, group_at(ents.pos[own]))) return CollisionWait::Done;
  if (past) {
    past_collision(own, other, outcome_of(p, issuer ? issuer->appearance : 0));
    return CollisionWait::Done;
  }
  const world::Result res = outcome_of(p, issuer->appearance);  // the PDU's own (collision_outcome.hpp)
  const auto& frame = w.terrain.frame();
  const Vec3 other_pos = ents.pos[other];
  Eigen::Vector3d ve(p.velocity.x, p.velocity.y, p.velocity.z);
  Vec3 v_other = ents.vel[other];
  if (ve.allFinite() && ve.norm() < kMaxSpeedMps) {
    const Vec3 ecef = frame.to_ecef(other_pos);
    v_other = frame.from_ecef(ecef + vv(ve)) - other_pos;
  }
  Vec3 n = ents.pos[own] - other_pos;
  n.z() = 0;
  n = n.norm() > 1e-9 ? Vec3(n.normalized()) : Vec3::UnitX();
  world::CollisionRecord rec;
  rec.a = std::min(own, other);
  rec.b = std::max(own, other);
  const double h = ents.heading_deg[other] * kDeg;
  const Vec3 fwd(std::sin(h), std::cos(h), 0), right(std::cos(h), -std::sin(h), 0);
  const Vec3 loc(p.location_in_entity.x, p.location_in_entity.y, p.location_in_entity.z);
  rec.point = loc.allFinite() && loc.norm() < kMaxContactOffsetM
                  ? Vec3(other_pos + fwd * loc.x() + right * loc.y() - Vec3::UnitZ() * loc.z())
                  : Vec3((other_pos + ents.pos[own]) / 2);
  rec.closing_speed_mps = std::max(0.0, (v_other - ents.vel[own]).dot(n));
  rec.angle_deg = collision::impact_angle_deg(ents.heading_deg[rec.a], ents.heading_deg[rec.b]);
  rec.method = "network";
  rec.tier = "network";
  rec.result_a = rec.result_b = res;
  inject_.clear();
  inject_.collisions.push_back(rec);
  world::EntityChange mine;
  mine.entity = own;
  mine.set_vel = !third;
  if (res == world::Result::Bounce && third) {
    mine.set_vel = false;
  } else if (res == world::Result::Bounce) {
    // The issuer's mass as it says; left unset (0) or unusable: the mass of the kind its type
    // maps to (models/entity_types.toml), as for the contacts we decide.
    const double said = p.mass;
    const double ma = std::isfinite(said) && said > 0 ? said : w.kinds[ents.kind[other]].mass_kg;
    const double mb = w.kinds[ents.kind[own]].mass_kg;
    Vec3 vb = ents.vel[own];
    vb += (collision::bounce_impulse(v_other, vb, ma, mb, n) / mb) * n;
    if (w.kinds[ents.kind[own]].mobility != world::Mobility::Air) vb.z() = 0;
    mine.vel = vb;
    mine.cruise_mps = static_cast<float>(vb.norm());
  } else {
    mine.vel = Vec3::Zero();
    mine.cruise_mps = third ? -1.f : 0.f;
    // Our entity's damage is ours to decide; the issuer's (and a third node's copy) arrive in
    // their owners' appearance.
    if (res == world::Result::Kill && !third) mine.to_state = static_cast<int>(w.kinds[ents.kind[own]].states.size()) - 1;
  }
  inject_.entities.push_back(mine);
  sim_.inject(inject_);
  inject_.clear();
  return CollisionWait::Done;
}

void NetBridge::past_collision(int own, int other, world::Result res) {
  const world::World& w = sim_.world();
  const auto& ents = w.ents;
  inject_.clear();
  if (other >= 0) {  // both here: the collision is recorded (logged), as the other nodes did
    world::CollisionRecord rec;
    rec.a = std::min(own, other);
    rec.b = std::max(own, other);
    rec.point = ents.pos[other];  // where the other stands (a kill or a stop left it there)
    rec.method = "network_past";  // closing speed and angle of then are not known: 0
    rec.tier = "network";
    rec.result_a = rec.result_b = res;
    inject_.collisions.push_back(rec);
  }
  // The lasting part of the outcome, on our vehicle where the catch-up left it: a kill destroys
  // and stops it, a stop stops it; a bounce of then changes nothing now. Damage only goes forward
  // (world::apply): the most damaged state wins over the catch-up's intact vehicle.
  if (res == world::Result::Kill || res == world::Result::Stop) {
    world::EntityChange mine;
    mine.entity = own;
    mine.set_vel = true;
    mine.vel = Vec3::Zero();
    mine.cruise_mps = 0.f;
    if (res == world::Result::Kill) mine.to_state = static_cast<int>(w.kinds[ents.kind[own]].states.size()) - 1;
    inject_.entities.push_back(mine);
  }
  if (!inject_.collisions.empty() || !inject_.entities.empty()) sim_.inject(inject_);
  inject_.clear();
}

void NetBridge::publish_collisions(const TickReport& r) {
  const auto& w = sim_.world();
  for (const auto& c : r.changes.collisions) {
    if (c.b_fixed || c.a < 0 || c.b < 0) continue;
    int own = -1, other = -1;
    if (is_own_vehicle(c.a) && remotes_.is_remote(c.b)) own = c.a, other = c.b;
    else if (is_own_vehicle(c.b) && remotes_.is_remote(c.a)) own = c.b, other = c.a;
    if (own < 0 || !ownership_.announces(own, remotes_, other)) continue;  // not ours to announce
    const world::Result res = own == c.a ? c.result_a : c.result_b;
    const Vec3 v = ownership_.velocity_before(own, other, w.ents.vel[own]);
    // To the colliding entity's cell: its owner holds that group. Repeated every heartbeat.
    const std::uint32_t group = group_at(w.ents.pos[other]);
    const auto pdu = collision_pdu(w, own, own_id(own), remotes_.id_of(other), next_event(), res, v, c.point);
    session_->send_to(group, pdu);
    collisions_.sent(pdu, group, now_s_);
  }
  collisions_.resend_due(now_s_, remotes_.thresholds().heartbeat_s, remotes_.thresholds().timeout_s,
                         [&](const net::CollisionPdu& pdu, std::uint32_t group) { session_->send_to(group, pdu); });
}

}  // namespace npsnet::node
