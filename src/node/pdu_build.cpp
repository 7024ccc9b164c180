#include "node/pdu_build.hpp"

#include <cmath>

#include "node/collision_outcome.hpp"
#include "node/dis_mapping.hpp"

namespace npsnet::node {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
Eigen::Vector3d ev(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
net::Vec3f f3(const Vec3& v) { return net::wire_vec3f(v.x(), v.y(), v.z()); }
net::Marking marking_of(const std::string& id) {
  auto mk = net::make_marking(id.substr(0, 11));
  return mk ? mk.value() : net::Marking{};
}
// Velocity `v` at local point `p` in ECEF axes.
Vec3 ecef_velocity(const world::World& w, const Vec3& p, const Vec3& v) {
  const auto& frame = w.terrain.frame();
  return frame.to_ecef(p + v) - frame.to_ecef(p);
}
}  // namespace

net::KinematicState entity_truth(const world::World& w, int e) {
  geo::FrameMemo memo(w.terrain.frame());
  return entity_truth(w, e, memo);
}

net::KinematicState entity_truth(const world::World& w, int e, geo::FrameMemo& memo, Mat3* jac) {
  net::KinematicState s;
  const Vec3 p = w.ents.pos[e];
  // Once, for the position, the orientation and the Jacobian, with the convergence and scale the
  // inverse gives (no forward projection).
  geo::FrameMemo::Grid grid;
  const geo::Geodetic g = memo.to_geodetic(p, grid);
  const Vec3 pe = memo.geodetic_to_ecef(g);
  s.position = ev(pe);
  const Vec3 eu = memo.to_dis_euler(g, grid, w.ents.heading_deg[e], w.ents.pitch_deg[e], w.ents.roll_deg[e]);
  s.orientation = {eu.x(), eu.y(), eu.z()};
  const Mat3 j = memo.jacobian(g, grid);
  s.velocity = ev(j * w.ents.vel[e]);  // the derivative (was a 1 s difference)
  if (jac) *jac = j;
  return s;
}

void fill_entity_state(const world::World& w, int e, const net::EntityId& id, const net::KinematicState& s,
                       net::DrAlgorithm algorithm, std::uint32_t appearance, std::uint8_t exercise, double state_t_s,
                       net::EntityStatePdu& es) {
  es.entity_id = id;
  es.force_id = w.ents.force[e];
  es.entity_type = to_net(w.kinds[w.ents.kind[e]].dis);
  es.alternative_entity_type = es.entity_type;
  es.marking = marking_of(w.ents.id[e]);
  es.appearance = appearance;
  net::write_kinematics(s, algorithm, es);
  es.header.timestamp = net::relative_timestamp(state_t_s);
  es.header.exercise_id = exercise;
}

void fill_cultural(const world::World& w, int o, const net::EntityId& id, net::EntityStatePdu& p) {
  p.entity_id = id;
  p.entity_type = to_net(w.kinds[w.fixed.kind[o]].dis);
  p.alternative_entity_type = p.entity_type;
  net::KinematicState s;
  const auto& frame = w.terrain.frame();
  s.position = ev(frame.to_ecef(w.fixed.pos[o]));
  const Vec3 eu = frame.to_dis_euler(w.fixed.pos[o], w.fixed.heading_deg[o], 0, 0);
  s.orientation = {eu.x(), eu.y(), eu.z()};
  net::write_kinematics(s, net::DrAlgorithm::Static, p);
  p.appearance = damage_appearance(w.kinds[w.fixed.kind[o]], w.fixed.state[o]);  // bits 3-4, as for vehicles
  p.marking = marking_of(w.fixed.id[o]);
  p.header.timestamp = net::relative_timestamp(w.t);
}

net::FirePdu fire_pdu(const world::World& w, int m, const net::EntityId& firing, const net::EntityId& target,
                      const net::EntityId& munition, const net::EventId& event) {
  const auto& ents = w.ents;
  net::FirePdu p;
  p.firing_entity_id = firing;
  p.target_entity_id = target;
  p.munition_id = munition;
  p.event_id = event;
  const Vec3 pe = w.terrain.frame().to_ecef(ents.pos[m]);
  p.location = {pe.x(), pe.y(), pe.z()};
  p.descriptor.munition_type = to_net(w.kinds[ents.kind[m]].dis);
  p.descriptor.warhead = dis::kWarheadHighExplosive;
  p.descriptor.fuse = dis::kFuseContact;
  p.descriptor.quantity = 1;
  p.velocity = f3(ecef_velocity(w, ents.pos[m], ents.vel[m]));
  p.range = net::wire_float((ents.aim[m] - ents.pos[m]).norm());
  p.header.timestamp = net::relative_timestamp(w.t);
  return p;
}

net::DetonationPdu detonation_pdu(const world::World& w, const world::DetonationRecord& d, const net::EntityId& firing,
                                  const net::EntityId& target, const net::EntityId& exploding,
                                  const net::EventId& event) {
  const int m = d.munition;
  net::DetonationPdu p;
  p.firing_entity_id = firing;
  p.target_entity_id = target;
  p.exploding_entity_id = exploding;
  p.event_id = event;
  const Vec3 pe = w.terrain.frame().to_ecef(d.point);
  p.location = {pe.x(), pe.y(), pe.z()};
  p.velocity = f3(ecef_velocity(w, d.point, w.ents.vel[m]));
  p.descriptor.munition_type = to_net(w.kinds[w.ents.kind[m]].dis);
  p.descriptor.warhead = dis::kWarheadHighExplosive;
  p.descriptor.fuse = dis::kFuseContact;
  p.descriptor.quantity = 1;
  p.detonation_result = d.target >= 0 ? dis::kResultEntityImpact : dis::kResultGroundImpact;
  p.header.timestamp = net::relative_timestamp(w.t);
  return p;
}

net::CollisionPdu collision_pdu(const world::World& w, int own, const net::EntityId& issuing,
                                const net::EntityId& colliding, const net::EventId& event, world::Result result,
                                const Vec3& own_vel, const Vec3& point) {
  const auto& ents = w.ents;
  net::CollisionPdu p;
  p.issuing_entity_id = issuing;
  p.colliding_entity_id = colliding;
  p.event_id = event;
  set_outcome(p, result);  // collision type, and the outcome in octet 31 (collision_outcome.hpp)
  p.velocity = f3(ecef_velocity(w, ents.pos[own], own_vel));
  p.mass = net::wire_float(w.kinds[ents.kind[own]].mass_kg);
  const Vec3 d = point - ents.pos[own];
  const double h = ents.heading_deg[own] * kDeg;
  p.location_in_entity = net::wire_vec3f(d.x() * std::sin(h) + d.y() * std::cos(h), d.x() * std::cos(h) - d.y() * std::sin(h), -d.z());
  p.header.timestamp = net::relative_timestamp(w.t);
  return p;
}

}  // namespace npsnet::node
