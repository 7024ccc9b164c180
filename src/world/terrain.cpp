// Terrain heightfield: GDAL loading (warped into the terrain-centred transverse Mercator frame
// when the raster has a coordinate system), nodata filling, bilinear height and normal, craters.
#include "world/terrain.hpp"

#include <gdal.h>
#include <gdal_alg.h>
#include <gdal_utils.h>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "world/error.hpp"

namespace npsnet::world {
namespace {

// Posts further than this from zero are taken as an undeclared nodata value, not a height.
constexpr double kMaxPlausibleHeightM = 100000.0;
// Rasters larger than this many posts are refused rather than exhausting memory.
constexpr double kMaxPosts = 4.0e8;
// Nodata value of the warped intermediate raster (exact in float).
constexpr double kWarpNodata = -32768.0;

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& msg) {
  throw InputError(file.string(), 0, "terrain", msg);
}

void register_gdal() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

// Silences GDAL's stderr output while alive and remembers the last message.
class GdalErrors {
 public:
  GdalErrors() {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~GdalErrors() { CPLPopErrorHandler(); }
  GdalErrors(const GdalErrors&) = delete;
  GdalErrors& operator=(const GdalErrors&) = delete;
  static std::string last(const std::string& fallback) {
    const char* m = CPLGetLastErrorMsg();
    return (m && *m) ? std::string(m) : fallback;
  }
};

struct DatasetCloser {
  void operator()(void* ds) const {
    if (ds) GDALClose(static_cast<GDALDatasetH>(ds));
  }
};
using Dataset = std::unique_ptr<void, DatasetCloser>;

struct TransformerDeleter {
  void operator()(void* t) const {
    if (t) GDALDestroyGenImgProjTransformer(t);
  }
};
using Transformer = std::unique_ptr<void, TransformerDeleter>;

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string tm_proj_string(double lat0, double lon0) {
  return "+proj=tmerc +lat_0=" + fmt(lat0) + " +lon_0=" + fmt(lon0) +
         " +k=1 +x_0=0 +y_0=0 +datum=WGS84 +units=m +no_defs";
}

// Reads band 1 of `ds` as floats in our order (row 0 = south) and marks nodata posts.
// `north_up` says whether GDAL's row 0 is the north edge; `east_right` whether column 0 is west.
void read_band(const std::filesystem::path& file, GDALDatasetH ds, bool north_up, bool east_right,
               std::vector<float>& h, std::vector<unsigned char>& missing) {
  const int cols = GDALGetRasterXSize(ds), rows = GDALGetRasterYSize(ds);
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  std::vector<float> img(static_cast<size_t>(cols) * rows);
  if (GDALRasterIO(band, GF_Read, 0, 0, cols, rows, img.data(), cols, rows, GDT_Float32, 0, 0) !=
      CE_None) {
    fail(file, "cannot read the raster's heights: " + GdalErrors::last("read error"));
  }
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  const bool nodata_nan = has_nodata && std::isnan(nodata);
  const float nodata_f = static_cast<float>(nodata);
  h.assign(img.size(), 0.0f);
  missing.assign(img.size(), 0);
  for (int r = 0; r < rows; ++r) {
    const int j = north_up ? rows - 1 - r : r;
    for (int c = 0; c < cols; ++c) {
      const int i = east_right ? c : cols - 1 - c;
      const float v = img[static_cast<size_t>(r) * cols + c];
      const size_t k = static_cast<size_t>(j) * cols + i;
      if (has_nodata && (nodata_nan ? std::isnan(v) : v == nodata_f)) {
        missing[k] = 1;
        continue;
      }
      if (!std::isfinite(v)) {
        fail(file, "non-finite height at post (" + std::to_string(i) + ", " + std::to_string(j) +
                       ") (row 0 = south); declare it as the band's nodata value or fix it");
      }
      if (std::abs(v) > kMaxPlausibleHeightM) {
        fail(file, "implausible height " + fmt(v) + " m at post (" + std::to_string(i) + ", " +
                       std::to_string(j) + "); is it an undeclared nodata value?");
      }
      h[k] = v;
    }
  }
}

// Fills nodata posts from their neighbours, layer by layer outward from the valid posts: each
// post of a layer takes the mean of its already-valid 8-neighbours.
void fill_nodata(const std::filesystem::path& file, int cols, int rows, std::vector<float>& h,
                 std::vector<unsigned char>& missing) {
  const size_t n = h.size();
  const size_t n_missing = static_cast<size_t>(std::count(missing.begin(), missing.end(), 1));
  if (n_missing == 0) return;
  if (2 * n_missing > n) {
    fail(file, std::to_string(n_missing) + " of " + std::to_string(n) +
                   " posts are nodata (more than half); give a raster that covers its extent");
  }
  auto each_neighbour = [&](size_t k, auto&& fn) {
    const int i = static_cast<int>(k % cols), j = static_cast<int>(k / cols);
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        if (!di && !dj) continue;
        const int a = i + di, b = j + dj;
        if (a >= 0 && b >= 0 && a < cols && b < rows) fn(static_cast<size_t>(b) * cols + a);
      }
  };
  // 2 = queued in the current or next layer.
  std::vector<size_t> layer, next;
  for (size_t k = 0; k < n; ++k) {
    if (missing[k] != 1) continue;
    bool touches = false;
    each_neighbour(k, [&](size_t q) { touches = touches || missing[q] == 0; });
    if (touches) {
      layer.push_back(k);
      missing[k] = 2;
    }
  }
  std::vector<float> values;
  while (!layer.empty()) {
    values.resize(layer.size());
    for (size_t t = 0; t < layer.size(); ++t) {
      double sum = 0;
      int cnt = 0;
      each_neighbour(layer[t], [&](size_t q) {
        if (missing[q] == 0) {
          sum += h[q];
          ++cnt;
        }
      });
      values[t] = static_cast<float>(sum / cnt);
    }
    next.clear();
    for (size_t t = 0; t < layer.size(); ++t) {
      h[layer[t]] = values[t];
      missing[layer[t]] = 0;
    }
    for (size_t k : layer)
      each_neighbour(k, [&](size_t q) {
        if (missing[q] == 1) {
          missing[q] = 2;
          next.push_back(q);
        }
      });
    layer.swap(next);
  }
}

void check_size(const std::filesystem::path& file, int cols, int rows) {
  if (cols < 2 || rows < 2) {
    fail(file, "raster has " + std::to_string(cols) + " x " + std::to_string(rows) +
                   " posts; a terrain needs at least 2 x 2");
  }
  if (static_cast<double>(cols) * rows > kMaxPosts) {
    fail(file, "raster has " + std::to_string(cols) + " x " + std::to_string(rows) +
                   " posts, more than the supported " + fmt(kMaxPosts));
  }
}

// A raster without a coordinate system: local metres, lower-left post at `origin`.
Terrain load_local(const std::filesystem::path& file, GDALDatasetH ds, const geo::Geodetic& origin) {
  const int cols = GDALGetRasterXSize(ds), rows = GDALGetRasterYSize(ds);
  double gt[6] = {0, 1, 0, 0, 0, 1};
  const bool has_gt = GDALGetGeoTransform(ds, gt) == CE_None;
  if (!has_gt) {
    gt[0] = 0, gt[1] = 1, gt[2] = 0, gt[3] = 0, gt[4] = 0, gt[5] = -1;  // 1 m posts, north-up
  }
  if (gt[2] != 0.0 || gt[4] != 0.0) {
    fail(file, "the raster's geotransform is rotated or sheared; resample it to a north-up grid");
  }
  const double sx = std::abs(gt[1]), sy = std::abs(gt[5]);
  if (!(sx > 0) || !(sy > 0) || !std::isfinite(sx) || !std::isfinite(sy)) {
    fail(file, "the raster's pixel size is zero or not finite");
  }
  if (std::abs(sx - sy) > 1e-9 * std::max(sx, sy)) {
    fail(file, "pixels are not square (" + fmt(sx) + " m by " + fmt(sy) +
                   " m); a raster without a coordinate system needs square posts (resample it, "
                   "or give it a coordinate system so that it is warped)");
  }
  std::vector<float> h;
  std::vector<unsigned char> missing;
  read_band(file, ds, gt[5] < 0, gt[1] > 0, h, missing);
  fill_nodata(file, cols, rows, h, missing);
  return Terrain(cols, rows, sx, std::move(h), origin);
}

// A raster with a coordinate system: warp into a TM centred on the raster's centre.
Terrain load_warped(const std::filesystem::path& file, GDALDatasetH ds) {
  const int src_cols = GDALGetRasterXSize(ds), src_rows = GDALGetRasterYSize(ds);
  // 1. The raster's centre in WGS84 longitude/latitude.
  const std::string wgs84 = "+proj=longlat +datum=WGS84 +no_defs";
  char** opts = CSLSetNameValue(nullptr, "DST_SRS", wgs84.c_str());
  Transformer to_geo(GDALCreateGenImgProjTransformer2(ds, nullptr, opts));
  CSLDestroy(opts);
  if (!to_geo) {
    fail(file, "cannot relate the raster's coordinate system to WGS84: " +
                   GdalErrors::last("unknown error"));
  }
  double cx = src_cols / 2.0, cy = src_rows / 2.0, cz = 0;
  int ok = 0;
  if (!GDALGenImgProjTransform(to_geo.get(), FALSE, 1, &cx, &cy, &cz, &ok) || !ok ||
      !std::isfinite(cx) || !std::isfinite(cy) || std::abs(cy) > 90) {
    fail(file, "cannot locate the raster's centre in WGS84: " + GdalErrors::last("transform failed"));
  }
  const double lat_c = cy, lon_c = cx;
  const std::string tm = tm_proj_string(lat_c, lon_c);

  // 2. The suggested output grid in that TM gives the ground resolution and footprint.
  opts = CSLSetNameValue(nullptr, "DST_SRS", tm.c_str());
  Transformer to_tm(GDALCreateGenImgProjTransformer2(ds, nullptr, opts));
  CSLDestroy(opts);
  if (!to_tm) fail(file, "cannot build the warp transformer: " + GdalErrors::last("unknown error"));
  double sgt[6];
  double extent[4];
  int px = 0, ln = 0;
  if (GDALSuggestedWarpOutput2(ds, GDALGenImgProjTransform, to_tm.get(), sgt, &px, &ln, extent,
                               0) != CE_None) {
    fail(file, "cannot compute the warped grid: " + GdalErrors::last("unknown error"));
  }
  const double s = sgt[1];
  if (!(s > 0) || !std::isfinite(s)) fail(file, "the raster's ground resolution is not positive");
  // Posts at pixel centres, symmetric about the centre (TM origin), inside the footprint's box.
  const double hx = std::min(-extent[0], extent[2]), hy = std::min(-extent[1], extent[3]);
  const double mx = std::floor(hx / s - 0.5), my = std::floor(hy / s - 0.5);
  if (!(mx >= 1) || !(my >= 1)) {
    fail(file, "raster covers less than 2 x 2 posts after resampling to square posts");
  }
  if ((2 * mx + 1) * (2 * my + 1) > kMaxPosts) {
    fail(file, "raster would have more than " + fmt(kMaxPosts) + " posts after resampling");
  }
  const int cols = static_cast<int>(2 * mx + 1), rows = static_cast<int>(2 * my + 1);
  const double x1 = (mx + 0.5) * s, y1 = (my + 0.5) * s;

  // 3. Warp (bilinear) into an in-memory raster.
  const std::string te[] = {fmt(-x1), fmt(-y1), fmt(x1), fmt(y1)};
  const std::string ts[] = {std::to_string(cols), std::to_string(rows)};
  const std::string ndv = fmt(kWarpNodata);
  const char* argv[] = {"-of", "MEM", "-t_srs", tm.c_str(), "-te", te[0].c_str(), te[1].c_str(),
                        te[2].c_str(), te[3].c_str(), "-ts", ts[0].c_str(), ts[1].c_str(), "-r",
                        "bilinear", "-ot", "Float32", "-dstnodata", ndv.c_str(), "-wo",
                        "INIT_DEST=NO_DATA", nullptr};
  GDALWarpAppOptions* wopts = GDALWarpAppOptionsNew(const_cast<char**>(argv), nullptr);
  if (!wopts) fail(file, "cannot set up the warp: " + GdalErrors::last("bad options"));
  int usage_error = 0;
  GDALDatasetH src = ds;
  Dataset out(GDALWarp("", nullptr, 1, &src, wopts, &usage_error));
  GDALWarpAppOptionsFree(wopts);
  if (!out) fail(file, "warping failed: " + GdalErrors::last("unknown error"));
  if (GDALGetRasterXSize(out.get()) != cols || GDALGetRasterYSize(out.get()) != rows) {
    fail(file, "warping produced an unexpected grid size");
  }

  std::vector<float> h;
  std::vector<unsigned char> missing;
  read_band(file, out.get(), true, true, h, missing);
  fill_nodata(file, cols, rows, h, missing);

  // 4. The SW post's geodetic position; the frame built from it recovers (lat_c, lon_c).
  const geo::TransverseMercator proj(lat_c, lon_c);
  const geo::Geodetic sw = proj.inverse(-mx * s, -my * s);
  return Terrain(cols, rows, s, std::move(h), sw);
}

}  // namespace

Terrain::Terrain(int cols, int rows, double spacing_m, std::vector<float> heights,
                 const geo::Geodetic& origin)
    : cols_(cols), rows_(rows), spacing_(spacing_m), inv_spacing_(1 / spacing_m), h_(std::move(heights)), origin_(origin) {
  if (cols < 2 || rows < 2) throw std::invalid_argument("Terrain: needs at least 2 x 2 posts");
  if (!(spacing_m > 0) || !std::isfinite(spacing_m))
    throw std::invalid_argument("Terrain: spacing must be positive");
  if (h_.size() != static_cast<size_t>(cols) * rows)
    throw std::invalid_argument("Terrain: heights size is not cols * rows");
  frame_ = geo::LocalFrame(origin, width_m(), depth_m());
  block_cols_ = (cols_ - 2) / kBlock + 1;
  const long block_rows = (rows_ - 2) / kBlock + 1;
  block_lo_.assign(static_cast<size_t>(block_cols_ * block_rows), 0.0);
  bound_blocks(0, 0, block_cols_ - 1, block_rows - 1);
}

void Terrain::bound_blocks(long bi0, long bj0, long bi1, long bj1) {
  for (long bj = bj0; bj <= bj1; ++bj)
    for (long bi = bi0; bi <= bi1; ++bi) {
      // The posts of the block's cells and of the cells one around them.
      const long i0 = std::max(0L, bi * kBlock - 1), i1 = std::min<long>(cols_ - 1, bi * kBlock + kBlock + 1);
      const long j0 = std::max(0L, bj * kBlock - 1), j1 = std::min<long>(rows_ - 1, bj * kBlock + kBlock + 1);
      double lo = std::numeric_limits<double>::infinity(), big = 0;
      bool finite = true;
      for (long j = j0; j <= j1; ++j)
        for (long i = i0; i <= i1; ++i) {
          const double p = post(static_cast<int>(i), static_cast<int>(j));
          finite = finite && std::isfinite(p);
          lo = std::min(lo, p), big = std::max(big, std::abs(p));
        }
      block_lo_[static_cast<size_t>(bj * block_cols_ + bi)] =
          finite ? lo - 1e-9 * big : -std::numeric_limits<double>::infinity();
    }
}

Terrain Terrain::load(const std::filesystem::path& file, const geo::Geodetic& origin) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) fail(file, "file not found");
  if (std::filesystem::is_directory(file, ec)) fail(file, "is a directory, not a raster file");
  register_gdal();
  GdalErrors quiet;
  Dataset ds(GDALOpenEx(file.string().c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr,
                        nullptr));
  if (!ds) {
    fail(file, "not a readable raster (GDAL: " +
                   GdalErrors::last("unsupported or corrupt format") + ")");
  }
  if (GDALGetRasterCount(ds.get()) < 1) fail(file, "the raster has no bands");
  const int cols = GDALGetRasterXSize(ds.get()), rows = GDALGetRasterYSize(ds.get());
  check_size(file, cols, rows);
  OGRSpatialReferenceH srs = GDALGetSpatialRef(ds.get());
  const bool has_crs = (srs != nullptr) ||
                       (GDALGetGCPCount(ds.get()) > 0 && GDALGetGCPSpatialRef(ds.get()) != nullptr);
  return has_crs ? load_warped(file, ds.get()) : load_local(file, ds.get(), origin);
}

Vec3 Terrain::normal(double x, double y) const {
  const double u = std::clamp(x / spacing_, 0.0, static_cast<double>(cols_ - 1));
  const double v = std::clamp(y / spacing_, 0.0, static_cast<double>(rows_ - 1));
  const int i = std::min(static_cast<int>(u), cols_ - 2);
  const int j = std::min(static_cast<int>(v), rows_ - 2);
  const double fx = u - i, fy = v - j;
  const double h00 = post(i, j), h10 = post(i + 1, j), h01 = post(i, j + 1),
               h11 = post(i + 1, j + 1);
  const double dhdx = ((h10 - h00) * (1 - fy) + (h11 - h01) * fy) / spacing_;
  const double dhdy = ((h01 - h00) * (1 - fx) + (h11 - h10) * fx) / spacing_;
  return Vec3(-dhdx, -dhdy, 1.0).normalized();
}

PostRect Terrain::crater(double cx, double cy, double radius_m, double depth_m) {
  PostRect changed;  // empty
  if (!(radius_m > 0) || !(depth_m > 0) || !std::isfinite(cx) || !std::isfinite(cy) ||
      !std::isfinite(radius_m) || !std::isfinite(depth_m)) {
    return changed;
  }
  const double lo_i = std::ceil((cx - radius_m) / spacing_), hi_i = std::floor((cx + radius_m) / spacing_);
  const double lo_j = std::ceil((cy - radius_m) / spacing_), hi_j = std::floor((cy + radius_m) / spacing_);
  const int i0 = static_cast<int>(std::max(lo_i, 0.0));
  const int i1 = static_cast<int>(std::min(hi_i, static_cast<double>(cols_ - 1)));
  const int j0 = static_cast<int>(std::max(lo_j, 0.0));
  const int j1 = static_cast<int>(std::min(hi_j, static_cast<double>(rows_ - 1)));
  bool any = false;
  const double r2 = radius_m * radius_m;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const double dx = i * spacing_ - cx, dy = j * spacing_ - cy;
      const double q = (dx * dx + dy * dy) / r2;
      if (q >= 1.0) continue;
      // Smooth bowl: depth at the centre, zero with zero slope at the rim.
      const double dz = depth_m * (1.0 - q) * (1.0 - q);
      float& p = h_[static_cast<size_t>(j) * cols_ + i];
      const float lowered = static_cast<float>(p - dz);
      if (!(lowered < p)) continue;
      p = lowered;
      if (!any) changed = {i, j, i, j};
      any = true;
      changed.i0 = std::min(changed.i0, i);
      changed.j0 = std::min(changed.j0, j);
      changed.i1 = std::max(changed.i1, i);
      changed.j1 = std::max(changed.j1, j);
    }
  }
  if (any) {  // the blocks whose posts (their cells' and the cells' around) were lowered
    const long last_i = (cols_ - 2) / kBlock, last_j = (rows_ - 2) / kBlock;
    bound_blocks(std::max(0L, (changed.i0 - 1L - kBlock) / kBlock), std::max(0L, (changed.j0 - 1L - kBlock) / kBlock),
                 std::min(last_i, (changed.i1 + 1L) / kBlock), std::min(last_j, (changed.j1 + 1L) / kBlock));
  }
  return changed;
}

}  // namespace npsnet::world
