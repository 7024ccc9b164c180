// PDU building: what a local entity, fixed object, fire, detonation or collision looks like on
// the wire. Pure functions of the world and the ids the caller resolved; no I/O.
// Units: world local frame metres and m/s in, WGS84 ECEF metres and m/s, DIS Euler radians out.
// Timestamps: relative, the scenario time of the state the PDU carries (w.t; an Entity State
// is given its state's time, which after a tick's step is w.t + dt).
#pragma once
#include <cstdint>

#include "core/geodesy.hpp"
#include "net/net.hpp"
#include "world/changes.hpp"
#include "world/world.hpp"

namespace npsnet::node {

// Entity e's true state: ECEF position, ECEF velocity (the local velocity through the frame's
// Jacobian at e's position), DIS Euler angles (acceleration and angular velocity zero; the
// publisher fills them).
net::KinematicState entity_truth(const world::World& w, int e);
// The same through `memo` (the same bits); with `jac`, also the Jacobian at e's position that the
// velocity went through (exact_state's anchor).
net::KinematicState entity_truth(const world::World& w, int e, geo::FrameMemo& memo, Mat3* jac = nullptr);

// The one Entity State fill of a local vehicle: id, force, kind's DIS type (also as the
// alternative type), marking = scenario id, appearance, kinematics with `algorithm`, timestamp
// = state_t_s (scenario s) relative.
void fill_entity_state(const world::World& w, int e, const net::EntityId& id, const net::KinematicState& s,
                       net::DrAlgorithm algorithm, std::uint32_t appearance, std::uint8_t exercise, double state_t_s,
                       net::EntityStatePdu& es);

// A fixed object as a static cultural feature (kind 5): its damage in appearance bits 3-4.
void fill_cultural(const world::World& w, int object, const net::EntityId& id, net::EntityStatePdu& p);

// Fire of local munition m (just launched): location, velocity and range from the world.
net::FirePdu fire_pdu(const world::World& w, int m, const net::EntityId& firing, const net::EntityId& target,
                      const net::EntityId& munition, const net::EventId& event);

// Detonation `d` of a local munition.
net::DetonationPdu detonation_pdu(const world::World& w, const world::DetonationRecord& d, const net::EntityId& firing,
                                  const net::EntityId& target, const net::EntityId& exploding,
                                  const net::EventId& event);

// Collision issued by local entity `own` against `other`: elastic for a bounce, else inelastic,
// the outcome `result` (both sides') in octet 31 (collision_outcome.hpp);
// velocity `own_vel` (local frame, before the response) and the kind's mass; the contact point
// in the issuer's body frame (x forward, y right, z down).
net::CollisionPdu collision_pdu(const world::World& w, int own, const net::EntityId& issuing,
                                const net::EntityId& colliding, const net::EventId& event, world::Result result,
                                const Vec3& own_vel, const Vec3& point);

}  // namespace npsnet::node
