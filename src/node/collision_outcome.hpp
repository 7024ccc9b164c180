// The outcome of a cross-node collision travels in its Collision PDU (issue 11), so the colliding
// entity's owner never reads it from the issuer's Entity State (lost, or overtaken by the
// Collision PDU under jitter: kills arrived as stops).
//  * Where: octet 31 of the Collision PDU, the padding octet after the collision type
//    (net::CollisionPdu::padding; DIS7-NOTES.md "Collision"). 0 = not stated (every other
//    simulator: padding is zero when sent and ignored when received, so they are unaffected;
//    tshark shows it as padding, open-dis reads it into `pad`), 1 = bounce, 2 = stop, 3 = kill.
//    The collision type keeps its standard meaning: 1 elastic for a bounce, 0 inelastic else.
//  * Why not derived by the receiver from the PDU: Figure 8's kill/stop test compares the closing
//    speed (both velocities along the contact normal) with 5 m/s and its band test compares both
//    headings; the decider reads the receiver's vehicle from its dead-reckoned copy, the receiver
//    its exact state, so near a threshold the two nodes would decide differently.
//  * Reading: a stated outcome that agrees with the collision type (bounce with elastic, stop or
//    kill with inelastic) is the outcome; anything else (0, another simulator's PDU, a corrupt
//    octet) falls back to: elastic = bounce; inelastic = kill when the issuer's appearance reads
//    destroyed, else stop.
#pragma once
#include <cstdint>

#include "net/pdu.hpp"
#include "world/changes.hpp"

namespace npsnet::node {

inline constexpr std::uint8_t kOutcomeUnstated = 0, kOutcomeBounce = 1, kOutcomeStop = 2, kOutcomeKill = 3;

// Collision type and outcome octet of a collision whose outcome (for the colliding entity) is r:
// Bounce, Stop or Kill (any other result is sent as an unstated inelastic collision).
void set_outcome(net::CollisionPdu& p, world::Result r);
// The outcome a receiver applies (see above); issuer_appearance: the issuer's last appearance.
world::Result outcome_of(const net::CollisionPdu& p, std::uint32_t issuer_appearance);

}  // namespace npsnet::node
