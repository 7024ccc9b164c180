// Rasters and coordinates read through GDAL / PROJ on their own, for tests that check what the
// node says about a terrain against the file itself. Header-only.
#pragma once
#include <gdal.h>
#include <ogr_srs_api.h>

#include <filesystem>
#include <string>
#include <vector>

namespace npsnet::test {

struct RasterGrid {
  int cols = 0, rows = 0;
  double gt[6] = {};  // GDAL geotransform: x0, dx, 0, y0, 0, dy (pixel corners)
  std::string epsg;   // the CRS's EPSG code, "" when none
  std::vector<float> h;  // band 1, row 0 = north; empty when unreadable
};

inline RasterGrid read_raster_grid(const std::filesystem::path& f) {
  GDALAllRegister();
  RasterGrid g;
  GDALDatasetH ds = GDALOpen(f.c_str(), GA_ReadOnly);
  if (!ds) return g;
  g.cols = GDALGetRasterXSize(ds), g.rows = GDALGetRasterYSize(ds);
  GDALGetGeoTransform(ds, g.gt);
  if (OGRSpatialReferenceH srs = GDALGetSpatialRef(ds)) {
    const char* code = OSRGetAuthorityCode(srs, nullptr);
    g.epsg = code ? code : "";
  }
  g.h.resize(static_cast<size_t>(g.cols) * g.rows);
  if (GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, 0, 0, g.cols, g.rows, g.h.data(), g.cols, g.rows, GDT_Float32, 0, 0) !=
      CE_None)
    g.h.clear();
  GDALClose(ds);
  return g;
}

// Transforms n points (x = easting or lon, y = northing or lat) from EPSG `from` to EPSG `to`
// in place through PROJ; false when PROJ cannot.
inline bool transform_epsg(int from, int to, double* x, double* y, int n) {
  OGRSpatialReferenceH src = OSRNewSpatialReference(nullptr), dst = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(src, from);
  OSRImportFromEPSG(dst, to);
  OSRSetAxisMappingStrategy(src, OAMS_TRADITIONAL_GIS_ORDER);
  OSRSetAxisMappingStrategy(dst, OAMS_TRADITIONAL_GIS_ORDER);
  OGRCoordinateTransformationH ct = OCTNewCoordinateTransformation(src, dst);
  const bool ok = ct && OCTTransform(ct, n, x, y, nullptr);
  if (ct) OCTDestroyCoordinateTransformation(ct);
  OSRDestroySpatialReference(src);
  OSRDestroySpatialReference(dst);
  return ok;
}

}  // namespace npsnet::test
