// A vehicle driven by its player (shared/ARCHITECTURE.md, "Player"), one fixed step at a time,
// within its kind's Table 2 limit (or the scenario's override, Entities::max_mps). Controls are
// -1..1: throttle (+ forward), steer (+ right), climb (+ up). Handling per kind (kinds.toml):
// accel_mps2, brake_mps2, turn_radius_m, climb_mps, fuel_lph.
//  - ground: throttle accelerates, or brakes while moving the other way, then reverses (at most
//    kReverseFraction of the limit); no throttle coasts to a stop at kCoastMps2; steer turns on a
//    circle of turn_radius_m / |steer| (yaw rate at most kGroundYawDps); keeps to the terrain
//    (follow_terrain) and off the water (stops at the shore).
//  - ship: the same on water only (stops at the shore), at the water level.
//  - air: throttle changes airspeed (no reverse; no throttle holds it), climb sets the vertical
//    speed (climb_mps at full), steer banks (kMaxBankDeg at full) and the bank turns the craft
//    (g tan(bank) / speed, at most kAirYawDps). Nothing holds it above the ground: meeting the
//    terrain is a Crash (collision::ground_contact decides the outcome); resting on it is not.
// Fuel: fuel_lph x (speed / limit) litres per hour; an empty tank gives no thrust (a ground
// vehicle or ship coasts to a stop, an aircraft slows and sinks). A kind with no fuel_l never
// runs dry. A wreck does not move.
#pragma once
#include <vector>

#include "world/world.hpp"

namespace npsnet::dynamics {

inline constexpr double kReverseFraction = 0.25;   // reverse speed limit / forward limit
inline constexpr double kCoastMps2 = 0.6;          // ground: rolling to a stop, m/s^2
inline constexpr double kShipCoastMps2 = 0.05;     // ship: drifting to a stop, m/s^2
inline constexpr double kGroundYawDps = 45.0;      // pivot-steer limit of a tracked vehicle, deg/s
inline constexpr double kMaxBankDeg = 45.0;        // aircraft bank at full steer
inline constexpr double kBankRateDps = 90.0;       // how fast the bank follows the stick
inline constexpr double kAirYawDps = 30.0;
inline constexpr double kAirTurnMinSpeedMps = 20.0;  // below it the turn rate is that of this speed
inline constexpr double kDryAirSinkMps = 5.0;      // an aircraft with an empty tank sinks this fast

struct Controls {
  double throttle = 0, steer = 0, climb = 0;  // each -1..1
};

// A driven aircraft that met the terrain this step (it was above the ground before it).
struct Crash {
  int entity = -1;
  Vec3 point{0, 0, 0};
  double speed_mps = 0;  // its speed at the contact
};

void drive(world::World& w, int e, const Controls& c, double dt, std::vector<Crash>& crashes);

// Burns the fuel for moving at speed_mps for dt (fuel_lph x speed / limit). False when the tank
// is empty (after this step's burn); always true for a kind without fuel.
bool burn_fuel(world::World& w, int e, double speed_mps, double dt);

// Where the driven vehicle's weapon points: the nearest live vehicle within kAimConeDeg of its
// nose and kAimRangeM (target = that entity, point = its centre), else where the line of its nose
// meets the terrain within kAimRangeM, else the ground below that line's end (target = -1).
inline constexpr double kAimConeDeg = 4.0;
inline constexpr double kAimRangeM = 3000.0;
struct Aim {
  Vec3 point{0, 0, 0};
  int target = -1;
};
Aim aim_from(const world::World& w, int e);

}  // namespace npsnet::dynamics
