// What `npsnet check` says about a scenario's world: extent in metres and degrees, the terrain's
// coordinate system, where the local origin (SW corner) ended up, posts, objects per kind, the
// water's share of the map, vehicles per node. And the origin_geodetic warning: a raster with a
// coordinate system places itself, so origin_geodetic is ignored for it (the raster wins).
#pragma once
#include <filesystem>
#include <string>

#include "world/scenario.hpp"

namespace npsnet::node {

// The raster's coordinate system as GDAL names it (e.g. "WGS 84 / UTM zone 10N"), "" when none.
std::string raster_crs_name(const std::filesystem::path& terrain);

// Several lines, each starting with two spaces.
std::string world_summary(const world::Scenario& s, const world::World& w, const std::string& crs);

// "FILE:LINE: world.origin_geodetic: warning: ..." when the scenario gives origin_geodetic for a
// raster that has a coordinate system; "" otherwise.
std::string origin_warning(const world::Scenario& s, const world::World& w, const std::string& crs);

}  // namespace npsnet::node
