// Bounds of the numbers a scenario, kinds file, objects file or model may hold. Loaders (and so
// `npsnet check`) reject anything outside them, so that a run never meets a value it cannot use:
// floats that overflow to inf, tick counts that overflow, positions that leave every map.
#pragma once

namespace npsnet::world {

inline constexpr double kMaxDurationS = 1e7;     // run length (s, ~116 days): 1e9 ticks at dt 0.01
inline constexpr double kMaxSpeedKmh = 50000.0;  // any speed (km/h, ~14 km/s: above every munition)
inline constexpr double kMaxHeightM = 100000.0;  // |height| of a position, water level, origin (m)
inline constexpr double kMaxHeadingDeg = 360.0;  // |heading| (deg)
inline constexpr double kMaxSizeM = 10000.0;     // radii, blast and crater sizes, model coordinates (m)
inline constexpr double kMaxMassKg = 1e9;
inline constexpr double kMaxCount = 1e6;         // rounds, fuel litres, resistance

}  // namespace npsnet::world
