// The default world's fixed objects: the seven kinds of the thesis's Table 1 and their placement.
// Units: positions in whole centimetres (x east, y north from the SW corner), headings in tenths
// of a degree (compass, 0..3599). make_objects places exactly Table 1's count of each kind,
// sorted by kind; none stands in water, in the reserve or within 1 m of the map edge; the same
// heights give the same objects on every platform. require() throws std::runtime_error.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "default_world/layout.hpp"

namespace npsnet::default_world {

// --- Objects -------------------------------------------------------------------------------------
enum Kind { kTree, kBush, kPole, kBuilding, kWatertower, kBunker, kRock, kKinds };
constexpr std::array<const char*, kKinds> kKindName = {"tree",     "bush",       "telephone_pole",
                                                       "building", "watertower", "bunker", "rock"};
constexpr std::array<char, kKinds> kIdPrefix = {'T', 'B', 'P', 'H', 'W', 'K', 'R'};
constexpr std::array<int, kKinds> kKindCount = {
    th::kTable1Trees,       th::kTable1Bushes,     th::kTable1TelephonePoles, th::kTable1Buildings,
    th::kTable1Watertowers, th::kTable1OtherManMade, th::kTable1OtherNatural};

struct Object {
  Kind kind;
  int64_t x_cm, y_cm;
  int heading_tenths;  // 0..3599
};

// Throws std::runtime_error("generator invariant failed: " + what) unless ok.
void require(bool ok, const std::string& what);
// Whether (x, y) (m) lies in the proving-ground reserve.
bool in_reserve(double x, double y);

// Table 1's objects on the heights h (make_heights): kind order, then generation order.
std::vector<Object> make_objects(const std::vector<float>& h);

struct Stats {
  int occupied = 0, max_per_square = 0, min_per_square = 0;
  double average = 0;
};

// Objects per gridsquare over all kSquares * kSquares squares; average is per occupied square.
Stats square_stats(const std::vector<Object>& objs);

}  // namespace npsnet::default_world
