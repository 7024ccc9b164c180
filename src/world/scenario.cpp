#include "npsnet_dirs.hpp"
#include "world/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <unordered_set>

#include "world/random.hpp"
#include "world/text_file.hpp"
#include "world/toml_util.hpp"

namespace npsnet::world {

std::filesystem::path default_kinds_file() { return std::filesystem::path(NPSNET_SOURCE_DIR) / "models" / "kinds.toml"; }

namespace {

// Fields of a CSV line as std::getline(..., ',') finds them: a trailing ',' ends the last one.
size_t count_fields(std::string_view line) {
  const size_t commas = static_cast<size_t>(std::count(line.begin(), line.end(), ','));
  return 1 + commas - (!line.empty() && line.back() == ',' ? 1 : 0);
}

void check_id(TomlReader& r, const toml::node* n, const std::string& field, const std::string& id) {
  if (id.empty()) r.problem(n, field, "must not be empty");
  if (id.size() > kMaxIdLength)
    r.problem(n, field, "'" + id + "' is " + std::to_string(id.size()) + " characters; at most " +
                            std::to_string(kMaxIdLength) + " (it travels as the DIS marking)");
  for (char c : id)
    if (static_cast<unsigned char>(c) < 33 || static_cast<unsigned char>(c) > 126) {
      r.problem(n, field, "'" + id + "' must be printable ASCII without spaces");
      break;
    }
}

}  // namespace

Scenario load_scenario(const std::filesystem::path& file) {
  const std::string fname = file.string();
  if (!file_exists(file)) throw InputError(fname, 0, "file", "file not found");
  return load_scenario_text(read_text_file(file, "file"), file);
}

Scenario load_scenario_text(std::string_view text, const std::filesystem::path& file) {
  const std::string fname = file.string();
  toml::table root = parse_toml_text(text, fname);
  std::vector<Problem> problems;
  TomlReader r(fname, problems);
  Scenario s;
  s.file = file;
  const auto dir = file.parent_path();
  r.unknown_keys(root, "", {"duration_s", "world", "vehicle", "fixed", "fire", "background", "collision_method",
                          "collision_tier", "collision_budget_ms"});
  if (auto v = r.number(root, "duration_s", "duration_s", false, 0)) {
    if (*v <= 0) r.problem(root.get("duration_s"), "duration_s", "must be positive");
    else if (*v > kMaxDurationS) r.problem(root.get("duration_s"), "duration_s", range_message(0, kMaxDurationS, "s", *v));
    s.duration_s = *v;
  }
  if (auto m = r.string(root, "collision_method", "collision_method", false, 0)) {
    if (!collision_method_from_name(*m))
      r.problem(root.get("collision_method"), "collision_method", std::string(kCollisionMethodChoices) + " (got '" + *m + "')");
    s.collision_method = *m;
  }
  if (auto b = r.number_in(root, "collision_budget_ms", "collision_budget_ms", false, 0, 0, 1e6))
    s.collision_budget_ms = *b;
  if (auto m = r.string(root, "collision_tier", "collision_tier", false, 0)) {
    if (!shape_tier_from_name(*m))
      r.problem(root.get("collision_tier"), "collision_tier", std::string(kShapeTierChoices) + " (got '" + *m + "')");
    s.collision_tier = *m;
  }
  const toml::table* w = root["world"].as_table();
  if (!w) {
    r.problem(root.get("world"), "world", "missing [world] table");
  } else {
    const int wl = r.line(w);
    r.unknown_keys(*w, "world.", {"terrain", "objects", "kinds", "origin_geodetic", "water_level_m"});
    if (auto t = r.string(*w, "terrain", "world.terrain", true, wl)) {
      s.terrain = dir / *t;
      if (!file_exists(s.terrain)) r.problem(w->get("terrain"), "world.terrain", "file not found: " + s.terrain.string());
    }
    if (auto o = r.string(*w, "objects", "world.objects", false, wl)) {
      s.objects = dir / *o;
      if (!file_exists(s.objects)) r.problem(w->get("objects"), "world.objects", "file not found: " + s.objects.string());
    }
    if (auto k = r.string(*w, "kinds", "world.kinds", false, wl)) {
      s.kinds = dir / *k;
      if (!file_exists(s.kinds)) r.problem(w->get("kinds"), "world.kinds", "file not found: " + s.kinds.string());
    } else {
      s.kinds = default_kinds_file();
    }
    if (auto g = r.numbers(*w, "origin_geodetic", "world.origin_geodetic", 2, 3, false, wl)) {
      const auto& v = *g;
      if (std::abs(v[0]) > 90 || std::abs(v[1]) > 180)
        r.problem(w->get("origin_geodetic"), "world.origin_geodetic", "latitude must be within +-90 and longitude +-180 degrees");
      if (v.size() > 2 && std::abs(v[2]) > kMaxHeightM)
        r.problem(w->get("origin_geodetic"), "world.origin_geodetic", "height " + range_message(-kMaxHeightM, kMaxHeightM, "m", v[2]));
      s.origin = {v[0], v[1], v.size() > 2 ? v[2] : 0.0};
      s.origin_line = r.line(w->get("origin_geodetic"));
    }
    if (auto l = r.number_in(*w, "water_level_m", "world.water_level_m", false, wl, -kMaxHeightM, kMaxHeightM, "m"))
      s.water_level_m = *l;
  }
  std::set<std::string> ids;
  auto unique = [&](const toml::node* n, const std::string& field, const std::string& id) {
    if (!ids.insert(id).second) r.problem(n, field, "duplicate id '" + id + "'");
  };
  if (const toml::node* vn = root.get("vehicle")) {
    const toml::array* arr = vn->as_array();
    if (!arr) r.problem(vn, "vehicle", "must be an array of tables [[vehicle]]");
    for (size_t i = 0; arr && i < arr->size(); ++i) {
      const toml::table* t = (*arr)[i].as_table();
      const std::string p = "vehicle[" + std::to_string(i) + "].";
      if (!t) {
        r.problem(&(*arr)[i], p, "must be a table");
        continue;
      }
      const int tl = r.line(t);
      r.unknown_keys(*t, p, {"id", "kind", "position_m", "heading_deg", "speed_kmh", "max_speed_kmh", "waypoints_m",
                             "node", "autonomous", "snapshots", "loop", "force"});
      VehicleSpec v;
      v.line = tl;
      if (auto id = r.string(*t, "id", p + "id", true, tl)) {
        check_id(r, t->get("id"), p + "id", *id);
        unique(t->get("id"), p + "id", *id);
        v.id = *id;
      }
      v.kind = r.string(*t, "kind", p + "kind", true, tl).value_or("");
      if (auto pos = r.numbers(*t, "position_m", p + "position_m", 2, 3, true, tl)) {
        v.pos = {(*pos)[0], (*pos)[1], pos->size() > 2 ? (*pos)[2] : 0.0};
        v.has_z = pos->size() > 2;
        if (std::abs(v.pos.z()) > kMaxHeightM)
          r.problem(t->get("position_m"), p + "position_m", "z " + range_message(-kMaxHeightM, kMaxHeightM, "m", v.pos.z()));
      }
      v.heading_deg = r.number_in(*t, "heading_deg", p + "heading_deg", false, tl, -kMaxHeadingDeg, kMaxHeadingDeg, "deg").value_or(0);
      v.speed_kmh = r.number_in(*t, "speed_kmh", p + "speed_kmh", false, tl, 0, kMaxSpeedKmh, "km/h").value_or(0);
      v.max_speed_kmh = r.number_in(*t, "max_speed_kmh", p + "max_speed_kmh", false, tl, 0, kMaxSpeedKmh, "km/h");
      if (v.max_speed_kmh && *v.max_speed_kmh <= 0) r.problem(t->get("max_speed_kmh"), p + "max_speed_kmh", "must be positive");
      if (const toml::node* wn = t->get("waypoints_m")) {
        const toml::array* wa = wn->as_array();
        bool ok = wa != nullptr;
        for (size_t k = 0; ok && k < wa->size(); ++k) {
          const toml::array* pt = (*wa)[k].as_array();
          ok = pt && pt->size() == 2 && (*pt)[0].is_number() && (*pt)[1].is_number();
          if (ok) {
            Vec2 q((*pt)[0].value<double>().value_or(0), (*pt)[1].value<double>().value_or(0));
            if (!q.allFinite()) {
              r.problem(wn, p + "waypoints_m", "must be finite");
              ok = true;
              break;
            }
            v.waypoints.push_back(q);
          }
        }
        if (!ok) r.problem(wn, p + "waypoints_m", "must be an array of [x, y] pairs");
      }
      if (auto n = r.number(*t, "node", p + "node", false, tl)) {
        if (*n < 1 || *n > 65535 || *n != std::floor(*n)) r.problem(t->get("node"), p + "node", "must be an integer 1-65535");
        else v.node = static_cast<int>(*n);
      }
      v.autonomous = r.boolean(*t, "autonomous", p + "autonomous").value_or(false);
      v.snapshots = r.boolean(*t, "snapshots", p + "snapshots").value_or(true);
      v.loop = r.boolean(*t, "loop", p + "loop").value_or(false);
      if (auto f = r.string(*t, "force", p + "force", false, tl)) {  // IEEE 1278.1 Force ID
        if (*f == "friendly") v.force = 1;
        else if (*f == "opposing") v.force = 2;
        else if (*f == "neutral") v.force = 3;
        else r.problem(t->get("force"), p + "force", "must be friendly, opposing or neutral (got '" + *f + "')");
      }
      s.vehicles.push_back(std::move(v));
    }
  }
  if (const toml::node* fnode = root.get("fixed")) {
    const toml::array* arr = fnode->as_array();
    if (!arr) r.problem(fnode, "fixed", "must be an array of tables [[fixed]]");
    for (size_t i = 0; arr && i < arr->size(); ++i) {
      const toml::table* t = (*arr)[i].as_table();
      const std::string p = "fixed[" + std::to_string(i) + "].";
      if (!t) continue;
      const int tl = r.line(t);
      r.unknown_keys(*t, p, {"id", "kind", "position_m", "heading_deg"});
      FixedSpec f;
      f.line = tl;
      if (auto id = r.string(*t, "id", p + "id", true, tl)) {
        check_id(r, t->get("id"), p + "id", *id);
        unique(t->get("id"), p + "id", *id);
        f.id = *id;
      }
      f.kind = r.string(*t, "kind", p + "kind", true, tl).value_or("");
      if (auto pos = r.numbers(*t, "position_m", p + "position_m", 2, 2, true, tl)) f.pos = {(*pos)[0], (*pos)[1]};
      f.heading_deg = r.number_in(*t, "heading_deg", p + "heading_deg", false, tl, -kMaxHeadingDeg, kMaxHeadingDeg, "deg").value_or(0);
      s.fixed.push_back(std::move(f));
    }
  }
  if (const toml::node* fnode = root.get("fire")) {
    const toml::array* arr = fnode->as_array();
    if (!arr) r.problem(fnode, "fire", "must be an array of tables [[fire]]");
    for (size_t i = 0; arr && i < arr->size(); ++i) {
      const toml::table* t = (*arr)[i].as_table();
      const std::string p = "fire[" + std::to_string(i) + "].";
      if (!t) continue;
      const int tl = r.line(t);
      r.unknown_keys(*t, p, {"t_s", "shooter", "munition", "target_m", "target"});
      FireSpec f;
      f.line = tl;
      f.t_s = r.number_in(*t, "t_s", p + "t_s", true, tl, 0, kMaxDurationS, "s").value_or(0);
      f.shooter = r.string(*t, "shooter", p + "shooter", true, tl).value_or("");
      f.munition = r.string(*t, "munition", p + "munition", true, tl).value_or("");
      f.target = r.string(*t, "target", p + "target", false, tl).value_or("");
      if (auto tm = r.numbers(*t, "target_m", p + "target_m", 2, 2, false, tl)) f.target_m = Vec2((*tm)[0], (*tm)[1]);
      if (f.target.empty() == !f.target_m.has_value()) r.problem(tl, p + "target", "give exactly one of target or target_m");
      s.fires.push_back(std::move(f));
    }
  }
  if (const toml::table* b = root["background"].as_table()) {
    const int bl = r.line(b);
    r.unknown_keys(*b, "background.", {"vehicles", "seed", "exclude_m", "area_m"});
    if (auto n = r.number(*b, "vehicles", "background.vehicles", true, bl)) {
      if (*n < 0 || *n > 1e6 || *n != std::floor(*n)) r.problem(b->get("vehicles"), "background.vehicles", "must be an integer 0-1000000");
      else s.background_vehicles = static_cast<int>(*n);
    }
    if (auto n = r.number_in(*b, "seed", "background.seed", false, bl, 0, 9007199254740992.0)) {
      if (*n != std::floor(*n)) r.problem(b->get("seed"), "background.seed", "must be an integer");
      s.background_seed = static_cast<uint64_t>(*n);
    }
    if (auto e = r.numbers(*b, "exclude_m", "background.exclude_m", 4, 4, false, bl))
      s.background_exclude = std::make_pair(Vec2((*e)[0], (*e)[1]), Vec2((*e)[2], (*e)[3]));
    if (auto a = r.numbers(*b, "area_m", "background.area_m", 4, 4, false, bl)) {
      if (!((*a)[0] < (*a)[2] && (*a)[1] < (*a)[3])) r.problem(b->get("area_m"), "background.area_m", "must be [x0, y0, x1, y1] with x0 < x1 and y0 < y1");
      else s.background_area = std::make_pair(Vec2((*a)[0], (*a)[1]), Vec2((*a)[2], (*a)[3]));
    }
  }
  // Fire references resolve against scenario ids (vehicles); munition kinds are checked with the world.
  for (size_t i = 0; i < s.fires.size(); ++i) {
    const auto& f = s.fires[i];
    const std::string p = "fire[" + std::to_string(i) + "].";
    bool shooter = false;
    for (const auto& v : s.vehicles) shooter = shooter || v.id == f.shooter;
    if (!f.shooter.empty() && !shooter) r.problem(f.line, p + "shooter", "no vehicle with id '" + f.shooter + "'");
    if (!f.target.empty() && !ids.count(f.target)) r.problem(f.line, p + "target", "no vehicle or fixed object with id '" + f.target + "'");
  }
  if (!problems.empty()) throw InputError(std::move(problems));
  return s;
}

void load_objects_csv(const std::filesystem::path& file, const KindTable& kinds, const Terrain& terrain,
                      double water_level_m, FixedObjects& out, std::vector<Problem>& problems) {
  std::string text;
  try {
    text = read_text_file(file, "objects");
  } catch (const InputError& e) {
    problems.insert(problems.end(), e.problems().begin(), e.problems().end());
    return;
  }
  load_objects_csv_text(text, file, kinds, terrain, water_level_m, out, problems);
}

void load_objects_csv_text(std::string_view text, const std::filesystem::path& file, const KindTable& kinds,
                           const Terrain& terrain, double water_level_m, FixedObjects& out,
                           std::vector<Problem>& problems) {
  const std::string fname = file.string();
  std::unordered_set<std::string> ids;
  ids.reserve(out.size() * 2 + 1024);
  for (const auto& id : out.id) ids.insert(id);
  int ln = 0;
  // Lines and fields as std::getline splits them ('\n'; then ',', where a trailing ',' makes no
  // empty last field), without a stream per line: a 40,000-object file is 40,000 lines.
  std::vector<std::string> cols;
  size_t ncols = 0;
  for (size_t at = 0; at < text.size();) {
    const size_t nl = text.find('\n', at);
    std::string_view line = text.substr(at, nl == std::string_view::npos ? std::string_view::npos : nl - at);
    at = nl == std::string_view::npos ? text.size() : nl + 1;
    ++ln;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line[0] == '#') continue;
    if (ln == 1 && line.starts_with("id,")) continue;  // header
    ncols = 0;
    for (size_t f = 0; f < line.size() && ncols <= 5;) {
      const size_t comma = line.find(',', f);
      const std::string_view c = line.substr(f, comma == std::string_view::npos ? std::string_view::npos : comma - f);
      if (cols.size() <= ncols) cols.emplace_back();
      cols[ncols++].assign(c);
      f = comma == std::string_view::npos ? line.size() : comma + 1;
    }
    if (ncols < 4 || ncols > 5) {
      problems.push_back({fname, ln, "line", "expected id,kind,x_m,y_m[,heading_deg] (got " + std::to_string(count_fields(line)) + " fields)"});
      continue;
    }
    const std::string& id = cols[0];
    if (id.empty() || id.size() > kMaxIdLength)
      problems.push_back({fname, ln, "id", "'" + id + "' must be 1 to " + std::to_string(kMaxIdLength) + " characters"});
    const bool dup = !ids.insert(id).second;
    if (dup) problems.push_back({fname, ln, "id", "duplicate id '" + id + "'"});
    const int k = kinds.find(cols[1]);
    if (k < 0) problems.push_back({fname, ln, "kind", "unknown kind '" + cols[1] + "' (known: " + kinds.names() + ")"});
    else if (kinds[k].mobile()) problems.push_back({fname, ln, "kind", "'" + cols[1] + "' is not a fixed kind"});
    double v[3] = {0, 0, 0};
    bool ok = true;
    static const char* names[3] = {"x_m", "y_m", "heading_deg"};
    for (size_t c = 2; c < ncols; ++c) {
      char* end = nullptr;
      v[c - 2] = std::strtod(cols[c].c_str(), &end);
      if (end == cols[c].c_str() || *end != '\0' || !std::isfinite(v[c - 2])) {
        problems.push_back({fname, ln, names[c - 2], "'" + cols[c] + "' is not a finite number"});
        ok = false;
      } else if (c == 4 && std::abs(v[2]) > kMaxHeadingDeg) {
        problems.push_back({fname, ln, names[2], range_message(-kMaxHeadingDeg, kMaxHeadingDeg, "deg", v[2])});
        ok = false;
      }
    }
    if (!ok || k < 0 || dup) continue;
    if (!terrain.contains(v[0], v[1])) {
      problems.push_back({fname, ln, "position", "(" + cols[2] + ", " + cols[3] + ") is off the map"});
      continue;
    }
    if (terrain.height(v[0], v[1]) < water_level_m) {
      problems.push_back({fname, ln, "position", "(" + cols[2] + ", " + cols[3] + ") is in water"});
      continue;
    }
    out.add(id, k, Vec3(v[0], v[1], terrain.height(v[0], v[1])), static_cast<float>(v[2]),
            static_cast<float>(kinds[k].radius_m));
  }
}

World build_world(const Scenario& s) {
  std::vector<Problem> problems;
  World w;
  const std::string sf = s.file.string();
  w.terrain = Terrain::load(s.terrain, s.origin);
  w.kinds = KindTable::load(s.kinds, w.models);
  w.water_level_m = s.water_level_m;
  if (!s.objects.empty()) load_objects_csv(s.objects, w.kinds, w.terrain, w.water_level_m, w.fixed, problems);
  std::unordered_set<std::string> ids(w.fixed.id.begin(), w.fixed.id.end());
  for (size_t i = 0; i < s.fixed.size(); ++i) {
    const auto& f = s.fixed[i];
    const std::string p = "fixed[" + std::to_string(i) + "].";
    const int k = w.kinds.find(f.kind);
    if (k < 0) problems.push_back({sf, f.line, p + "kind", "unknown kind '" + f.kind + "' (known: " + w.kinds.names() + ")"});
    else if (w.kinds[k].mobile()) problems.push_back({sf, f.line, p + "kind", "'" + f.kind + "' is not a fixed kind"});
    if (!w.terrain.contains(f.pos.x(), f.pos.y())) problems.push_back({sf, f.line, p + "position_m", "off the map"});
    if (!ids.insert(f.id).second) problems.push_back({sf, f.line, p + "id", "duplicate id '" + f.id + "' (also in the objects file)"});
    if (k >= 0 && !w.kinds[k].mobile() && w.terrain.contains(f.pos.x(), f.pos.y()))
      w.fixed.add(f.id, k, Vec3(f.pos.x(), f.pos.y(), w.terrain.height(f.pos.x(), f.pos.y())),
                  static_cast<float>(f.heading_deg), static_cast<float>(w.kinds[k].radius_m));
  }
  auto place = [&](const VehicleSpec& v, int k, const std::string& p, const std::string& file, int line) {
    const Kind& kind = w.kinds[k];
    const bool on_map = w.terrain.contains(v.pos.x(), v.pos.y());
    if (!on_map) {
      problems.push_back({file, line, p + "position_m", "(" + std::to_string(v.pos.x()) + ", " + std::to_string(v.pos.y()) +
                                                           ") is off the map (0..." + std::to_string(w.terrain.width_m()) + ")"});
      return;
    }
    const bool water = w.is_water(v.pos.x(), v.pos.y());
    if (kind.mobility == Mobility::Ground && water) problems.push_back({file, line, p + "position_m", "a ground vehicle cannot start in water"});
    if (kind.mobility == Mobility::Ship && !water) problems.push_back({file, line, p + "position_m", "a ship must start in water"});
    if (kind.mobility == Mobility::Munition) problems.push_back({file, line, p + "kind", "a munition is fired, not placed"});
    for (size_t q = 0; q < v.waypoints.size(); ++q)
      if (!w.terrain.contains(v.waypoints[q].x(), v.waypoints[q].y()))
        problems.push_back({file, line, p + "waypoints_m", "waypoint " + std::to_string(q + 1) + " is off the map"});
    double z = w.terrain.height(v.pos.x(), v.pos.y());
    if (kind.mobility == Mobility::Ship) z = w.water_level_m;
    if (v.has_z) z = v.pos.z();
    const int e = w.ents.add(v.id, k, Vec3(v.pos.x(), v.pos.y(), z), static_cast<float>(v.heading_deg),
                             static_cast<float>(kind.radius_m));
    const double limit = v.max_speed_kmh.value_or(kind.max_speed_kmh);
    w.ents.max_mps[e] = static_cast<float>(kmh2mps(limit));
    w.ents.cruise_mps[e] = static_cast<float>(kmh2mps(std::min(v.speed_kmh, limit)));
    const Vec2 d = heading_to_dir(v.heading_deg);
    w.ents.vel[e] = Vec3(d.x(), d.y(), 0) * w.ents.cruise_mps[e];
    w.ents.autonomous[e] = v.autonomous;
    w.ents.snapshots[e] = v.snapshots;
    w.ents.rounds[e] = kind.rounds;
    w.ents.fuel_l[e] = static_cast<float>(kind.fuel_l);
    w.ents.node[e] = v.node;
    w.ents.force[e] = v.force;
    w.ents.route[e] = v.waypoints;
    w.ents.loop_route[e] = v.loop;
  };
  for (size_t i = 0; i < s.vehicles.size(); ++i) {
    const auto& v = s.vehicles[i];
    const std::string p = "vehicle[" + std::to_string(i) + "].";
    const int k = w.kinds.find(v.kind);
    if (k < 0) {
      problems.push_back({sf, v.line, p + "kind", "unknown kind '" + v.kind + "' (known: " + w.kinds.names() + ")"});
      continue;
    }
    if (!ids.insert(v.id).second) problems.push_back({sf, v.line, p + "id", "duplicate id '" + v.id + "' (also a fixed object)"});
    place(v, k, p, sf, v.line);
  }
  for (size_t i = 0; i < s.fires.size(); ++i) {
    const int k = w.kinds.find(s.fires[i].munition);
    if (k < 0 || w.kinds[k].mobility != Mobility::Munition)
      problems.push_back({sf, s.fires[i].line, "fire[" + std::to_string(i) + "].munition",
                          "'" + s.fires[i].munition + "' is not a munition kind"});
  }
  if (!problems.empty()) throw InputError(std::move(problems));
  // Background traffic: ground vehicles on land driving waypoints over the whole map (the
  // thesis's load of 500 vehicles, p. 1), never in the excluded area, never snapshotted.
  if (s.background_vehicles > 0) {
    Rng rng(s.background_seed);
    const char* bg_kinds[] = {"m1a1", "hmmwv", "bmp"};
    Vec2 lo(200, 200), hi(w.terrain.width_m() - 200, w.terrain.depth_m() - 200);
    if (s.background_area) lo = lo.cwiseMax(s.background_area->first), hi = hi.cwiseMin(s.background_area->second);
    if (!(lo.x() < hi.x() && lo.y() < hi.y()))
      throw InputError(sf, 0, "background.area_m", "lies outside the terrain (less 200 m at its edges)");
    auto free_spot = [&](Vec2& out) {
      for (int tries = 0; tries < 1000; ++tries) {
        Vec2 q(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()));
        if (w.is_water(q.x(), q.y())) continue;
        if (s.background_exclude) {
          const auto& [lo, hi] = *s.background_exclude;
          if (q.x() >= lo.x() - 500 && q.x() <= hi.x() + 500 && q.y() >= lo.y() - 500 && q.y() <= hi.y() + 500) continue;
        }
        out = q;
        return true;
      }
      return false;
    };
    for (int n = 0; n < s.background_vehicles; ++n) {
      const int k = w.kinds.find(bg_kinds[rng.below(3)]);
      if (k < 0) throw InputError(s.kinds.string(), 0, "kinds", "background traffic needs kinds m1a1, hmmwv, bmp");
      VehicleSpec v;
      char id[16];
      std::snprintf(id, sizeof id, "bg%05d", n);
      v.id = id;
      Vec2 q;
      if (!free_spot(q)) break;
      v.pos = Vec3(q.x(), q.y(), 0);
      for (int k2 = 0; k2 < 4; ++k2) {
        Vec2 wp;
        if (free_spot(wp)) v.waypoints.push_back(q + (wp - q).normalized() * std::min((wp - q).norm(), 3000.0));
      }
      v.heading_deg = v.waypoints.empty() ? 0 : dir_to_heading(v.waypoints[0] - q);
      v.speed_kmh = rng.uniform(15, 55);
      v.snapshots = false;
      v.loop = true;
      place(v, k, "background.", sf, 0);
    }
  }
  w.index_fixed();
  return w;
}

}  // namespace npsnet::world
