// A local-frame bound on a local vehicle's dead-reckoning error, so that net out turns a vehicle
// into ECEF / DIS terms (transverse Mercator inverse, geodesy: the costly part) only when its
// Entity State may be due (issue 13). Exactly equivalent, not approximate: dr_quiet() says true
// only when the exact test, net::DrPublisher::needs_update(entity_truth(w, e), t), is certain to
// say None; otherwise the caller does the exact test. So the vehicles sent, and the bytes sent,
// are those of computing every vehicle's ECEF state every tick (BridgeOptions::dr_prefilter =
// false, the reference tests/node/test_dr_bound.cpp compares with).
//
// How: at every exact test of a vehicle (exact_state()) we keep an anchor: its local position p_c
// (m), the exact position error vector E_c = truth - believed (ECEF m), the Jacobian J of the
// local -> ECEF map F at p_c (geo::LocalFrame::jacobian), the exact orientation error theta_c
// (rad) and its heading, pitch, roll (deg). Later, at local position p (d = p - p_c) and time t:
//  * position: |F(p) - B(t)| <= |E_c + J d - (B(t) - B(t_c))| + K |d|^2 / 2 + K |d| + eps,
//    B = the believed (dead-reckoned, RVW) ECEF position, K = kCurvaturePerM, a bound on F's
//    second derivative (the Earth's curvature ~1.6e-7 /m and the projection's, with a margin of
//    about 20; the K |d| term, kept from when J was a 1 m finite difference, is now margin);
//  * orientation (the angle between rotations is a metric, invariant on both sides):
//    err(t) <= theta_c + |w| (t - t_c) + |dheading| + |dpitch| + |droll| + Kf |d| + eps,
//    w = the sent body rates (the believed orientation turns by |w| dt), Kf = kFrameTurnPerM
//    bounds how far the local level frame and the grid convergence turn per metre travelled.
//  * quiet only when both bounds are below the thresholds, the heartbeat is not due, the
//    algorithm is RVW and |d| <= kMaxAnchorDistM. tests/node/test_dr_bound.cpp checks K and Kf
//    on the default world's frame and that a crowd sends the same PDUs with and without it.
// Units: local frame metres and m/s, ECEF metres, seconds, radians (angles stored in degrees
// where the world keeps them).
#pragma once
#include "core/math.hpp"
#include "net/dead_reckoning.hpp"
#include "world/world.hpp"

namespace npsnet::node {

inline constexpr double kCurvaturePerM = 1e-5;   // K: bound on |F''| (1/m)
inline constexpr double kFrameTurnPerM = 1e-5;   // Kf: turn of the level frame + convergence (rad/m)
inline constexpr double kMaxAnchorDistM = 500.0;  // farther than this from the anchor: exact test
inline constexpr double kBoundEpsM = 1e-4, kBoundEpsRad = 1e-5;  // rounding margins

struct DrAnchor {
  Mat3 jac = Mat3::Zero();  // ECEF m per local m at p
  Vec3 p = Vec3::Zero();    // local position of the exact test (m)
  Vec3 err = Vec3::Zero();  // ECEF truth - believed position then (m)
  double t = 0;             // its state time (s)
  double theta = 0;         // its orientation error (rad)
  float heading = 0, pitch = 0, roll = 0;  // deg
  bool valid = false;
};

// Whether the exact test at state time t is certain to say None for entity e, published by pub.
bool dr_quiet(const DrAnchor& a, const net::DrPublisher& pub, const world::World& w, int e, double t);

// The exact state of e (entity_truth) and a new anchor for it, not valid until dr_rebase gives
// it its errors: against the publisher's believed pose when the state is not sent, or the new
// one after it is (the caller's choice: one rebase a test).
net::KinematicState exact_state(const world::World& w, int e, DrAnchor& a);
// The anchor's errors, of the exact state s at t, against pub's believed pose then (after a send:
// the new one). Only once pub has sent (before, the anchor stays not valid).
void dr_rebase(const net::KinematicState& s, const net::DrPublisher& pub, double t, DrAnchor& a);

}  // namespace npsnet::node
