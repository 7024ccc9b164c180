// The bridge's warfare receive side (Fire and Detonation PDUs of other simulators): what their
// munition is here (munition_table.hpp) and what its detonation result allows
// (munition_codes.hpp). Contract in net_bridge.hpp.
#include <algorithm>
#include <cmath>

#include "node/dis_mapping.hpp"
#include "node/munition_codes.hpp"
#include "node/net_bridge.hpp"

namespace npsnet::node {

namespace {
double round3(double v) { return std::round(v * 1000.0) / 1000.0; }
Vec3 vv(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
}  // namespace

void NetBridge::on_fire(const net::FirePdu& p) {
  const auto& w = sim_.world();
  const int shooter = remotes_.index_of(p.firing_entity_id);
  const MunitionEffect fx = munitions_->effect(p.descriptor, w.kinds);
  auto ev = event("fire");
  ev["shooter"] = shooter >= 0 ? w.ents.id[shooter] : id_text(p.firing_entity_id);
  ev["munition"] = fx.kind >= 0 ? std::string(fx.name) : type_text(p.descriptor.munition_type);
  ev["dis_type"] = type_text(p.descriptor.munition_type);
  ev["warhead"] = fx.warhead;
  ev["fuse"] = fuse_class(p.descriptor.fuse);
  ev["quantity"] = p.descriptor.quantity;
  ev["round"] = id_text(p.munition_id);
  const int target = remotes_.index_of(p.target_entity_id);
  ev["target"] = target >= 0 ? w.ents.id[target] : "";
  const Eigen::Vector3d loc(p.location.x, p.location.y, p.location.z);
  if (loc.allFinite()) {
    const Vec3 l = w.terrain.frame().from_ecef(vv(loc));
    ev["from"] = nlohmann::json::array({round3(l.x()), round3(l.y()), round3(l.z())});
  }
  ev["remote"] = true;
  log_.write(ev);
}

void NetBridge::on_detonation(const net::DetonationPdu& p, double arrival_s) {
  if (drop_detonations_s_ > 0 && arrival_s - start_s_ < drop_detonations_s_) {
    ++dropped_detonations_;  // the test hook: this datagram is "lost"
    return;
  }
  const world::World& w = sim_.world();
  const Eigen::Vector3d loc(p.location.x, p.location.y, p.location.z);
  const Vec3 point = loc.allFinite() ? w.terrain.frame().from_ecef(vv(loc)) : Vec3(0, 0, 0);
  // A round of another NPSNET node (a scenario vehicle fired it): kept for adoption (ledger).
  const int firer = remotes_.index_of(p.firing_entity_id);
  const bool adoptable = firer >= 0 && !w.ents.local[firer] && w.ents.node[firer] >= 1;
  if (!detonations_.received(p, arrival_s, adoptable, point.allFinite() ? group_at(point) : net::Session::kDestination))
    return;  // a repeat (heartbeat repair, adoption) or a duplicated datagram
  if (!loc.allFinite()) return;
  if (!point.allFinite() || !w.terrain.contains(point.x(), point.y())) return;
  const MunitionEffect fx = munitions_->effect(p.descriptor, w.kinds);
  if (fx.kind < 0) return;  // the kinds file has no munition at all
  const DetonationResultInfo res = detonation_result(p.detonation_result);
  int hit = -1;
  if (p.detonation_result == dis::kResultEntityImpact) {
    hit = own_entity_of(p.target_entity_id);
    if (hit < 0 && !ours(p.target_entity_id))
      hit = remotes_.index_of(p.target_entity_id);
    if (hit >= 0 && !w.ents.active[hit]) hit = -1;
  }
  world::DetonationRecord d;
  d.kind = fx.kind;
  d.shooter = remotes_.index_of(p.firing_entity_id);
  d.round = "rd" + id_text(p.exploding_entity_id);
  d.target = hit;
  d.point = point;
  d.result = res.name;
  const double agl = point.z() - w.terrain.height(point.x(), point.y());
  if ((p.detonation_result == 0 || p.detonation_result == dis::kResultDetonation) && air_fuse(p.descriptor.fuse) &&
      agl >= w.kinds[fx.kind].crater_radius_m)
    d.result = "airburst";
  d.decides_fixed = false;  // the firing node publishes the fixed objects its round changed
  d.crater = fx.crater && res.crater;
  // A round that fell before this node joined (a repeat reaching a restarted node or a late
  // joiner): its crater and the direct hit it names apply; its blast damages none of our
  // vehicles: they stood elsewhere then (the catch-up moved them as if it never fell), and where
  // a repeat finds them depends on when it arrives.
  d.blast = fx.blast && res.blast && !dated_before_join(p.header.timestamp);
  d.hit_destroys = fx.hit_destroys && res.blast;
  d.quantity = std::max<int>(1, p.descriptor.quantity);
  d.munition_name = fx.name;
  d.warhead = fx.warhead;
  d.fuse = fuse_class(p.descriptor.fuse);
  sim_.inject_detonation(d);
}

}  // namespace npsnet::node
