// The default world's terrain (terrain.hpp): value noise, heights, and the GeoTIFF writer.
#include "default_world/terrain.hpp"

#include <gdal.h>
#include <cpl_string.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "default_world/random.hpp"

namespace npsnet::default_world {

// --- Value noise (integer hash lattice, quintic fade) -------------------------------------------
namespace {

double lattice(int64_t ix, int64_t iy, uint64_t octave) {
  uint64_t h = kSeed ^ (static_cast<uint64_t>(ix) * 0x9E3779B97F4A7C15ull) ^
               (static_cast<uint64_t>(iy) * 0xC2B2AE3D27D4EB4Full) ^ (octave * 0x165667B19E3779F9ull);
  h = splitmix64(h);
  return static_cast<double>(h >> 11) * 0x1.0p-52 - 1.0;  // [-1, 1)
}

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

}  // namespace

double value_noise(double x, double y, uint64_t octave) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<int64_t>(fx), iy = static_cast<int64_t>(fy);
  const double u = fade(x - fx), v = fade(y - fy);
  const double a = lattice(ix, iy, octave), b = lattice(ix + 1, iy, octave);
  const double c = lattice(ix, iy + 1, octave), d = lattice(ix + 1, iy + 1, octave);
  return (a + (b - a) * u) * (1 - v) + (c + (d - c) * u) * v;
}

namespace {

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

}  // namespace

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

}  // namespace npsnet::default_world
