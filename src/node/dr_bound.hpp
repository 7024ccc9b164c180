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

// What dr_quiet reads of a vehicle's anchor and publisher, made once per exact test (dr_quick):
// two cache lines where the two were some 350 bytes on seven, which net out's pass over every
// vehicle streams each tick (at 100,000 vehicles more than the cache). The position term is taken
// into the local frame: with e, v, a any vectors (near the solutions of J e = E, J v = the sent
// velocity, J a = the sent acceleration; kept as floats), E + J d - db = J (e + d - db_local) + rho,
// so
//   |E + J d - db| <= sigma |e + d - v s1 - a s2| + |rho|,
// sigma >= J's largest singular value (the square root of JtJ's largest row sum of magnitudes,
// times 1 + 1e-12, rounded up to a float), s1, s2 db's factors of the sent velocity and
// acceleration, and |rho| at most the residuals of the kept e, v, a (their rounding to floats
// included) times the largest s1, s2 a quiet vehicle can have (a heartbeat: since the anchor is
// at or after the last send), taken off the position threshold (pos_limit). Every other float is
// rounded the safe way: what is added to a bound up, a limit down. Its bound is not below the
// ECEF form's (sigma >= 1 here, rho added), so a vehicle may go to the exact test a tick sooner
// than with that form, and the PDUs are the same.
struct alignas(64) DrQuick {
  Vec3 p = Vec3::Zero();                        // the anchor's local position (m)
  double t = 0, last_sent = 0;                  // the anchor's state time; the last send's (s)
  Vec3f err = Vec3f::Zero();                    // ~ J^-1 E (local m)
  Vec3f vel = Vec3f::Zero(), acc = Vec3f::Zero();  // ~ J^-1 of the sent velocity, acceleration
  float sigma = 0;                              // >= |J y| / |y| for every y
  float theta = 0, turn_rate = 0;               // >= the anchor's orientation error; |sent body rates|
  float pos_limit = 0, rot_limit = 0, heartbeat_s = 0;  // <= the thresholds (pos_limit less |rho|)
  float heading = 0, pitch = 0, roll = 0;       // the anchor's (deg)
  bool usable = false;   // anchor valid, the publisher has sent, RVW, J invertible, all finite
  bool has_sent = false;  // the publisher's has_sent()
};
static_assert(sizeof(DrQuick) == 128, "DrQuick: two cache lines");
DrQuick dr_quick(const DrAnchor& a, const net::DrPublisher& pub);

// Whether the exact test at state time t is certain to say None for entity e, published by the
// publisher q was made from (q = dr_quick(anchor, publisher)).
bool dr_quiet(const DrQuick& q, const world::World& w, int e, double t);

// The exact state of e (entity_truth) and a new anchor for it, not valid until dr_rebase gives
// it its errors: against the publisher's believed pose when the state is not sent, or the new
// one after it is (the caller's choice: one rebase a test).
net::KinematicState exact_state(const world::World& w, int e, DrAnchor& a);
// The anchor's errors, of the exact state s at t, against pub's believed pose then (after a send:
// the new one). Only once pub has sent (before, the anchor stays not valid).
void dr_rebase(const net::KinematicState& s, const net::DrPublisher& pub, double t, DrAnchor& a);
// The same from what pub.test(s, t) compared when it said None (its believed pose and
// orientation error): the same anchor, without computing them again.
void dr_rebase(const net::KinematicState& s, const net::DrPublisher::Test& test, double t, DrAnchor& a);

}  // namespace npsnet::node
