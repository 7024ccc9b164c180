// Math types for the node: doubles for world positions, floats where precision allows.
// Threading: types and pure functions only; core/ holds no state.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "core/trig.hpp"

namespace npsnet {
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec3f = Eigen::Vector3f;
using Mat3 = Eigen::Matrix3d;

inline constexpr double kPi = std::numbers::pi;
inline constexpr double deg2rad(double d) { return d * kPi / 180.0; }
inline constexpr double rad2deg(double r) { return r * 180.0 / kPi; }
inline constexpr double kmh2mps(double v) { return v / 3.6; }
inline constexpr double mps2kmh(double v) { return v * 3.6; }

// Wrap an angle in degrees to [0, 360). An angle already in range is returned as it is (what
// fmod gives for it, -0 included: the same bits without the libm call of the hot loops); one
// within a turn below or above gets deg + 360 or deg - 360, as fmod's exact remainder (deg itself
// for |deg| < 360; deg - 360, exact for deg in [360, 720) by Sterbenz's lemma) then gives.
inline double wrap360(double deg) {
  if (deg >= 0.0 && deg < 360.0) return deg;
  if (deg > -360.0 && deg < 0.0) return deg + 360.0;
  if (deg >= 360.0 && deg < 720.0) return deg - 360.0;
  double r = std::fmod(deg, 360.0);
  return r < 0 ? r + 360.0 : r;
}
// An angle in degrees wrapped to [-180, 180], the short way round (for a difference of two
// angles): std::remainder's exact result, an angle already within (-180, 180) as it is (what
// remainder gives for it, without the libm call of the hot loops). NaN and infinities: NaN.
inline double wrap180(double deg) { return std::abs(deg) < 180.0 ? deg : std::remainder(deg, 360.0); }
// Compass heading (0 = north = +y, 90 = east = +x) to a unit vector in the local frame, and back,
// with core/trig.hpp's sincos and atan2 (every vehicle, every tick).
inline Vec2 heading_to_dir(double heading_deg) {
  const SinCos v = sincos_deg(heading_deg);
  return {v.s, v.c};
}
inline double dir_to_heading(const Vec2& d) { return wrap360(rad2deg(atan2_rad(d.x(), d.y()))); }
inline bool finite(const Vec3& v) { return v.allFinite(); }
}  // namespace npsnet
