#include "node/remote_entities.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <cstdio>

#include "node/dis_mapping.hpp"

namespace npsnet::node {

namespace {
Vec3 vv(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
bool finite3(const Eigen::Vector3d& v) { return v.allFinite(); }
// A remote pose the world can hold: finite, within 1000 km of the frame's origin, slower than
// 10 km/s. Anything else (corrupt or hostile PDUs) leaves the entity where it was.
bool usable(const Vec3& p, const Vec3& v, const Vec3& hpr) {
  return p.allFinite() && v.allFinite() && hpr.allFinite() && p.norm() < 1e6 && v.norm() < 1e4;
}
double round3(double v) { return std::round(v * 1000.0) / 1000.0; }
}  // namespace

RemoteEntities::RemoteEntities(const net::DrThresholds& t, Simulation& sim, EventLog& log,
                               std::shared_ptr<const EntityTypeTable> types)
    : sim_(sim),
      log_(log),
      types_(types ? std::move(types)
                   : std::make_shared<const EntityTypeTable>(EntityTypeTable::load(EntityTypeTable::default_file()))),
      table_(t) {
  remote_id_.assign(sim_.world().ents.size(), net::EntityId{});
}

void RemoteEntities::grow() {
  const size_t n = sim_.world().ents.size();
  if (remote_id_.size() < n) remote_id_.resize(n);
}

net::EntityId RemoteEntities::id_of(int e) const {
  return e >= 0 && static_cast<size_t>(e) < remote_id_.size() ? remote_id_[e] : net::EntityId{};
}

int RemoteEntities::index_of(const net::EntityId& id) const {
  auto it = world_of_.find(id);
  return it == world_of_.end() ? -1 : it->second;
}

const net::RemoteEntity* RemoteEntities::find(const net::EntityId& id) const {
  auto i = table_.find(id);
  return i ? &table_[*i] : nullptr;
}

nlohmann::json RemoteEntities::event(const char* type) const {
  const auto& w = sim_.world();
  return {{"event", type}, {"t", round3(w.t)}, {"frame", w.frame}};
}

int RemoteEntities::kind_for(int e, const net::EntityType& t) const {
  const auto& w = sim_.world();
  const int k = w.ents.kind[e];
  return same_type(w.kinds[k].dis, t) ? k : types_->resolve(t, w.kinds).kind;
}

void RemoteEntities::on_entity_state(const net::EntityStatePdu& p, double now_s, double unix_now_s) {
  grow();
  if (!finite3(Eigen::Vector3d(p.location.x, p.location.y, p.location.z))) return;
  const Known before = known(p.entity_id);
  const auto r = table_.apply(p, now_s, unix_now_s);
  if (r != net::RemoteEntityTable::ApplyResult::Ignored) noted_.push_back({p.entity_id, r, before, known(p.entity_id), p.appearance});
}

void RemoteEntities::on_update(const net::EntityStateUpdatePdu& p, double now_s, double unix_now_s) {
  grow();
  const Known before = known(p.entity_id);
  const auto r = table_.apply(p, now_s, unix_now_s);
  if (r != net::RemoteEntityTable::ApplyResult::Ignored) noted_.push_back({p.entity_id, r, before, known(p.entity_id), p.appearance});
}

void RemoteEntities::mirror(double now_s, bool poses) {
  now_s_ = now_s;
  grow();
  for (const auto& n : noted_) settle(n);
  noted_.clear();
  expire(now_s);
  if (poses) set_poses(now_s);
  flush();
}

void RemoteEntities::flush() {
  if (mirrors_.mirrors.empty()) return;
  sim_.apply_net_in(mirrors_);
  mirrors_.clear();
  grow();
}

void RemoteEntities::deactivate(int e) {
  world::Mirror m;
  m.op = world::Mirror::Op::Deactivate;
  m.entity = e;
  mirrors_.mirrors.push_back(m);
}

RemoteEntities::Known RemoteEntities::known(const net::EntityId& id) const {
  const net::RemoteEntity* r = find(id);
  return r ? Known{true, r->type, r->marking, r->appearance, r->force_id} : Known{};
}

const char* RemoteEntities::tracked_as(const net::EntityType& t) const {
  const EntityChoice c = types_->resolve(t, sim_.world().kinds);
  return c.kind < 0 ? c.track : "";
}

nlohmann::json RemoteEntities::tracked_event(const char* type, const net::EntityId& id, const net::EntityType& t,
                                             const net::Marking& m) const {
  const std::string marking = net::marking_text(m);
  auto ev = event(type);
  ev["id"] = marking.empty() ? id_text(id) : marking;
  ev["entity"] = id_text(id);
  ev["marking"] = marking;
  ev["kind"] = type_text(t);
  ev["tracked_as"] = tracked_as(t);
  return ev;
}

void RemoteEntities::settle(const Noted& n) {
  using R = net::RemoteEntityTable::ApplyResult;
  const net::EntityId& id = n.id;
  const Known& before = n.before;
  const std::uint32_t appearance = n.appearance;
  if (n.result == R::Joined) joined(id, n.after);
  flush();  // what follows reads the world as the mirrors so far left it
  const int e = index_of(id);
  if (n.result == R::Deactivated) {
    if (e >= 0 && sim_.world().ents.active[e]) {
      const auto& ents = sim_.world().ents;
      deactivate(e);
      auto ev = event("entity_removed");  // its owner took it out of the exercise
      ev["id"] = ents.id[e];
      ev["entity"] = id_text(id);
      ev["marking"] = net::marking_text(before.marking);
      ev["kind"] = sim_.world().kinds[ents.kind[e]].name;
      ev["state"] = sim_.world().kinds[ents.kind[e]].states[ents.state[e]];
      log_.write(ev);
    } else if (e < 0 && *tracked_as(before.type)) {
      auto ev = tracked_event("entity_removed", id, before.type, before.marking);
      ev["state"] = kDamageNames[damage_bits(before.appearance)];
      log_.write(ev);
    }
    return;
  }
  if (!n.after.heard) return;
  const Known* now = &n.after;
  if (e < 0) {  // tracked, not in the world: its damage bits as its owner says
    const unsigned from = before.heard ? damage_bits(before.appearance) : 0, to = damage_bits(appearance);
    if (from == to || !*tracked_as(now->type)) return;
    auto ev = tracked_event("damage", id, now->type, now->marking);
    ev["object"] = ev["id"];
    ev.erase("id");
    ev["from_state"] = kDamageNames[from];
    ev["to_state"] = kDamageNames[to];
    ev["remote"] = true;
    log_.write(ev);
    return;
  }
  // Damage is the owner's: shown as its appearance says, also when it goes back (a repair).
  const auto& w = sim_.world();
  const int k = kind_for(e, now->type);
  if (k < 0) return;
  const int to = state_from_appearance(w.kinds[k], appearance);
  if (to != w.ents.state[e]) {
    world::EntityChange ch;
    ch.entity = e;
    ch.to_state = to;
    ch.owner_state = true;
    inject(ch);
  }
}

void RemoteEntities::inject(const world::EntityChange& ch) {
  inject_.clear();
  inject_.entities.push_back(ch);
  sim_.inject(inject_);
  inject_.clear();
}

void RemoteEntities::joined(const net::EntityId& id, const Known& r) {
  flush();  // earlier mirrors first: this join reads the world
  const world::World& w = sim_.world();
  const auto& ents = w.ents;
  const std::string marking = net::marking_text(r.marking);
  int e = index_of(id);
  int kind = e >= 0 ? kind_for(e, r.type) : -1;
  const bool rejoin = e >= 0;  // this id was here before (timed out or deactivated): the same entity
  if (rejoin)
    for (auto& s : resumes_)
      if (s.entity == e) s.until_s = now_s_ + kResumeS;
  if (e < 0) {
    // A scenario vehicle of another node with this marking, not yet bound to an entity id.
    for (size_t i = 0; i < ents.size(); ++i)
      if (!ents.local[i] && ents.id[i] == marking && remote_id_[i].site == 0 &&
          w.kinds[ents.kind[i]].mobility != world::Mobility::Munition) {
        e = static_cast<int>(i);
        break;
      }
    if (e >= 0) {
      kind = kind_for(e, r.type);
      if (kind < 0) kind = ents.kind[e];
      if (kind != ents.kind[e]) {  // the owner says it is another type: show that kind
        world::EntityChange ch;
        ch.entity = e;
        ch.to_kind = kind;
        inject(ch);
      }
    } else {
      const EntityChoice c = types_->resolve(r.type, w.kinds);
      if (c.kind < 0 && *c.track) {  // tracked, not simulated: no model for what it is
        auto ev = tracked_event("entity_joined", id, r.type, r.marking);
        ev["model"] = "none";
        log_.write(ev);
        return;
      }
      kind = c.kind;
      if (kind < 0) return;  // no vehicle kind at all in this kinds file
      world::Mirror m;
      m.op = world::Mirror::Op::Join;
      m.entity = static_cast<int>(ents.size());
      m.kind = kind;
      m.name = marking.empty() ? id_text(id) : marking;
      mirrors_.mirrors.push_back(std::move(m));
      e = static_cast<int>(ents.size());
      flush();  // the entity exists from here on
    }
    remote_id_[e] = id;
    world_of_[id] = e;
  }
  world::Mirror m;
  m.op = world::Mirror::Op::Activate;
  m.entity = e;
  m.force = r.force_id;  // as its owner says
  mirrors_.mirrors.push_back(m);
  if (kind < 0) kind = ents.kind[e];
  const bool known_type = same_type(w.kinds[kind].dis, r.type);
  auto ev = event("entity_joined");
  ev["id"] = ents.id[e];
  ev["entity"] = id_text(id);
  ev["marking"] = marking;
  ev["kind"] = known_type ? w.kinds[kind].name : type_text(r.type);
  if (!known_type) ev["model"] = w.kinds[kind].name;
  if (rejoin) ev["rejoin"] = true;
  log_.write(ev);
}

bool RemoteEntities::resumed_contact(int a, int b, double now_s) {
  bool hit = false;
  std::erase_if(resumes_, [&](const Resume& s) {
    const bool pair = (s.entity == a && s.partner == b) || (s.entity == b && s.partner == a);
    if (pair && !hit && now_s <= s.until_s && std::isfinite(s.until_s)) return hit = true;
    return now_s > s.until_s;  // rejoined more than kResumeS ago: a later contact is new
  });
  return hit;
}

void RemoteEntities::expire(double now_s) {
  flush();  // a timeout reads whether the entity is still there
  const world::World& w = sim_.world();
  table_.expire(now_s, [&](const net::RemoteEntity& r) {
    const int e = index_of(r.id);
    if (e < 0) {  // tracked, not in the world
      if (*tracked_as(r.type)) log_.write(tracked_event("entity_timeout", r.id, r.type, r.marking));
      return;
    }
    // The episodes it is in go on if it comes back (a lost heartbeat or two, not a departure).
    sim_.detector().each_partner(e, [&](int q) {
      if (q != e && w.ents.active[q] && resumes_.size() < kMaxResumes)
        resumes_.push_back({e, q, std::numeric_limits<double>::infinity()});
    });
    deactivate(e);
    auto ev = event("entity_timeout");
    ev["id"] = w.ents.id[e];
    ev["entity"] = id_text(r.id);
    ev["marking"] = net::marking_text(r.marking);
    ev["kind"] = w.kinds[w.ents.kind[e]].name;
    log_.write(ev);
  });
}

std::string RemoteEntities::listing(double now_s, std::size_t max_lines) const {
  const auto& w = sim_.world();
  std::string out;
  const std::size_t n = table_.size();
  for (std::size_t i = 0; i < n && i < max_lines; ++i) {
    const net::RemoteEntity& r = table_[i];
    const int e = index_of(r.id);
    const char* track = e >= 0 ? "" : tracked_as(r.type);  // tracked only: what it is, its damage bits
    const std::string kind = e >= 0 ? w.kinds[w.ents.kind[e]].name : *track ? track : "none";
    const std::string state = e >= 0 ? w.kinds[w.ents.kind[e]].states[w.ents.state[e]]
                              : *track ? kDamageNames[damage_bits(r.appearance)] : "unknown";
    char b[160];
    std::snprintf(b, sizeof b, " owner site %u app %u last update %.1f s ago damage ", r.id.site, r.id.application,
                  now_s - r.last_update_s);
    out += "\n  remote " + id_text(r.id) + " " + nlohmann::json(net::marking_text(r.marking)).dump() + " type " +
           type_text(r.type) + " (" + kind + ")" + b + state + " (appearance damage " +
           std::to_string(damage_bits(r.appearance)) + ") force " + std::to_string(r.force_id);
  }
  if (n > max_lines) out += "\n  remote ... " + std::to_string(n - max_lines) + " more";
  return out;
}

void RemoteEntities::set_poses(double now_s) {
  flush();  // joins and removals first: only active entities get a pose
  const world::World& w = sim_.world();
  const auto& frame = w.terrain.frame();
  for (std::size_t i = 0; i < table_.size(); ++i) {
    const net::RemoteEntity& r = table_[i];
    const int e = index_of(r.id);
    if (e < 0 || !w.ents.active[e]) continue;
    const net::Pose pose = table_.displayed_pose(i, now_s);
    if (!finite3(pose.position)) continue;
    const Vec3 p = frame.from_ecef(vv(pose.position));
    const Vec3 hpr = frame.from_dis_euler(p, Vec3(pose.orientation.psi, pose.orientation.theta, pose.orientation.phi));
    const Vec3 ahead = frame.from_ecef(vv(pose.position + pose.velocity));  // dead-reckoned, world axes
    if (!usable(p, ahead - p, hpr)) continue;
    world::Mirror m;
    m.op = world::Mirror::Op::Pose;
    m.entity = e;
    m.pos = p, m.vel = ahead - p;
    m.heading_deg = static_cast<float>(hpr.x());
    m.pitch_deg = static_cast<float>(hpr.y());
    m.roll_deg = static_cast<float>(hpr.z());
    mirrors_.mirrors.push_back(m);
  }
}

}  // namespace npsnet::node
