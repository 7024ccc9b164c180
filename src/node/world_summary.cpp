#include "node/world_summary.hpp"

#include <gdal.h>
#include <ogr_srs_api.h>

#include <cpl_error.h>

#include <cstdio>
#include <map>

namespace npsnet::node {

std::string raster_crs_name(const std::filesystem::path& terrain) {
  GDALAllRegister();
  CPLPushErrorHandler(CPLQuietErrorHandler);
  GDALDatasetH ds = GDALOpenEx(terrain.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
  std::string name;
  if (ds) {
    OGRSpatialReferenceH srs = GDALGetSpatialRef(ds);
    if (!srs && GDALGetGCPCount(ds) > 0) srs = GDALGetGCPSpatialRef(ds);
    if (srs) {
      const char* n = OSRGetName(srs);
      name = n && *n ? n : "unnamed coordinate system";
      const char* auth = OSRGetAuthorityName(srs, nullptr);
      const char* code = OSRGetAuthorityCode(srs, nullptr);
      if (auth && code) name += std::string(" (") + auth + ":" + code + ")";
    }
    GDALClose(ds);
  }
  CPLPopErrorHandler();
  return name;
}

std::string world_summary(const world::Scenario& s, const world::World& w, const std::string& crs) {
  const world::Terrain& t = w.terrain;
  const geo::Geodetic sw = t.frame().to_geodetic(Vec3(0, 0, 0));
  const geo::Geodetic ne = t.frame().to_geodetic(Vec3(t.width_m(), t.depth_m(), 0));
  std::string out;
  char b[512];
  std::snprintf(b, sizeof b, "  terrain: %s\n  coordinate system: %s\n", s.terrain.string().c_str(),
                crs.empty() ? "none: the raster is taken as local metres, its SW corner at origin_geodetic" : crs.c_str());
  out += b;
  std::snprintf(b, sizeof b,
                "  extent: x 0 to %.2f m (east), y 0 to %.2f m (north); %d x %d posts at %.3f m\n"
                "  origin (SW corner, local 0,0): lat %.6f, lon %.6f%s\n"
                "  NE corner: lat %.6f, lon %.6f; %.4f x %.4f degrees (lon x lat)\n",
                t.width_m(), t.depth_m(), t.cols(), t.rows(), t.spacing_m(), sw.lat_deg, sw.lon_deg,
                crs.empty() ? " (from origin_geodetic)" : " (from the raster's coordinate system)", ne.lat_deg, ne.lon_deg,
                ne.lon_deg - sw.lon_deg, ne.lat_deg - sw.lat_deg);
  out += b;
  size_t wet = 0;
  float lo = t.posts().empty() ? 0 : t.posts()[0], hi = lo;
  for (float h : t.posts()) {
    wet += h < w.water_level_m;
    lo = std::min(lo, h), hi = std::max(hi, h);
  }
  char level[64] = "no water level";
  if (w.water_level_m >= -1e8) std::snprintf(level, sizeof level, "%.2f m", w.water_level_m);
  std::snprintf(b, sizeof b, "  heights: %.1f to %.1f m; water (below %s): %.2f %% of the posts\n", lo, hi, level,
                100.0 * static_cast<double>(wet) / static_cast<double>(std::max<size_t>(1, t.posts().size())));
  out += b;
  std::map<std::string, int> kinds;
  for (size_t o = 0; o < w.fixed.size(); ++o) kinds[w.kinds[w.fixed.kind[o]].name] += 1;
  out += "  fixed objects: " + std::to_string(w.fixed.size());
  for (const auto& [k, n] : kinds) out += (k == kinds.begin()->first ? " (" : ", ") + k + " " + std::to_string(n);
  out += kinds.empty() ? "\n" : ")\n";
  std::map<int, std::map<std::string, int>> nodes;
  for (const auto& v : s.vehicles) nodes[v.node][v.kind] += 1;
  out += "  vehicles: " + std::to_string(s.vehicles.size()) + " in the scenario";
  if (s.background_vehicles > 0) out += " + " + std::to_string(s.background_vehicles) + " background (node 1)";
  out += "\n";
  for (const auto& [node, ks] : nodes) {
    out += "    node " + std::to_string(node) + ":";
    for (const auto& [k, n] : ks) out += " " + k + " " + std::to_string(n);
    out += "\n";
  }
  return out;
}

std::string origin_warning(const world::Scenario& s, const world::World& w, const std::string& crs) {
  if (crs.empty() || s.origin_line <= 0) return "";
  const geo::Geodetic sw = w.terrain.origin();
  char b[512];
  std::snprintf(b, sizeof b,
                "%s:%d: world.origin_geodetic: warning: ignored: the terrain has a coordinate system (%s), which "
                "places it; its SW corner is at lat %.6f, lon %.6f (remove origin_geodetic, or use a raster without one)",
                s.file.string().c_str(), s.origin_line, crs.c_str(), sw.lat_deg, sw.lon_deg);
  return b;
}

}  // namespace npsnet::node
