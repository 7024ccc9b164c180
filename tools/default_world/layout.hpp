// The default world's layout: map size and posts, water level, lake, proving-ground reserve, and
// the targets the objects are placed to (make_default_world.cpp describes the world they make).
// Units: metres as double; names ending in Cm are whole centimetres (int64_t), the objects' grid.
// Invariants: kPosts = kSquares * kPostsPerSquare + 1 posts a side, kSpacing * (kPosts - 1) =
// kWorld; the thesis's numbers come from core/constants.hpp (npsnet::thesis, alias th) only.
#pragma once
#include <cstdint>

#include "core/constants.hpp"

namespace npsnet::default_world {

namespace th = npsnet::thesis;

// --- World layout ------------------------------------------------------------------------------
constexpr int kSquares = th::kGridsquaresPerSide;             // 400 per side
constexpr double kWorld = th::kWorldSizeM;                    // 50 km
constexpr int kPostsPerSquare = 2;                            // posts every half gridsquare
constexpr int kPosts = kSquares * kPostsPerSquare + 1;        // 801
constexpr double kSpacing = th::kGridsquareM / kPostsPerSquare;  // 62.5 m
constexpr int64_t kSquareCm = static_cast<int64_t>(th::kGridsquareM * 100);  // 12500
constexpr int64_t kWorldCm = static_cast<int64_t>(kWorld * 100);
constexpr int64_t kEdgeMarginCm = 150;                        // objects stay > 1 m from the edge

constexpr double kWaterLevelM = 200.0;                        // scenario water_level_m
constexpr double kDryMarginM = 1.5;                           // objects stand >= 201.5 m

constexpr double kLandLowM = 215.0, kLandHighM = 600.0;       // land outside the lake
constexpr double kLakeX = 25000, kLakeY = 25000;              // lake centre
constexpr double kLakeSemiX = 3000, kLakeSemiY = 2000;        // 6 km x 4 km
constexpr double kLakeBottomM = 185.0;
constexpr double kLakeShoreBlendM = 2500;                     // shore rises into the hills

constexpr double kReserveX0 = 2000, kReserveX1 = 14000;       // proving ground reserve
constexpr double kReserveY0 = 2000, kReserveY1 = 8000;
constexpr double kReserveFlatMarginM = 500;                   // flat this far around it
constexpr double kReserveBlendM = 3000;                       // then blends into the hills

constexpr int kOccupiedTarget = 10335;  // 40303 / 10335 = 3.8997 -> 3.9 per occupied square
constexpr int kForests = 90;
constexpr double kMinSpacingM = 3.0;    // between objects in one gridsquare

constexpr uint64_t kSeed = 19910601;

}  // namespace npsnet::default_world
