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
//
// The parts, in default_world/: layout.hpp (sizes, lake, reserve, seed), random.hpp (the RNG),
// terrain.hpp (value noise, heights, GeoTIFF), objects.hpp (placement, Table 1 statistics) and
// weight_tree.hpp (the sampler the objects use). This file checks the result against the thesis,
// writes the CSV and prints the statistics.
#include <gdal.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "default_world/layout.hpp"
#include "default_world/objects.hpp"
#include "default_world/terrain.hpp"

using namespace npsnet::default_world;

namespace {

// --- CSV -----------------------------------------------------------------------------------------
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
