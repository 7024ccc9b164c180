// make_default_world: writes the bundled default world, deterministically.
//
//   Regenerate the committed files (from the repository root, after building the target
//   `make_default_world`):
//       build/tools/make_default_world terrain
//   It writes terrain/default.tif and terrain/default-objects.csv and prints their statistics.
//
// default.tif: 50 km x 50 km, 801 x 801 Float32 posts at 62.5 m (half a 125 m gridsquare), no
// coordinate system (local metres, x east, y north; the scenario places the SW corner at
// origin_geodetic), DEFLATE + floating-point predictor. Rolling hills (value noise, ~215-600 m),
// an elliptical lake 6 km x 4 km centred at (25 km, 25 km) whose bottom (185 m) lies 15 m below
// the 200 m water level, and a flat "proving ground" reserve x in [2, 14] km, y in [2, 8] km
// (250-270 m, slope < 3 deg) kept free of objects for hand-placed test cases.
//
// default-objects.csv: `id,kind,x_m,y_m,heading_deg`, one fixed object a line, reproducing the
// thesis's Table 1 (Osborne 1991, p. 10) exactly: the count of each kind, 0 and 18 objects as the
// minimum and maximum per 125 m gridsquare, and 3.9 objects on average per occupied gridsquare.
// Trees and bushes grow in forests (bushes toward their edges), 54 telephone poles follow a road,
// and no object stands in water, in the reserve, or within 1 m of the map edge.
//
// Only integer arithmetic, + - * / and sqrt (all exactly rounded in IEEE 754) decide the output,
// and the random numbers come from our own xoshiro256**, so the files are the same on every
// platform. The one transcendental call (atan2, for telephone-pole headings) is rounded to 0.1
// degree before it is written.
#include <gdal.h>
#include <cpl_string.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/constants.hpp"

namespace {

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

// --- Random numbers: xoshiro256** seeded by splitmix64 ---------------------------------------
uint64_t splitmix64(uint64_t& s) {
  uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

class Rng {
 public:
  explicit Rng(uint64_t seed) {
    for (auto& w : s_) w = splitmix64(seed);
  }
  uint64_t next() {
    const uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Integer in [lo, hi], unbiased (rejection).
  int64_t range(int64_t lo, int64_t hi) {
    const uint64_t span = static_cast<uint64_t>(hi - lo) + 1;
    const uint64_t limit = UINT64_MAX - UINT64_MAX % span;
    uint64_t r;
    do r = next();
    while (r >= limit);
    return lo + static_cast<int64_t>(r % span);
  }

 private:
  static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::array<uint64_t, 4> s_{};
};

// --- Value noise (integer hash lattice, quintic fade) -------------------------------------------
double lattice(int64_t ix, int64_t iy, uint64_t octave) {
  uint64_t h = kSeed ^ (static_cast<uint64_t>(ix) * 0x9E3779B97F4A7C15ull) ^
               (static_cast<uint64_t>(iy) * 0xC2B2AE3D27D4EB4Full) ^ (octave * 0x165667B19E3779F9ull);
  h = splitmix64(h);
  return static_cast<double>(h >> 11) * 0x1.0p-52 - 1.0;  // [-1, 1)
}

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

double value_noise(double x, double y, uint64_t octave) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<int64_t>(fx), iy = static_cast<int64_t>(fy);
  const double u = fade(x - fx), v = fade(y - fy);
  const double a = lattice(ix, iy, octave), b = lattice(ix + 1, iy, octave);
  const double c = lattice(ix, iy + 1, octave), d = lattice(ix + 1, iy + 1, octave);
  return (a + (b - a) * u) * (1 - v) + (c + (d - c) * u) * v;
}

double hills(double x, double y) {
  constexpr std::array<double, 6> wavelength = {16000, 8000, 4000, 2000, 1000, 500};
  constexpr std::array<double, 6> amplitude = {1.0, 0.6, 0.4, 0.25, 0.12, 0.06};
  double n = 0;
  for (size_t k = 0; k < wavelength.size(); ++k)
    n += amplitude[k] * value_noise(x / wavelength[k] + 0.37 * k, y / wavelength[k] + 0.61 * k, k);
  return n;
}

double smoother(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return fade(t);
}

double reserve_distance(double x, double y) {
  const double dx = std::max({kReserveX0 - x, 0.0, x - kReserveX1});
  const double dy = std::max({kReserveY0 - y, 0.0, y - kReserveY1});
  return std::sqrt(dx * dx + dy * dy);
}

// --- Terrain -------------------------------------------------------------------------------------
std::vector<float> make_heights() {
  std::vector<double> n(static_cast<size_t>(kPosts) * kPosts);
  for (int j = 0; j < kPosts; ++j)
    for (int i = 0; i < kPosts; ++i) n[static_cast<size_t>(j) * kPosts + i] = hills(i * kSpacing, j * kSpacing);
  const auto [lo, hi] = std::minmax_element(n.begin(), n.end());
  const double nlo = *lo, nhi = *hi;
  std::vector<float> h(n.size());
  for (int j = 0; j < kPosts; ++j) {
    for (int i = 0; i < kPosts; ++i) {
      const double x = i * kSpacing, y = j * kSpacing;
      const size_t k = static_cast<size_t>(j) * kPosts + i;
      // Rolling hills; squaring part of the range flattens the valley floors.
      const double t = (n[k] - nlo) / (nhi - nlo);
      double z = kLandLowM + (kLandHighM - kLandLowM) * (0.45 * t + 0.55 * t * t);
      // Proving ground: a gentle plane with a faint swell, blended into the hills around it.
      const double pg = 255.0 + 6.0 * (x - kReserveX0) / (kReserveX1 - kReserveX0) +
                        3.0 * (y - kReserveY0) / (kReserveY1 - kReserveY0) +
                        2.0 * value_noise(x / 3000.0, y / 3000.0, 99);
      const double w = 1.0 - smoother((reserve_distance(x, y) - kReserveFlatMarginM) / kReserveBlendM);
      z = w * pg + (1.0 - w) * z;
      // Lake: an elliptical bowl, 185 m at the centre, 200 m (the water level) on the ellipse;
      // beyond it the shore rises smoothly into the hills over kLakeShoreBlendM.
      const double ex = (x - kLakeX) / kLakeSemiX, ey = (y - kLakeY) / kLakeSemiY;
      const double rho = std::sqrt(ex * ex + ey * ey);
      if (rho <= 1.0) {
        z = kLakeBottomM + (kWaterLevelM - kLakeBottomM) * rho * rho;
      } else {
        const double beyond = (rho - 1.0) * kLakeSemiY;  // ~ metres past the shore
        z = kWaterLevelM + (z - kWaterLevelM) * smoother(beyond / kLakeShoreBlendM);
      }
      h[k] = static_cast<float>(std::nearbyint(z * 32.0) / 32.0);  // 1/32 m: compresses well
    }
  }
  return h;
}

float post(const std::vector<float>& h, int i, int j) { return h[static_cast<size_t>(j) * kPosts + i]; }

double height_at(const std::vector<float>& h, double x, double y) {
  const double u = std::clamp(x / kSpacing, 0.0, kPosts - 1.0), v = std::clamp(y / kSpacing, 0.0, kPosts - 1.0);
  const int i = std::min(static_cast<int>(u), kPosts - 2), j = std::min(static_cast<int>(v), kPosts - 2);
  const double fx = u - i, fy = v - j;
  return (post(h, i, j) * (1 - fx) + post(h, i + 1, j) * fx) * (1 - fy) +
         (post(h, i, j + 1) * (1 - fx) + post(h, i + 1, j + 1) * fx) * fy;
}

// Slope (deg) at a post from central differences.
double slope_deg(const std::vector<float>& h, int i, int j) {
  const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, kPosts - 1);
  const int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, kPosts - 1);
  const double gx = (post(h, i1, j) - post(h, i0, j)) / ((i1 - i0) * kSpacing);
  const double gy = (post(h, i, j1) - post(h, i, j0)) / ((j1 - j0) * kSpacing);
  return std::atan(std::sqrt(gx * gx + gy * gy)) * 180.0 / 3.14159265358979323846;
}

void write_tif(const std::filesystem::path& p, const std::vector<float>& h) {
  GDALDriverH drv = GDALGetDriverByName("GTiff");
  if (!drv) throw std::runtime_error("GDAL has no GTiff driver");
  char** opts = nullptr;
  opts = CSLSetNameValue(opts, "COMPRESS", "DEFLATE");
  opts = CSLSetNameValue(opts, "PREDICTOR", "3");
  opts = CSLSetNameValue(opts, "ZLEVEL", "9");
  GDALDatasetH ds = GDALCreate(drv, p.string().c_str(), kPosts, kPosts, 1, GDT_Float32, opts);
  CSLDestroy(opts);
  if (!ds) throw std::runtime_error("cannot create " + p.string());
  // Pixel centres on the posts: column i at x = i * 62.5, row 0 (north) at y = 50 km.
  double gt[6] = {-kSpacing / 2, kSpacing, 0, kWorld + kSpacing / 2, 0, -kSpacing};
  GDALSetGeoTransform(ds, gt);
  std::vector<float> north_up(h.size());
  for (int r = 0; r < kPosts; ++r)
    std::copy_n(h.begin() + static_cast<size_t>(kPosts - 1 - r) * kPosts, kPosts,
                north_up.begin() + static_cast<size_t>(r) * kPosts);
  const CPLErr e = GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, kPosts, kPosts,
                                north_up.data(), kPosts, kPosts, GDT_Float32, 0, 0);
  GDALClose(ds);
  if (e != CE_None) throw std::runtime_error("cannot write " + p.string());
}

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

int square_of(int64_t cm) { return static_cast<int>(cm / kSquareCm); }

bool dry(const std::vector<float>& h, double x, double y) {
  return height_at(h, x, y) >= kWaterLevelM + kDryMarginM;
}

bool in_reserve(double x, double y) {
  return x >= kReserveX0 && x <= kReserveX1 && y >= kReserveY0 && y <= kReserveY1;
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

void require(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error("generator invariant failed: " + what);
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

// Fenwick tree of non-negative weights for sampling an index with probability ~ weight.
class WeightTree {
 public:
  explicit WeightTree(const std::vector<double>& w) : n_(w.size()), t_(w.size() + 1, 0.0), w_(w) {
    for (size_t i = 0; i < n_; ++i) add(i, w[i]);
  }
  void set(size_t i, double w) {
    add(i, w - w_[i]);
    w_[i] = w;
  }
  double weight(size_t i) const { return w_[i]; }
  double total() const {
    double s = 0;
    for (size_t i = n_; i > 0; i -= i & (~i + 1)) s += t_[i];
    return s;
  }
  // The index whose cumulative range holds `target` (0 <= target < total).
  size_t find(double target) const {
    size_t pos = 0;
    size_t step = 1;
    while (step * 2 <= n_) step *= 2;
    for (; step; step /= 2) {
      if (pos + step <= n_ && t_[pos + step] <= target) {
        pos += step;
        target -= t_[pos];
      }
    }
    return std::min(pos, n_ - 1);
  }

 private:
  void add(size_t i, double d) {
    for (size_t k = i + 1; k <= n_; k += k & (~k + 1)) t_[k] += d;
  }
  size_t n_;
  std::vector<double> t_, w_;
};

struct Stats {
  int occupied = 0, max_per_square = 0, min_per_square = 0;
  double average = 0;
};

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

std::string format_cm(int64_t cm) {
  char b[32];
  std::snprintf(b, sizeof b, "%lld.%02lld", static_cast<long long>(cm / 100), static_cast<long long>(cm % 100));
  return b;
}

void write_csv(const std::filesystem::path& p, const std::vector<Object>& objs) {
  std::ofstream f(p, std::ios::binary);
  if (!f) throw std::runtime_error("cannot create " + p.string());
  f << "id,kind,x_m,y_m,heading_deg\n";
  std::array<int, kKinds> serial{};
  char id[16];
  for (const auto& o : objs) {
    std::snprintf(id, sizeof id, "%c%07d", kIdPrefix[o.kind], ++serial[o.kind]);
    f << id << ',' << kKindName[o.kind] << ',' << format_cm(o.x_cm) << ',' << format_cm(o.y_cm) << ','
      << o.heading_tenths / 10 << '.' << o.heading_tenths % 10 << '\n';
  }
  if (!f.flush()) throw std::runtime_error("cannot write " + p.string());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR   (writes OUT_DIR/default.tif, OUT_DIR/default-objects.csv)\n",
                 argv[0]);
    return 2;
  }
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    GDALAllRegister();

    const std::vector<float> h = make_heights();
    const std::vector<Object> objs = make_objects(h);

    // Check the result against the thesis before writing anything.
    std::array<int, kKinds> per_kind{};
    for (const auto& o : objs) ++per_kind[o.kind];
    for (int k = 0; k < kKinds; ++k) require(per_kind[k] == kKindCount[k], std::string("count of ") + kKindName[k]);
    require(static_cast<int>(objs.size()) == th::kTable1Total, "Table 1 total");
    const Stats st = square_stats(objs);
    require(st.min_per_square == th::kTable1MinPerGridsquare, "minimum per gridsquare");
    require(st.max_per_square == th::kTable1MaxPerGridsquare, "maximum per gridsquare");
    require(std::nearbyint(st.average * 10) / 10 == th::kTable1AveragePerGridsquare, "average per gridsquare");

    write_tif(dir / "default.tif", h);
    write_csv(dir / "default-objects.csv", objs);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    // Statistics.
    const auto [lo, hi] = std::minmax_element(h.begin(), h.end());
    std::vector<double> slopes;
    slopes.reserve(h.size());
    double pg_lo = 1e9, pg_hi = -1e9, pg_slope = 0;
    size_t water = 0;
    for (int j = 0; j < kPosts; ++j)
      for (int i = 0; i < kPosts; ++i) {
        const double sl = slope_deg(h, i, j);
        slopes.push_back(sl);
        if (post(h, i, j) < kWaterLevelM) ++water;
        if (in_reserve(i * kSpacing, j * kSpacing)) {
          pg_lo = std::min<double>(pg_lo, post(h, i, j));
          pg_hi = std::max<double>(pg_hi, post(h, i, j));
          pg_slope = std::max(pg_slope, sl);
        }
      }
    std::sort(slopes.begin(), slopes.end());
    const auto pct = [&](double q) { return slopes[static_cast<size_t>(q * (slopes.size() - 1))]; };
    const size_t under15 = static_cast<size_t>(std::lower_bound(slopes.begin(), slopes.end(), 15.0) - slopes.begin());
    std::printf("terrain: %d x %d posts at %.1f m, heights %.2f .. %.2f m, %zu posts below the %.0f m water level\n",
                kPosts, kPosts, kSpacing, *lo, *hi, water, kWaterLevelM);
    std::printf("slopes: median %.2f deg, 90%% %.2f, 99%% %.2f, max %.2f; %.2f%% of posts under 15 deg\n",
                pct(0.5), pct(0.9), pct(0.99), slopes.back(), 100.0 * under15 / slopes.size());
    std::printf("proving ground: heights %.2f .. %.2f m, max slope %.2f deg\n", pg_lo, pg_hi, pg_slope);
    std::printf("objects: %zu (trees %d, bushes %d, poles %d, buildings %d, watertowers %d, bunkers %d, rocks %d)\n",
                objs.size(), per_kind[kTree], per_kind[kBush], per_kind[kPole], per_kind[kBuilding],
                per_kind[kWatertower], per_kind[kBunker], per_kind[kRock]);
    std::printf("per gridsquare: min %d, max %d, average %.4f over %d occupied of %d\n", st.min_per_square,
                st.max_per_square, st.average, st.occupied, kSquares * kSquares);
    std::printf("files: %s (%ju bytes), %s (%ju bytes); %.2f s\n", (dir / "default.tif").string().c_str(),
                static_cast<uintmax_t>(std::filesystem::file_size(dir / "default.tif")),
                (dir / "default-objects.csv").string().c_str(),
                static_cast<uintmax_t>(std::filesystem::file_size(dir / "default-objects.csv")), secs);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_default_world: %s\n", e.what());
    return 1;
  }
}
