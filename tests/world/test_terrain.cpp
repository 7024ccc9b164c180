// Terrain: bilinear heights and normals, craters, and loading rasters through GDAL (a bare .asc
// in local metres, GeoTIFFs in EPSG:4326 and in a UTM zone warped into the local TM frame).
#include <gtest/gtest.h>

#include <gdal.h>
#include <cpl_error.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "support/gdal_read.hpp"
#include "support/scratch.hpp"
#include "world/error.hpp"
#include "world/terrain.hpp"

using namespace npsnet;
using namespace npsnet::world;
namespace fs = std::filesystem;

namespace {

fs::path temp_dir() {
  return npsnet::test::fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
}

// A plane h = a + b x + c y sampled on posts.
Terrain plane(int cols, int rows, double s, double a, double b, double c) {
  std::vector<float> h(static_cast<size_t>(cols) * rows);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) h[static_cast<size_t>(j) * cols + i] = float(a + b * i * s + c * j * s);
  return Terrain(cols, rows, s, std::move(h), {35.98, -121.25, 0});
}

// Writes a single-band Float32 GeoTIFF; `north_up` rows (row 0 = north), EPSG code or 0 for none.
void write_geotiff(const fs::path& p, int cols, int rows, const double gt[6], int epsg,
                   const std::vector<float>& north_up, const double* nodata = nullptr) {
  GDALAllRegister();
  GDALDriverH drv = GDALGetDriverByName("GTiff");
  ASSERT_NE(drv, nullptr);
  GDALDatasetH ds = GDALCreate(drv, p.string().c_str(), cols, rows, 1, GDT_Float32, nullptr);
  ASSERT_NE(ds, nullptr);
  GDALSetGeoTransform(ds, const_cast<double*>(gt));
  if (epsg) {
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(srs, epsg);
    GDALSetSpatialRef(ds, srs);
    OSRDestroySpatialReference(srs);
  }
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  if (nodata) GDALSetRasterNoDataValue(band, *nodata);
  ASSERT_EQ(GDALRasterIO(band, GF_Write, 0, 0, cols, rows, const_cast<float*>(north_up.data()),
                         cols, rows, GDT_Float32, 0, 0),
            CE_None);
  GDALClose(ds);
}

// Distance on the ground between two geodetic points (m).
double ground_distance(const geo::Geodetic& a, const geo::Geodetic& b) {
  return (geo::geodetic_to_ecef({a.lat_deg, a.lon_deg, 0}) -
          geo::geodetic_to_ecef({b.lat_deg, b.lon_deg, 0}))
      .norm();
}

// Local position of the highest post.
Vec2 highest_post(const Terrain& t) {
  int bi = 0, bj = 0;
  for (int j = 0; j < t.rows(); ++j)
    for (int i = 0; i < t.cols(); ++i)
      if (t.post(i, j) > t.post(bi, bj)) bi = i, bj = j;
  return {bi * t.spacing_m(), bj * t.spacing_m()};
}

// The loaded grid is the raster's bounding box in the local frame: given the raster's four outer
// corners (geodetic), the box they span starts within 2 posts SW of local (0, 0) and ends within
// 2 posts NE of the far corner, so the origin is the SW corner's geodetic position.
void expect_grid_spans(const Terrain& t, const std::vector<geo::Geodetic>& corners) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& c : corners) {
    const Vec3 l = t.frame().to_local(c);
    x0 = std::min(x0, l.x()), y0 = std::min(y0, l.y());
    x1 = std::max(x1, l.x()), y1 = std::max(y1, l.y());
  }
  const double s = t.spacing_m();
  EXPECT_LE(x0, 0.0);
  EXPECT_GE(x0, -2 * s);
  EXPECT_LE(y0, 0.0);
  EXPECT_GE(y0, -2 * s);
  EXPECT_GE(x1, t.width_m());
  EXPECT_LE(x1, t.width_m() + 2 * s);
  EXPECT_GE(y1, t.depth_m());
  EXPECT_LE(y1, t.depth_m() + 2 * s);
}

std::string load_error(const fs::path& p) {
  try {
    Terrain::load(p, {35.98, -121.25, 0});
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(Terrain, BilinearExactOnTiltedPlane) {
  const Terrain t = plane(11, 7, 10.0, 200.0, 0.1, -0.05);
  EXPECT_DOUBLE_EQ(t.width_m(), 100.0);
  EXPECT_DOUBLE_EQ(t.depth_m(), 60.0);
  for (double x : {0.0, 3.3, 17.5, 50.0, 99.9, 100.0})
    for (double y : {0.0, 1.25, 33.3, 59.99, 60.0})
      EXPECT_NEAR(t.height(x, y), 200.0 + 0.1 * x - 0.05 * y, 1e-4) << x << " " << y;
  // Clamped outside the map: the nearest edge.
  EXPECT_NEAR(t.height(-50, 30), t.height(0, 30), 1e-9);
  EXPECT_NEAR(t.height(500, 500), t.height(100, 60), 1e-9);
}

TEST(Terrain, HeightsFourAtOnceGiveTheBitsOfHeight) {
  // heights4 (a vehicle's four corners in one go) against four height() calls: random posts,
  // points on and off the map, on posts and on the far edges.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<float> h(13 * 9);
  for (float& v : h) v = static_cast<float>(50.0 + 30.0 * u(rng));
  const Terrain t(13, 9, 12.5, std::move(h), {35.98, -121.25, 0});
  std::vector<double> xs = {0.0, -0.0, 12.5, 25.0, t.width_m(), std::nextafter(t.width_m(), 0.0), -1e9, 1e9, 37.5};
  std::vector<double> ys = {0.0, 100.0, t.depth_m(), std::nextafter(t.depth_m(), 0.0), -3.0, 1e12, 62.5, 99.99, 0.1};
  for (int i = 0; i < 40000; ++i) xs.push_back(-20 + 200 * u(rng)), ys.push_back(-20 + 140 * u(rng));
  for (size_t i = 0; i + 4 <= xs.size(); i += 4) {
    const double x[4] = {xs[i], xs[i + 1], xs[i + 2], xs[i + 3]}, y[4] = {ys[i], ys[i + 1], ys[i + 2], ys[i + 3]};
    double got[4];
    t.heights4(x, y, got);
    for (int k = 0; k < 4; ++k) {
      const double want = t.height(x[k], y[k]);
      ASSERT_EQ(std::memcmp(&got[k], &want, sizeof want), 0) << x[k] << " " << y[k] << ": " << got[k] << " " << want;
    }
  }
}

TEST(Terrain, SurelyAboveOnlyWhereTheHeightIsAbove) {
  // surely_above (World::is_water's shortcut) against height(): a valley across several blocks of
  // cells, a spacing whose reciprocal rounds (so the cell found by multiplying is sometimes one
  // off), points on post lines and off the map, levels from below the lowest post to above the
  // highest, and again after craters have cut below them.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int cols = 41, rows = 37;
  const double s = 12.3;
  std::vector<float> h(static_cast<size_t>(cols) * rows);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i)
      h[static_cast<size_t>(j) * cols + i] = static_cast<float>(200.0 + 0.02 * (i - 20) * (i - 20) + 3.0 * u(rng));
  Terrain t(cols, rows, s, std::move(h), {35.98, -121.25, 0});
  std::vector<double> xs, ys;
  for (int i = 0; i < cols; ++i) xs.push_back(i * s), xs.push_back(std::nextafter(i * s, 0.0)), xs.push_back(std::nextafter(i * s, 1e9));
  for (int j = 0; j < rows; ++j) ys.push_back(j * s), ys.push_back(std::nextafter(j * s, 0.0));
  for (double v : {-1e12, -5.0, t.width_m() + 7, 1e12, std::numeric_limits<double>::quiet_NaN()}) xs.push_back(v), ys.push_back(v);
  for (int k = 0; k < 3000; ++k) xs.push_back(-30 + (t.width_m() + 60) * u(rng)), ys.push_back(-30 + (t.depth_m() + 60) * u(rng));
  auto check = [&](const char* when, double share) {
    int above = 0, said = 0;
    for (const double level : {150.0, 199.0, 200.5, 201.0, 202.0, 204.0, 210.0, 230.0})
      for (size_t a = 0; a < xs.size(); ++a) {
        const double x = xs[a], y = ys[(a * 7 + static_cast<size_t>(level)) % ys.size()];
        if (std::isnan(x) || std::isnan(y)) {
          EXPECT_FALSE(t.surely_above(x, y, level));
          continue;
        }
        const double z = t.height(x, y);
        above += z > level;
        if (!t.surely_above(x, y, level)) continue;
        ++said;
        ASSERT_GT(z, level) << when << ": at " << x << ", " << y << " level " << level;
      }
    std::printf("%s: %d of %d points above their level answered\n", when, said, above);
    EXPECT_GT(said, share * above) << when << ": the bound should answer for most points well above";
  };
  check("as loaded", 0.5);
  EXPECT_TRUE(t.surely_above(100.0, 100.0, 150.0));
  for (int k = 0; k < 6; ++k) t.crater(t.width_m() * u(rng), t.depth_m() * u(rng), 20 + 30 * u(rng), 15.0);
  t.crater(0.0, 0.0, 40.0, 30.0);  // a corner
  t.crater(t.width_m(), t.depth_m(), 40.0, 30.0);
  check("after craters", 0.3);  // (a crater lowers the bound of the blocks around it)
}

TEST(Terrain, NormalOn30DegreeSlope) {
  const double slope = std::tan(deg2rad(30.0));
  const Terrain t = plane(9, 9, 5.0, 100.0, slope, 0.0);  // rises toward +x
  for (double x : {2.0, 13.7, 38.0})
    for (double y : {1.0, 21.0}) {
      const Vec3 n = t.normal(x, y);
      EXPECT_NEAR(n.norm(), 1.0, 1e-12);
      EXPECT_NEAR(rad2deg(std::acos(n.z())), 30.0, 1e-4);
      EXPECT_NEAR(n.x(), -std::sin(deg2rad(30.0)), 1e-5);  // tilts away from the rise
      EXPECT_NEAR(n.y(), 0.0, 1e-9);
    }
  const Terrain ty = plane(9, 9, 5.0, 100.0, 0.0, -slope);  // falls toward +y
  EXPECT_NEAR(ty.normal(20, 20).y(), std::sin(deg2rad(30.0)), 1e-5);
}

TEST(Terrain, CraterLowersBowlAndReportsRect) {
  Terrain t = plane(101, 101, 2.0, 300.0, 0.0, 0.0);
  const std::vector<float> before = t.posts();
  const PostRect r = t.crater(100.0, 60.0, 9.0, 3.0);
  ASSERT_FALSE(r.empty());
  EXPECT_NEAR(t.post(50, 30), 297.0, 1e-4);  // the centre post goes down by depth
  EXPECT_NEAR(t.height(100.0, 60.0), 297.0, 1e-4);
  // Posts strictly inside the 9 m radius are at |d| <= 8 m: columns 46..54, rows 26..34.
  EXPECT_EQ(r.i0, 46);
  EXPECT_EQ(r.i1, 54);
  EXPECT_EQ(r.j0, 26);
  EXPECT_EQ(r.j1, 34);
  for (int j = 0; j < t.rows(); ++j)
    for (int i = 0; i < t.cols(); ++i) {
      const float b = before[static_cast<size_t>(j) * t.cols() + i];
      const double d = std::hypot(i * 2.0 - 100.0, j * 2.0 - 60.0);
      ASSERT_LE(t.post(i, j), b);  // never raises
      if (d >= 9.0) {
        ASSERT_EQ(t.post(i, j), b) << i << " " << j;
      }
      if (d < 8.9) {
        ASSERT_LT(t.post(i, j), b);
      }
      if (t.post(i, j) != b) {
        ASSERT_GE(i, r.i0);
        ASSERT_LE(i, r.i1);
        ASSERT_GE(j, r.j0);
        ASSERT_LE(j, r.j1);
      }
    }
  // Deeper toward the centre.
  EXPECT_LT(t.post(50, 30), t.post(52, 30));
  EXPECT_LT(t.post(52, 30), t.post(54, 30));
  // A crater off the map, or of no size, changes nothing.
  EXPECT_TRUE(t.crater(-100, -100, 5, 2).empty());
  EXPECT_TRUE(t.crater(50, 50, 0, 2).empty());
  // At the corner only the posts on the map change.
  const PostRect c = t.crater(0.0, 0.0, 5.0, 1.0);
  EXPECT_EQ(c.i0, 0);
  EXPECT_EQ(c.j0, 0);
  EXPECT_EQ(c.i1, 2);
  EXPECT_EQ(c.j1, 2);
}

TEST(Terrain, LoadsAscInLocalMetres) {
  const fs::path d = temp_dir();
  const fs::path p = d / "small.asc";
  {
    std::ofstream f(p);
    f << "ncols 4\nnrows 3\nxllcorner 1000\nyllcorner 2000\ncellsize 25\nNODATA_value -9999\n"
         "30 31 32 33\n"       // north row
         "20 -9999 22 23\n"
         "10 11 12 13\n";      // south row
  }
  const geo::Geodetic origin{35.5, -120.5, 0};
  const Terrain t = Terrain::load(p, origin);
  EXPECT_EQ(t.cols(), 4);
  EXPECT_EQ(t.rows(), 3);
  EXPECT_DOUBLE_EQ(t.spacing_m(), 25.0);
  EXPECT_FLOAT_EQ(t.post(0, 0), 10.0f);  // row 0 = south
  EXPECT_FLOAT_EQ(t.post(3, 0), 13.0f);
  EXPECT_FLOAT_EQ(t.post(0, 2), 30.0f);
  EXPECT_FLOAT_EQ(t.post(2, 1), 22.0f);
  // The nodata post is the mean of its 8 neighbours.
  EXPECT_FLOAT_EQ(t.post(1, 1), (10 + 11 + 12 + 20 + 22 + 30 + 31 + 32) / 8.0f);
  EXPECT_DOUBLE_EQ(t.origin().lat_deg, 35.5);
  EXPECT_DOUBLE_EQ(t.origin().lon_deg, -120.5);
  const geo::Geodetic sw = t.frame().to_geodetic({0, 0, 0});
  EXPECT_NEAR(sw.lat_deg, 35.5, 1e-10);
  EXPECT_NEAR(sw.lon_deg, -120.5, 1e-10);
  EXPECT_NEAR(t.height(12.5, 0), 10.5, 1e-5);
  fs::remove_all(d);
}

TEST(Terrain, LoadsGeoTiffInEpsg4326) {
  const fs::path d = temp_dir();
  const fs::path p = d / "geo.tif";
  // 0.1 x 0.1 degree... 0.3 deg of longitude by 0.2 deg of latitude, 0.001 deg pixels.
  const int cols = 300, rows = 200;
  const double lon0 = -121.40, lat_top = 36.10, px = 0.001;
  const double gt[6] = {lon0, px, 0, lat_top, 0, -px};
  const geo::Geodetic peak{36.031, -121.3125, 0};
  std::vector<float> img(static_cast<size_t>(cols) * rows);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const geo::Geodetic g{lat_top - (r + 0.5) * px, lon0 + (c + 0.5) * px, 0};
      const double dist = ground_distance(g, peak);
      img[static_cast<size_t>(r) * cols + c] = float(250.0 + 400.0 * std::max(0.0, 1.0 - dist / 4000.0));
    }
  write_geotiff(p, cols, rows, gt, 4326, img);
  const Terrain t = Terrain::load(p, {0, 0, 0});  // origin ignored: the raster has a CRS
  // Square posts at about the raster's ground resolution (0.001 deg ~ 90 m E-W, 111 m N-S).
  EXPECT_GT(t.spacing_m(), 85.0);
  EXPECT_LT(t.spacing_m(), 115.0);
  EXPECT_NEAR(t.width_m(), 0.3 * 111320 * std::cos(deg2rad(36.0)), 3 * t.spacing_m());
  EXPECT_NEAR(t.depth_m(), 0.2 * 110950, 3 * t.spacing_m());
  // The frame is centred on the raster's centre.
  EXPECT_NEAR(t.frame().projection().lat0(), 36.0, 1e-9);
  EXPECT_NEAR(t.frame().projection().lon0(), -121.25, 1e-9);
  // The origin is the SW corner's geodetic: near the raster's SW pixel, and local (0, 0).
  const geo::Geodetic sw_pixel{lat_top - (rows - 0.5) * px, lon0 + 0.5 * px, 0};
  EXPECT_LT(ground_distance(t.origin(), sw_pixel), 2.0 * t.spacing_m());
  expect_grid_spans(t, {{lat_top - rows * px, lon0, 0}, {lat_top - rows * px, lon0 + cols * px, 0},
                        {lat_top, lon0, 0}, {lat_top, lon0 + cols * px, 0}});
  const Vec3 o = t.frame().to_local(t.origin());
  EXPECT_NEAR(o.x(), 0, 1e-6);
  EXPECT_NEAR(o.y(), 0, 1e-6);
  // The peak lands at its own local place within one post.
  const Vec3 want = t.frame().to_local(peak);
  const Vec2 got = highest_post(t);
  EXPECT_LT((got - want.head<2>()).norm(), t.spacing_m()) << got.transpose() << " vs "
                                                           << want.transpose();
  EXPECT_NEAR(t.height(want.x(), want.y()), 650.0, 15.0);
  fs::remove_all(d);
}

TEST(Terrain, LoadsGeoTiffInUtmZone) {
  const fs::path d = temp_dir();
  const fs::path p = d / "utm.tif";
  // UTM zone 10N around Fort Hunter-Liggett; 30 m pixels, 7.2 km x 4.8 km.
  const int cols = 240, rows = 160;
  const double e0 = 655000.0, n_top = 3990000.0, px = 30.0;
  const double gt[6] = {e0, px, 0, n_top, 0, -px};
  const double pe = e0 + 2000.0, pn = n_top - 3100.0;  // the peak, in UTM
  std::vector<float> img(static_cast<size_t>(cols) * rows);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const double e = e0 + (c + 0.5) * px, n = n_top - (r + 0.5) * px;
      img[static_cast<size_t>(r) * cols + c] =
          float(300.0 + 150.0 * std::max(0.0, 1.0 - std::hypot(e - pe, n - pn) / 1500.0));
    }
  write_geotiff(p, cols, rows, gt, 32610, img);
  // The peak, the centre, and the raster's four outer corners, through PROJ.
  const double e1 = e0 + cols * px, n_bot = n_top - rows * px;
  double xs[6] = {pe, e0 + cols * px / 2, e0, e1, e0, e1};
  double ys[6] = {pn, n_top - rows * px / 2, n_bot, n_bot, n_top, n_top};
  ASSERT_TRUE(test::transform_epsg(32610, 4326, xs, ys, 6));
  const geo::Geodetic peak{ys[0], xs[0], 0}, centre{ys[1], xs[1], 0};
  std::vector<geo::Geodetic> corners;
  for (int k = 2; k < 6; ++k) corners.push_back({ys[k], xs[k], 0});

  const Terrain t = Terrain::load(p, {0, 0, 0});
  EXPECT_NEAR(t.spacing_m(), 30.0, 1.0);
  EXPECT_NEAR(t.frame().projection().lat0(), centre.lat_deg, 1e-9);
  EXPECT_NEAR(t.frame().projection().lon0(), centre.lon_deg, 1e-9);
  // The UTM grid is rotated (~1.2 deg) against our TM grid: the local grid is the box that
  // bounds the rotated raster, and the origin is that box's SW corner.
  expect_grid_spans(t, corners);
  const Vec3 o = t.frame().to_local(t.origin());
  EXPECT_NEAR(o.x(), 0, 1e-6);
  EXPECT_NEAR(o.y(), 0, 1e-6);
  const Vec3 want = t.frame().to_local(peak);
  const Vec2 got = highest_post(t);
  EXPECT_LT((got - want.head<2>()).norm(), t.spacing_m()) << got.transpose() << " vs "
                                                           << want.transpose();
  EXPECT_NEAR(t.height(want.x(), want.y()), 450.0, 5.0);
  fs::remove_all(d);
}

TEST(Terrain, MissingFileMessage) {
  const fs::path p = fs::temp_directory_path() / "npsnet_no_such_terrain.tif";
  fs::remove(p);
  EXPECT_EQ(load_error(p), p.string() + ":0: terrain: file not found");
}

TEST(Terrain, GarbageFileMessage) {
  const fs::path d = temp_dir();
  const fs::path p = d / "garbage.tif";
  {
    std::ofstream f(p, std::ios::binary);
    f << "this is not a raster\n\x01\x02\x03";
  }
  const std::string e = load_error(p);
  EXPECT_EQ(e.rfind(p.string() + ":0: terrain: not a readable raster", 0), 0u) << e;
  fs::remove_all(d);
}

TEST(Terrain, RejectsBadRasters) {
  const fs::path d = temp_dir();
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(d / name) << text;
    return d / name;
  };
  // One post.
  EXPECT_NE(load_error(write("one.asc", "ncols 1\nnrows 1\nxllcorner 0\nyllcorner 0\n"
                                         "cellsize 10\n5\n"))
                .find(":0: terrain: raster has 1 x 1 posts"),
            std::string::npos);
  // Non-square pixels without a CRS.
  EXPECT_NE(load_error(write("rect.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\n"
                                          "dx 10\ndy 20\n1 2\n3 4\n"))
                .find("pixels are not square"),
            std::string::npos);
  // More than half nodata.
  EXPECT_NE(load_error(write("holes.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\n"
                                           "cellsize 10\nNODATA_value -9999\n"
                                           "-9999 -9999\n-9999 4\n"))
                .find("3 of 4 posts are nodata"),
            std::string::npos);
  // A NaN height that is not the declared nodata.
  const double gt[6] = {0, 10, 0, 20, 0, -10};
  write_geotiff(d / "nan.tif", 2, 2, gt, 0, {1.0f, std::nanf(""), 3.0f, 4.0f});
  EXPECT_NE(load_error(d / "nan.tif").find(":0: terrain: non-finite height at post (1, 1)"),
            std::string::npos)
      << load_error(d / "nan.tif");
  // The same with NaN declared as nodata loads and fills the post.
  const double nan_nodata = std::nan("");
  write_geotiff(d / "nan_nd.tif", 2, 2, gt, 0, {1.0f, std::nanf(""), 3.0f, 4.0f}, &nan_nodata);
  const Terrain t = Terrain::load(d / "nan_nd.tif", {35, -120, 0});
  EXPECT_FLOAT_EQ(t.post(1, 1), (1.0f + 3.0f + 4.0f) / 3.0f);
  fs::remove_all(d);
}

TEST(Terrain, LoadsDted) {
  // A DTED level 0 cell (1 x 1 degree, 121 x 121 posts, 30 arc-seconds) made with GDAL's DTED
  // driver, with a cone-shaped hill at a known place.
  const fs::path d = temp_dir();
  const fs::path p = d / "n35.dt0";
  GDALAllRegister();
  const int n = 121;
  const double px = 1.0 / 120.0, lat_s = 35.0, lon_w = -122.0;
  GDALDatasetH mem = GDALCreate(GDALGetDriverByName("MEM"), "", n, n, 1, GDT_Int16, nullptr);
  ASSERT_NE(mem, nullptr);
  double gt[6] = {lon_w - px / 2, px, 0, lat_s + 1 + px / 2, 0, -px};
  GDALSetGeoTransform(mem, gt);
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, 4326);
  GDALSetSpatialRef(mem, srs);
  OSRDestroySpatialReference(srs);
  const geo::Geodetic peak{35.6, -121.3, 0};
  std::vector<int16_t> img(static_cast<size_t>(n) * n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const geo::Geodetic g{lat_s + 1 - r * px, lon_w + c * px, 0};
      img[static_cast<size_t>(r) * n + c] =
          static_cast<int16_t>(200 + 800 * std::max(0.0, 1.0 - ground_distance(g, peak) / 20000.0));
    }
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(mem, 1), GF_Write, 0, 0, n, n, img.data(), n, n,
                         GDT_Int16, 0, 0),
            CE_None);
  GDALDatasetH dt = GDALCreateCopy(GDALGetDriverByName("DTED"), p.string().c_str(), mem, FALSE,
                                   nullptr, nullptr, nullptr);
  GDALClose(mem);
  ASSERT_NE(dt, nullptr) << CPLGetLastErrorMsg();
  GDALClose(dt);

  const Terrain t = Terrain::load(p, {0, 0, 0});
  EXPECT_GT(t.spacing_m(), 600.0);  // 30" is ~750 m east-west and ~925 m north-south here
  EXPECT_LT(t.spacing_m(), 950.0);
  EXPECT_NEAR(t.frame().projection().lat0(), 35.5, 1e-6);
  EXPECT_NEAR(t.frame().projection().lon0(), -121.5, 1e-6);
  const Vec3 want = t.frame().to_local(peak);
  EXPECT_LT((highest_post(t) - want.head<2>()).norm(), t.spacing_m());
  EXPECT_NEAR(t.height(want.x(), want.y()), 1000.0, 40.0);
  fs::remove_all(d);
}
