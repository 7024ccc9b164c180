// Scenario files (TOML, shared/ARCHITECTURE.md) and the world they build. Paths inside a file are
// relative to that file's folder. load_scenario checks syntax and fields; build_world loads the
// terrain, kinds, models and objects and checks what needs them (unknown kind, off the map, in
// water). Both throw InputError with every problem as FILE:LINE: field: message.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "world/error.hpp"
#include "world/limits.hpp"
#include "world/world.hpp"

namespace npsnet::world {

inline constexpr size_t kMaxIdLength = 11;  // the DIS marking's 11 characters

struct VehicleSpec {
  std::string id, kind;
  Vec3 pos{0, 0, 0};
  bool has_z = false;
  double heading_deg = 0, speed_kmh = 0;
  std::optional<double> max_speed_kmh;
  std::vector<Vec2> waypoints;
  int node = 1;
  bool autonomous = false, snapshots = true;
  bool loop = false;  // drives its waypoints over and over (background traffic)
  uint8_t force = 1;  // `force`: DIS Force ID, 1 "friendly" (default), 2 "opposing", 3 "neutral"
  int line = 0;
};

struct FixedSpec {
  std::string id, kind;
  Vec2 pos{0, 0};
  double heading_deg = 0;
  int line = 0;
};

struct FireSpec {
  double t_s = 0;
  std::string shooter, munition, target;  // target: an id, or empty when target_m is given
  std::optional<Vec2> target_m;
  int line = 0;
};

struct Scenario {
  std::filesystem::path file;
  double duration_s = 60;
  std::filesystem::path terrain, objects, kinds;
  geo::Geodetic origin{35.98, -121.25, 0.0};
  int origin_line = 0;  // where origin_geodetic was given; 0 = not given (the default above)
  double water_level_m = -1e9;
  // "continuous" (swept spheres, border objects, N-body, shape tiers: issue 6) or "thesis" (the
  // 1991 method, issue 3); collision_tier forces one shape tier for every pair ("auto": each
  // pair takes the cheapest tier that decides it). collision/collision.hpp parses both.
  std::string collision_method = "continuous";
  std::string collision_tier = "auto";
  // The auto tier's per-tick budget of modelled narrow-phase time (ms, >= 0; collision.hpp).
  double collision_budget_ms = kDefaultCollisionBudgetMs;
  std::vector<VehicleSpec> vehicles;
  std::vector<FixedSpec> fixed;
  std::vector<FireSpec> fires;
  int background_vehicles = 0;
  uint64_t background_seed = 1;
  // A region kept free of background traffic (the Appendix A cases live there).
  std::optional<std::pair<Vec2, Vec2>> background_exclude;
  // The region background traffic is placed and driven in ([x0, y0], [x1, y1], m; default: the
  // whole map less 200 m at the edges): a crowd, for the threading test and the tick benchmark.
  std::optional<std::pair<Vec2, Vec2>> background_area;
};

Scenario load_scenario(const std::filesystem::path& file);
// The same from `text`, the contents of `file` (its folder resolves the paths inside).
Scenario load_scenario_text(std::string_view text, const std::filesystem::path& file);
World build_world(const Scenario& s);

// Reads a fixed-object CSV (id,kind,x_m,y_m,heading_deg) into `out`, checking each line.
void load_objects_csv(const std::filesystem::path& file, const KindTable& kinds, const Terrain& terrain,
                      double water_level_m, FixedObjects& out, std::vector<Problem>& problems);
// The same from `text`, the contents of `file` (named in problems).
void load_objects_csv_text(std::string_view text, const std::filesystem::path& file, const KindTable& kinds,
                           const Terrain& terrain, double water_level_m, FixedObjects& out,
                           std::vector<Problem>& problems);

// The bundled kinds file (models/kinds.toml in the source tree).
std::filesystem::path default_kinds_file();

}  // namespace npsnet::world
