// net/dead_reckoning.hpp — DIS dead reckoning (IEEE 1278.1 Annex E) and the sender's policy.
// Units: positions ECEF metres (double), velocity m/s and acceleration m/s^2 in world (ECEF)
// axes, orientation DIS Euler angles (psi, theta, phi) radians, angular velocity rad/s about the
// entity's body axes, times in seconds.
//  * dead_reckon(state, algorithm, dt) extrapolates dt seconds from `state`:
//      1 Static: pose unchanged.              2 FPW: P + V dt, orientation fixed.
//      3 RPW: P + V dt, orientation rotated by the body rates.
//      4 RVW: P + V dt + A dt^2/2, rotating.  5 FVW: P + V dt + A dt^2/2, orientation fixed.
//    0 (other) is treated as static. 6..9 are the body-axis forms (IEEE 1278.1-2012 Annex E,
//    E.6): velocity v and acceleration a are in the entity's body axes (x forward, y right,
//    z down), the body turns at the angular velocity w, so that
//      6 FPB: P + R0 v dt (orientation fixed)       9 FVB: P + R0 (v dt + a dt^2/2) (fixed)
//      7 RPB: P + R0 R1 v, orientation rotating     8 RVB: P + R0 (R1 v + R2 a), rotating
//    with R1 = integral_0^dt exp([w] s) ds and R2 = integral_0^dt s exp([w] s) ds (Annex E's
//    closed forms): an entity turning at 0.2 rad/s at 10 m/s runs on a circle of 50 m.
//    The returned Pose carries the dead-reckoned velocity too (world axes, m/s): V + A dt for
//    world forms (V for P forms), R0 exp([w] dt) (v + a dt) for body forms (no rotation for
//    F forms) — the velocity at that moment, e.g. for a collision response.
//  * DrPublisher: one per local entity. needs_update() says whether an Entity State must go out
//    now: first time, |true - dead-reckoned| position error > position_threshold_m, orientation
//    error > orientation_threshold_rad, or heartbeat_s since the last send (>=).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <limits>

#include "net/pdu.hpp"

namespace net {

enum class DrAlgorithm : std::uint8_t {
  Other = 0, Static = 1, FPW = 2, RPW = 3, RVW = 4, FVW = 5, FPB = 6, RPB = 7, RVB = 8, FVB = 9,
};

inline constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

// IEEE 1278.1-2012 Annex C defaults (shared/DIS7-NOTES.md): the one place these numbers live;
// src/ takes them from here.
namespace annex_c {
inline constexpr double kHeartbeatS = 5.0;                // Entity State heartbeat, s
inline constexpr double kTimeoutS = 12.0;                 // remote entity timeout, s
inline constexpr double kPositionThresholdM = 1.0;        // dead-reckoning position error, m
inline constexpr double kOrientationThresholdDeg = 3.0;   // dead-reckoning orientation error, deg
}  // namespace annex_c

// Annex C defaults; every threshold is configurable.
struct DrThresholds {
  double position_threshold_m = annex_c::kPositionThresholdM;
  double orientation_threshold_rad = annex_c::kOrientationThresholdDeg * kDegToRad;
  double heartbeat_s = annex_c::kHeartbeatS;
  double timeout_s = annex_c::kTimeoutS;  // remote entity dropped after this long without an update
  double blend_s = 0.5;     // remote pose converges to a corrected track over this time
};

struct Euler {
  double psi = 0, theta = 0, phi = 0;  // radians
};

struct KinematicState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();          // ECEF m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // m/s
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();      // m/s^2
  Euler orientation;                                           // rad
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s, body axes
};

struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Euler orientation;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // world (ECEF) axes, m/s
};

// Body -> world rotation Rz(psi) Ry(theta) Rx(phi), and back (theta in [-pi/2, pi/2]).
Eigen::Quaterniond to_quaternion(const Euler& e) noexcept;
Euler to_euler(const Eigen::Quaterniond& q) noexcept;
// Smallest rotation angle (radians, [0, pi]) taking one orientation to the other.
double orientation_error_rad(const Euler& a, const Euler& b) noexcept;

Pose dead_reckon(const KinematicState& s, DrAlgorithm algorithm, double dt_s) noexcept;
// Algorithm octet from the wire (values > 9 are treated as 0, static).
DrAlgorithm dr_algorithm_from_wire(std::uint8_t v) noexcept;

// Conversions between the wire struct and the kinematic state (floats <-> doubles).
KinematicState kinematic_state(const EntityStatePdu& p) noexcept;
void write_kinematics(const KinematicState& s, DrAlgorithm algorithm, EntityStatePdu& p) noexcept;

class DrPublisher {
 public:
  enum class Reason : std::uint8_t { None, First, Position, Orientation, Heartbeat };

  explicit DrPublisher(DrAlgorithm algorithm = DrAlgorithm::RVW, DrThresholds t = {}) noexcept
      : algorithm_(algorithm), thresholds_(t) {}

  // Why an update is due at now_s given the entity's true state, or Reason::None.
  Reason needs_update(const KinematicState& truth, double now_s) const noexcept { return test(truth, now_s).reason; }
  // The same test and what it compared: the believed pose at now_s (once sent) and the
  // orientation error against it (rad; NaN when the position alone decided).
  struct Test {
    Reason reason = Reason::First;
    Pose believed;
    double orientation_error_rad = std::numeric_limits<double>::quiet_NaN();
  };
  Test test(const KinematicState& truth, double now_s) const noexcept;
  // Record that `sent` went out at now_s (call after sending the ESPDU).
  void mark_sent(const KinematicState& sent, double now_s) noexcept;
  // What receivers currently believe (the dead-reckoned last sent state at now_s).
  Pose believed_pose(double now_s) const noexcept;

  DrAlgorithm algorithm() const noexcept { return algorithm_; }
  const DrThresholds& thresholds() const noexcept { return thresholds_; }
  bool has_sent() const noexcept { return has_sent_; }
  // The state last sent, as receivers hold it (floats where the wire has floats).
  const KinematicState& sent_state() const noexcept { return sent_; }
  double last_sent_s() const noexcept { return last_sent_s_; }

 private:
  DrAlgorithm algorithm_;
  DrThresholds thresholds_;
  KinematicState sent_;
  double last_sent_s_ = 0;
  bool has_sent_ = false;
};

}  // namespace net
