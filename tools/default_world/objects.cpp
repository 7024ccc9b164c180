// Placement of the default world's fixed objects (objects.hpp): the special objects (telephone
// poles along a road, a hamlet, bunkers, rocks), the forests' trees and bushes, and the counts
// per gridsquare that Table 1 gives.
#include "default_world/objects.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "default_world/random.hpp"
#include "default_world/terrain.hpp"
#include "default_world/weight_tree.hpp"

namespace npsnet::default_world {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error("generator invariant failed: " + what);
}

bool in_reserve(double x, double y) {
  return x >= kReserveX0 && x <= kReserveX1 && y >= kReserveY0 && y <= kReserveY1;
}

namespace {

int square_of(int64_t cm) { return static_cast<int>(cm / kSquareCm); }

bool dry(const std::vector<float>& h, double x, double y) {
  return height_at(h, x, y) >= kWaterLevelM + kDryMarginM;
}

bool inside_margin(int64_t x_cm, int64_t y_cm) {
  return x_cm >= kEdgeMarginCm && y_cm >= kEdgeMarginCm && x_cm <= kWorldCm - kEdgeMarginCm &&
         y_cm <= kWorldCm - kEdgeMarginCm;
}

// The road the telephone poles follow: a polyline in metres.
const std::vector<std::array<double, 2>> kRoad = {{31000, 9000}, {32500, 10200}, {33600, 11800}, {35400, 12600}};

double distance_to_road(double x, double y) {
  double best = 1e300;
  for (size_t k = 0; k + 1 < kRoad.size(); ++k) {
    const double ax = kRoad[k][0], ay = kRoad[k][1], bx = kRoad[k + 1][0], by = kRoad[k + 1][1];
    const double vx = bx - ax, vy = by - ay;
    const double t = std::clamp(((x - ax) * vx + (y - ay) * vy) / (vx * vx + vy * vy), 0.0, 1.0);
    const double dx = x - (ax + t * vx), dy = y - (ay + t * vy);
    best = std::min(best, std::sqrt(dx * dx + dy * dy));
  }
  return best;
}

int64_t to_cm(double m) { return static_cast<int64_t>(std::nearbyint(m * 100.0)); }

// Compass heading in tenths of a degree of the direction (dx, dy).
int heading_tenths(double dx, double dy) {
  double deg = std::atan2(dx, dy) * 180.0 / 3.14159265358979323846;
  if (deg < 0) deg += 360.0;
  return static_cast<int>(std::nearbyint(deg * 10.0)) % 3600;
}

// Telephone poles along the road, buildings and the water tower in a hamlet at its bend, bunkers
// on a ridge, rocks scattered over dry land.
std::vector<Object> special_objects(const std::vector<float>& h, Rng& rng) {
  std::vector<Object> out;
  auto add = [&](Kind k, double x, double y, int heading) {
    const Object o{k, to_cm(x), to_cm(y), heading};
    require(inside_margin(o.x_cm, o.y_cm), "special object inside the map");
    require(dry(h, o.x_cm / 100.0, o.y_cm / 100.0), std::string(kKindName[k]) + " on dry land");
    require(!in_reserve(o.x_cm / 100.0, o.y_cm / 100.0), "special object outside the reserve");
    out.push_back(o);
  };
  // Poles every 60 m, 8 m to the right of the road's centreline.
  const double spacing = 60.0, offset = 8.0;
  double along = 100.0;
  int poles = 0;
  for (size_t k = 0; k + 1 < kRoad.size() && poles < th::kTable1TelephonePoles; ++k) {
    const double ax = kRoad[k][0], ay = kRoad[k][1], bx = kRoad[k + 1][0], by = kRoad[k + 1][1];
    const double len = std::sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
    const double ux = (bx - ax) / len, uy = (by - ay) / len;
    for (; along <= len && poles < th::kTable1TelephonePoles; along += spacing, ++poles)
      add(kPole, ax + ux * along + uy * offset, ay + uy * along - ux * offset, heading_tenths(ux, uy));
    along -= len;
  }
  require(poles == th::kTable1TelephonePoles, "all telephone poles fit along the road");
  // Hamlet at the road's second bend, west of the road.
  const double hx = kRoad[2][0], hy = kRoad[2][1];
  const int road_heading = heading_tenths(kRoad[3][0] - hx, kRoad[3][1] - hy);
  const std::array<std::array<double, 2>, th::kTable1Buildings> houses = {{{-45, 30}, {-70, -15}, {-30, 75}}};
  for (const auto& o : houses) add(kBuilding, hx + o[0], hy + o[1], road_heading);
  add(kWatertower, hx - 110, hy + 40, 0);
  // Bunkers on a line along a ridge north-east of the lake.
  for (int b = 0; b < th::kTable1OtherManMade; ++b) add(kBunker, 38000 + 180.0 * b, 34000 + 60.0 * b, 1350);
  // Rocks: anywhere on dry land outside the reserve.
  for (int r = 0; r < th::kTable1OtherNatural;) {
    const double x = rng.uniform(1000, kWorld - 1000), y = rng.uniform(1000, kWorld - 1000);
    if (!dry(h, x, y) || reserve_distance(x, y) < 200 || distance_to_road(x, y) < 50) continue;
    add(kRock, x, y, static_cast<int>(rng.range(0, 3599)));
    ++r;
  }
  return out;
}

}  // namespace

Stats square_stats(const std::vector<Object>& objs) {
  std::vector<int> count(static_cast<size_t>(kSquares) * kSquares, 0);
  for (const auto& o : objs) ++count[static_cast<size_t>(square_of(o.y_cm)) * kSquares + square_of(o.x_cm)];
  Stats s;
  s.min_per_square = *std::min_element(count.begin(), count.end());
  s.max_per_square = *std::max_element(count.begin(), count.end());
  s.occupied = static_cast<int>(std::count_if(count.begin(), count.end(), [](int c) { return c > 0; }));
  s.average = static_cast<double>(objs.size()) / s.occupied;
  return s;
}

std::vector<Object> make_objects(const std::vector<float>& h) {
  Rng rng(kSeed);
  std::vector<Object> objs = special_objects(h, rng);
  const size_t n_sq = static_cast<size_t>(kSquares) * kSquares;
  std::vector<int> special_count(n_sq, 0);
  for (const auto& o : objs) ++special_count[static_cast<size_t>(square_of(o.y_cm)) * kSquares + square_of(o.x_cm)];
  const int special_squares =
      static_cast<int>(std::count_if(special_count.begin(), special_count.end(), [](int c) { return c > 0; }));

  // Squares where vegetation may grow: every bilinear cell of the square dry, clear of the
  // reserve (with one square of margin), of the road and of the special objects' squares.
  std::vector<unsigned char> eligible(n_sq, 0);
  for (int gy = 0; gy < kSquares; ++gy)
    for (int gx = 0; gx < kSquares; ++gx) {
      const size_t g = static_cast<size_t>(gy) * kSquares + gx;
      float lowest = 1e30f;
      for (int dj = 0; dj <= kPostsPerSquare; ++dj)
        for (int di = 0; di <= kPostsPerSquare; ++di)
          lowest = std::min(lowest, post(h, gx * kPostsPerSquare + di, gy * kPostsPerSquare + dj));
      const double cx = (gx + 0.5) * th::kGridsquareM, cy = (gy + 0.5) * th::kGridsquareM;
      eligible[g] = lowest >= kWaterLevelM + kDryMarginM && special_count[g] == 0 &&
                    reserve_distance(cx, cy) > th::kGridsquareM &&
                    distance_to_road(cx, cy) > th::kGridsquareM;
    }

  // Forest density: smooth bumps of random size and strength.
  struct Forest {
    double x, y, r, s;
  };
  std::vector<Forest> forests;
  while (static_cast<int>(forests.size()) < kForests) {
    const Forest f{rng.uniform(0, kWorld), rng.uniform(0, kWorld), rng.uniform(600, 2400), rng.uniform(0.5, 1.0)};
    const int gx = static_cast<int>(f.x / th::kGridsquareM), gy = static_cast<int>(f.y / th::kGridsquareM);
    if (eligible[static_cast<size_t>(gy) * kSquares + gx]) forests.push_back(f);
  }
  std::vector<double> density(n_sq, 0.0);
  for (const auto& f : forests) {
    const int g0x = std::max(0, static_cast<int>((f.x - f.r) / th::kGridsquareM));
    const int g1x = std::min(kSquares - 1, static_cast<int>((f.x + f.r) / th::kGridsquareM));
    const int g0y = std::max(0, static_cast<int>((f.y - f.r) / th::kGridsquareM));
    const int g1y = std::min(kSquares - 1, static_cast<int>((f.y + f.r) / th::kGridsquareM));
    for (int gy = g0y; gy <= g1y; ++gy)
      for (int gx = g0x; gx <= g1x; ++gx) {
        const double dx = (gx + 0.5) * th::kGridsquareM - f.x, dy = (gy + 0.5) * th::kGridsquareM - f.y;
        const double q = (dx * dx + dy * dy) / (f.r * f.r);
        if (q < 1.0) density[static_cast<size_t>(gy) * kSquares + gx] += f.s * (1 - q) * (1 - q);
      }
  }
  // Ragged forest edges and clearings: modulate by value noise of ~1 km.
  for (int gy = 0; gy < kSquares; ++gy)
    for (int gx = 0; gx < kSquares; ++gx) {
      const double m = 0.6 + 0.7 * value_noise((gx + 0.5) * th::kGridsquareM / 900.0,
                                               (gy + 0.5) * th::kGridsquareM / 900.0, 77);
      density[static_cast<size_t>(gy) * kSquares + gx] *= std::clamp(m, 0.0, 1.2);
    }

  // Occupied squares: the highest-scoring eligible squares (forests, ragged at the edges, and a
  // few lone trees and bushes elsewhere).
  std::vector<double> score(n_sq, -1.0);
  std::vector<size_t> candidates;
  for (size_t g = 0; g < n_sq; ++g) {
    const double u = rng.uniform(), v = rng.uniform();
    if (!eligible[g]) continue;
    score[g] = density[g] * (0.3 + 0.7 * u) + 0.05 * v * v * v;
    candidates.push_back(g);
  }
  const int n_veg_squares = kOccupiedTarget - special_squares;
  require(static_cast<int>(candidates.size()) >= n_veg_squares, "enough eligible squares");
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](size_t a, size_t b) { return score[a] > score[b]; });
  candidates.resize(n_veg_squares);
  std::sort(candidates.begin(), candidates.end());  // back to map order

  // Objects per square: one each, the rest drawn in proportion to forest density, at most
  // the thesis's maximum per square.
  const int n_veg = th::kTable1Trees + th::kTable1Bushes;
  std::vector<int> count(candidates.size(), 1);
  std::vector<double> weight(candidates.size());
  for (size_t c = 0; c < candidates.size(); ++c) {
    const double d = std::min(density[candidates[c]], 1.5);
    weight[c] = d + 0.02;
  }
  WeightTree tree(weight);
  for (int placed = static_cast<int>(candidates.size()); placed < n_veg;) {
    const size_t c = tree.find(rng.uniform() * tree.total());
    if (tree.weight(c) <= 0.0) continue;  // a rounding edge landed on a full square
    if (++count[c] == th::kTable1MaxPerGridsquare) tree.set(c, 0.0);
    ++placed;
  }
  // Make sure the maximum is reached: top up the fullest square from the sparsest multi-object one.
  for (;;) {
    const auto full = std::max_element(count.begin(), count.end());
    if (*full >= th::kTable1MaxPerGridsquare) break;
    size_t donor = count.size();
    for (size_t c = 0; c < count.size(); ++c)
      if (count[c] > 1 && &count[c] != &*full && (donor == count.size() || weight[c] < weight[donor])) donor = c;
    require(donor < count.size(), "a donor square");
    --count[donor];
    ++*full;
  }

  // Trees or bushes: bushes where the forest is thin.
  struct Slot {
    size_t c;
    double key;
  };
  std::vector<Slot> slots;
  slots.reserve(n_veg);
  for (size_t c = 0; c < candidates.size(); ++c)
    for (int k = 0; k < count[c]; ++k) slots.push_back({c, density[candidates[c]] + 0.35 * rng.uniform()});
  std::vector<size_t> order(slots.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return slots[a].key < slots[b].key; });
  std::vector<Kind> kind(slots.size(), kTree);
  for (int b = 0; b < th::kTable1Bushes; ++b) kind[order[b]] = kBush;

  // Positions: uniform in the square (centimetres), at least kMinSpacingM apart within it.
  size_t s = 0;
  std::vector<std::array<int64_t, 2>> here;
  const int64_t min_d2 = to_cm(kMinSpacingM) * to_cm(kMinSpacingM);
  for (size_t c = 0; c < candidates.size(); ++c) {
    const int gx = static_cast<int>(candidates[c] % kSquares), gy = static_cast<int>(candidates[c] / kSquares);
    const int64_t x0 = std::max<int64_t>(gx * kSquareCm + 1, kEdgeMarginCm);
    const int64_t x1 = std::min<int64_t>((gx + 1) * kSquareCm - 1, kWorldCm - kEdgeMarginCm);
    const int64_t y0 = std::max<int64_t>(gy * kSquareCm + 1, kEdgeMarginCm);
    const int64_t y1 = std::min<int64_t>((gy + 1) * kSquareCm - 1, kWorldCm - kEdgeMarginCm);
    here.clear();
    for (int k = 0; k < count[c]; ++k, ++s) {
      int64_t x = 0, y = 0;
      for (int attempt = 0;; ++attempt) {
        require(attempt < 1000, "room for the objects of a square");
        x = rng.range(x0, x1), y = rng.range(y0, y1);
        bool clear = true;
        for (const auto& p : here) clear = clear && (p[0] - x) * (p[0] - x) + (p[1] - y) * (p[1] - y) >= min_d2;
        if (clear) break;
      }
      here.push_back({x, y});
      require(dry(h, x / 100.0, y / 100.0) && !in_reserve(x / 100.0, y / 100.0), "vegetation placement");
      objs.push_back({kind[s], x, y, static_cast<int>(rng.range(0, 3599))});
    }
  }
  // Kind order, then generation order.
  std::stable_sort(objs.begin(), objs.end(), [](const Object& a, const Object& b) { return a.kind < b.kind; });
  return objs;
}

}  // namespace npsnet::default_world
