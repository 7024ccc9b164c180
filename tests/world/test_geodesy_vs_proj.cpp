// Our WGS84 geodesy against PROJ (through GDAL's OGRCoordinateTransformation): geodetic -> ECEF
// and the terrain's transverse Mercator, on random points; both must agree to < 1 mm.
#include <gtest/gtest.h>

#include <ogr_srs_api.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/geodesy.hpp"

using namespace npsnet;
using namespace npsnet::geo;

namespace {

struct Rng {  // splitmix64
  uint64_t s;
  uint64_t next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * ((next() >> 11) * 0x1.0p-53); }
};

// Owns a PROJ transformation between two CRS given as user strings (EPSG codes, PROJ strings).
class ProjTransform {
 public:
  ProjTransform(const std::string& from, const std::string& to) {
    src_ = OSRNewSpatialReference(nullptr);
    dst_ = OSRNewSpatialReference(nullptr);
    EXPECT_EQ(OSRSetFromUserInput(src_, from.c_str()), OGRERR_NONE) << from;
    EXPECT_EQ(OSRSetFromUserInput(dst_, to.c_str()), OGRERR_NONE) << to;
    OSRSetAxisMappingStrategy(src_, OAMS_TRADITIONAL_GIS_ORDER);  // lon, lat
    OSRSetAxisMappingStrategy(dst_, OAMS_TRADITIONAL_GIS_ORDER);
    ct_ = OCTNewCoordinateTransformation(src_, dst_);
    EXPECT_NE(ct_, nullptr);
  }
  ~ProjTransform() {
    if (ct_) OCTDestroyCoordinateTransformation(ct_);
    OSRDestroySpatialReference(src_);
    OSRDestroySpatialReference(dst_);
  }
  bool operator()(std::vector<double>& x, std::vector<double>& y, std::vector<double>& z) {
    return ct_ && OCTTransform(ct_, static_cast<int>(x.size()), x.data(), y.data(), z.data());
  }

 private:
  OGRSpatialReferenceH src_ = nullptr, dst_ = nullptr;
  OGRCoordinateTransformationH ct_ = nullptr;
};

std::string g17(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

}  // namespace

TEST(GeodesyVsProj, GeodeticToEcef) {
  ProjTransform t("EPSG:4979", "EPSG:4978");  // WGS84 3D geographic -> geocentric
  Rng rng{11};
  const int n = 5000;
  std::vector<double> x(n), y(n), z(n);
  std::vector<Geodetic> g(n);
  for (int i = 0; i < n; ++i) {
    g[i] = {rng.uniform(-90, 90), rng.uniform(-180, 180), rng.uniform(-500, 50000)};
    x[i] = g[i].lon_deg, y[i] = g[i].lat_deg, z[i] = g[i].h_m;
  }
  ASSERT_TRUE(t(x, y, z));
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    const double d = (geodetic_to_ecef(g[i]) - Vec3(x[i], y[i], z[i])).norm();
    worst = std::max(worst, d);
    ASSERT_LT(d, 1e-3) << g[i].lat_deg << " " << g[i].lon_deg << " " << g[i].h_m;
    // And back: PROJ's ECEF through our inverse.
    const Geodetic back = ecef_to_geodetic({x[i], y[i], z[i]});
    ASSERT_LT((geodetic_to_ecef(back) - geodetic_to_ecef(g[i])).norm(), 1e-3);
  }
  RecordProperty("worst_mm", g17(worst * 1e3));
}

TEST(GeodesyVsProj, TransverseMercatorForward) {
  // The default world's frame: TM centred on a 50 km square whose SW corner is at FHL.
  const LocalFrame frame({35.98, -121.25, 0}, 50000, 50000);
  const TransverseMercator& tm = frame.projection();
  const std::string tmerc = "+proj=tmerc +lat_0=" + g17(tm.lat0()) + " +lon_0=" + g17(tm.lon0()) +
                            " +k=1 +x_0=" + g17(tm.false_easting()) +
                            " +y_0=" + g17(tm.false_northing()) + " +datum=WGS84 +units=m +no_defs";
  ProjTransform t("EPSG:4326", tmerc);
  Rng rng{12};
  const int n = 5000;
  std::vector<double> x(n), y(n), z(n, 0.0);
  std::vector<Geodetic> g(n);
  for (int i = 0; i < n; ++i) {
    // Up to ~75 km from the centre: the terrain and well beyond.
    g[i] = {tm.lat0() + rng.uniform(-0.7, 0.7), tm.lon0() + rng.uniform(-0.8, 0.8), 0};
    x[i] = g[i].lon_deg, y[i] = g[i].lat_deg;
  }
  ASSERT_TRUE(t(x, y, z));
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    const Vec2 ours = tm.forward(g[i].lat_deg, g[i].lon_deg);
    const double d = (ours - Vec2(x[i], y[i])).norm();
    worst = std::max(worst, d);
    ASSERT_LT(d, 1e-3) << g[i].lat_deg << " " << g[i].lon_deg;
  }
  RecordProperty("worst_mm", g17(worst * 1e3));
  // The SW corner is local (0, 0) in PROJ's hands too.
  std::vector<double> cx{-121.25}, cy{35.98}, cz{0};
  ASSERT_TRUE(t(cx, cy, cz));
  EXPECT_NEAR(cx[0], 0.0, 1e-3);
  EXPECT_NEAR(cy[0], 0.0, 1e-3);
}

TEST(GeodesyVsProj, TransverseMercatorFarFromMeridian) {
  // A UTM-sized strip (3 deg either side) at several latitudes, against PROJ's exact tmerc.
  Rng rng{13};
  for (double lat0 : {-60.0, 0.0, 35.0, 70.0}) {
    const TransverseMercator tm(lat0, 10.0, 500000.0, 0.0);
    const std::string s = "+proj=tmerc +lat_0=" + g17(lat0) +
                          " +lon_0=10 +k=1 +x_0=500000 +y_0=0 +datum=WGS84 +units=m +no_defs";
    ProjTransform t("EPSG:4326", s);
    const int n = 1000;
    std::vector<double> x(n), y(n), z(n, 0.0);
    for (int i = 0; i < n; ++i) {
      x[i] = 10.0 + rng.uniform(-3, 3);
      y[i] = std::clamp(lat0 + rng.uniform(-5, 5), -84.0, 84.0);
    }
    const std::vector<double> lon = x, lat = y;
    ASSERT_TRUE(t(x, y, z));
    for (int i = 0; i < n; ++i) {
      const Vec2 ours = tm.forward(lat[i], lon[i]);
      ASSERT_LT((ours - Vec2(x[i], y[i])).norm(), 1e-3) << lat[i] << " " << lon[i];
    }
  }
}
