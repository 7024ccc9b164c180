#include "world/kinds.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "world/limits.hpp"
#include "world/text_file.hpp"
#include "world/toml_util.hpp"

namespace npsnet::world {

const char* mobility_name(Mobility m) {
  switch (m) {
    case Mobility::Fixed: return "fixed";
    case Mobility::Ground: return "ground";
    case Mobility::Ship: return "ship";
    case Mobility::Air: return "air";
    case Mobility::Munition: return "munition";
  }
  return "?";
}

int Kind::state_index(const std::string& s) const {
  for (size_t i = 0; i < states.size(); ++i)
    if (states[i] == s) return static_cast<int>(i);
  return -1;
}

namespace {
// Table 2 (p. 11): the speed limit of a vehicle kind that does not set its own.
double table2_limit_kmh(Mobility m) {
  switch (m) {
    case Mobility::Ground: return thesis::kTable2GroundKmh;
    case Mobility::Ship: return thesis::kTable2ShipKmh;
    case Mobility::Air: return thesis::kTable2AirKmh;
    default: return 0;
  }
}
// What a vehicle must see, for the area of interest (--aoi), when its kind does not say:
// tank gunnery and ground sensors reach a few km, a ship's radar horizon about 10 km, an
// aircraft's air-to-ground sensors about 20 km.
double default_sensor_range_m(Mobility m) {
  switch (m) {
    case Mobility::Ground: return 5000.0;
    case Mobility::Ship: return 10000.0;
    case Mobility::Air: return 20000.0;
    default: return 0;
  }
}

// Driving data (dynamics/drive.hpp): vehicle handling, not thesis constants. A kind that does not
// give a value takes its mobility's default (ground: a tracked vehicle; ship: a patrol boat; air:
// a helicopter-like craft).
struct Handling {
  double accel, brake, turn_radius, climb;
};
Handling default_handling(Mobility m) {
  switch (m) {
    case Mobility::Ground: return {1.5, 4.0, 8.0, 0.0};
    case Mobility::Ship: return {0.3, 0.3, 150.0, 0.0};
    case Mobility::Air: return {4.0, 4.0, 100.0, 10.0};
    default: return {0, 0, 0, 0};
  }
}

void read_handling(TomlReader& r, const toml::table& t, const std::string& p, int tl, Kind& k) {
  const Handling d = default_handling(k.mobility);
  auto positive = [&](const char* key, double def) {
    const double v = r.number(t, key, p + key, false, tl).value_or(def);
    if (!(v >= 0)) r.problem(t.get(key), p + key, "must not be negative");
    return v;
  };
  k.fuel_lph = positive("fuel_lph", 0);
  k.accel_mps2 = positive("accel_mps2", d.accel);
  k.brake_mps2 = positive("brake_mps2", d.brake);
  k.turn_radius_m = positive("turn_radius_m", d.turn_radius);
  k.climb_mps = positive("climb_mps", d.climb);
  k.munition = r.string(t, "munition", p + "munition", false, tl).value_or("");
}
}  // namespace

KindTable KindTable::load(const std::filesystem::path& file, ModelLibrary& models) {
  if (!file_exists(file)) throw InputError(file.string(), 0, "file", "file not found");
  return load_text(read_text_file(file, "file"), file, models);
}

KindTable KindTable::load_text(std::string_view text, const std::filesystem::path& file, ModelLibrary& models) {
  const std::string fname = file.string();
  toml::table root = parse_toml_text(text, fname);
  std::vector<Problem> problems;
  TomlReader r(fname, problems);
  KindTable out;
  out.file_ = file;
  for (const auto& [key, node] : root) {
    const std::string name(key.str());
    const toml::table* t = node.as_table();
    if (!t) {
      r.problem(&node, name, "each kind must be a table [name]");
      continue;
    }
    const int tl = r.line(t);
    const std::string p = name + ".";
    r.unknown_keys(*t, p, {"mobility", "mass_kg", "radius_m", "states", "models", "explosive", "max_speed_kmh",
                           "dis_type", "blast_radius_m", "crater_radius_m", "crater_depth_m", "rounds", "fuel_l", "resistance",
                           "tiers", "trunk_radius_m", "sensor_range_m", "guided", "munition", "fuel_lph", "accel_mps2", "brake_mps2",
                           "turn_radius_m", "climb_mps"});
    Kind k;
    k.name = name;
    if (auto m = r.string(*t, "mobility", p + "mobility", true, tl)) {
      static const std::pair<const char*, Mobility> names[] = {{"fixed", Mobility::Fixed}, {"ground", Mobility::Ground},
          {"ship", Mobility::Ship}, {"air", Mobility::Air}, {"munition", Mobility::Munition}};
      bool found = false;
      for (auto& [s, v] : names)
        if (*m == s) k.mobility = v, found = true;
      if (!found) r.problem(t->get("mobility"), p + "mobility", "must be fixed, ground, ship, air or munition (got '" + *m + "')");
    }
    if (auto v = r.number_in(*t, "mass_kg", p + "mass_kg", true, tl, -kMaxMassKg, kMaxMassKg, "kg")) {
      if (*v <= 0) r.problem(t->get("mass_kg"), p + "mass_kg", "must be positive (got " + std::to_string(*v) + ")");
      k.mass_kg = *v;
    }
    auto states = r.strings(*t, "states", p + "states", true, tl);
    auto files = r.strings(*t, "models", p + "models", true, tl);
    if (states && files && states->size() != files->size())
      r.problem(t->get("models"), p + "models", "needs one model per state (" + std::to_string(states->size()) +
                                                    " states, " + std::to_string(files->size()) + " models)");
    else if (states && files) {
      k.states = *states;
      for (size_t i = 0; i < files->size(); ++i) {
        try {
          k.models.push_back(models.load(file.parent_path() / (*files)[i]));
        } catch (const InputError& e) {
          // The model's own problems, then where the kinds file named it.
          for (const auto& q : e.problems()) problems.push_back(q);
          r.problem(t->get("models"), p + "models", "cannot load '" + (*files)[i] + "'");
        }
      }
    }
    if (auto v = r.number_in(*t, "radius_m", p + "radius_m", false, tl, -kMaxSizeM, kMaxSizeM, "m")) {
      if (*v <= 0) r.problem(t->get("radius_m"), p + "radius_m", "must be positive");
      k.radius_m = *v;
    } else if (!k.models.empty()) {
      // "A slightly smaller value than the actual radius of the object is used" (p. 14).
      k.radius_m = thesis::kBoundingRadiusFraction * models[k.models[0]].true_radius;
    }
    if (!k.models.empty()) k.height_m = models[k.models[0]].bbox_max.z();
    for (int mi : k.models) {
      const Model& m = models[mi];
      const float r0 = models[k.models[0]].true_radius;
      k.radius_by_state.push_back(static_cast<float>(k.radius_m) * (r0 > 0 ? m.true_radius / r0 : 1.0f));
      k.centre_by_state.push_back(m.centre);
    }
    k.explosive = r.boolean(*t, "explosive", p + "explosive").value_or(false);
    k.max_speed_kmh = r.number_in(*t, "max_speed_kmh", p + "max_speed_kmh", false, tl, -kMaxSpeedKmh, kMaxSpeedKmh, "km/h")
                          .value_or(table2_limit_kmh(k.mobility));
    if (k.max_speed_kmh < 0) r.problem(t->get("max_speed_kmh"), p + "max_speed_kmh", "must not be negative");
    if (auto d = r.numbers(*t, "dis_type", p + "dis_type", 7, 7, true, tl)) {
      const auto& v = *d;
      bool fits = true;  // a value cast to an octet it does not fit is undefined (fuzz finding)
      for (size_t i = 0; i < 7 && fits; ++i) {
        const double hi = i == 2 ? 65535 : 255;  // country is 16 bits, the others 8
        fits = v[i] >= 0 && v[i] <= hi && v[i] == std::floor(v[i]);
        if (!fits) r.problem(t->get("dis_type"), p + "dis_type", "field " + std::to_string(i + 1) + " " + range_message(0, hi, "", v[i]).insert(8, "an integer "));
      }
      if (fits) k.dis = {uint8_t(v[0]), uint8_t(v[1]), uint16_t(v[2]), uint8_t(v[3]), uint8_t(v[4]), uint8_t(v[5]), uint8_t(v[6])};
    }
    k.guided = r.boolean(*t, "guided", p + "guided").value_or(false);
    if (k.guided && k.mobility != Mobility::Munition) r.problem(t->get("guided"), p + "guided", "only a munition is guided");
    k.blast_radius_m = r.number_in(*t, "blast_radius_m", p + "blast_radius_m", false, tl, 0, kMaxSizeM, "m").value_or(0);
    k.crater_radius_m = r.number_in(*t, "crater_radius_m", p + "crater_radius_m", false, tl, 0, kMaxSizeM, "m").value_or(0);
    k.crater_depth_m = r.number_in(*t, "crater_depth_m", p + "crater_depth_m", false, tl, 0, kMaxSizeM, "m").value_or(0);
    if (auto v = r.number_in(*t, "rounds", p + "rounds", false, tl, 0, kMaxCount, "")) {
      if (*v != std::floor(*v)) r.problem(t->get("rounds"), p + "rounds", "must be a whole number of rounds");
      else k.rounds = static_cast<int>(*v);
    }
    k.fuel_l = r.number_in(*t, "fuel_l", p + "fuel_l", false, tl, 0, kMaxCount, "l").value_or(0);
    k.sensor_range_m = r.number_in(*t, "sensor_range_m", p + "sensor_range_m", false, tl, -1e7, 1e7, "m").value_or(default_sensor_range_m(k.mobility));
    if (!(k.sensor_range_m >= 0)) r.problem(t->get("sensor_range_m"), p + "sensor_range_m", "must not be negative");
    k.resistance = r.number_in(*t, "resistance", p + "resistance", false, tl, -kMaxCount, kMaxCount, "").value_or(1.0);
    if (k.resistance <= 0) r.problem(t->get("resistance"), p + "resistance", "must be positive");
    if (auto tiers = r.strings(*t, "tiers", p + "tiers", false, tl)) {
      // Collision shape tiers (issue 6; collision/collision.hpp): the highest one listed.
      for (const auto& tn : *tiers) {
        const auto v = shape_tier_from_name(tn);
        if (!v || *v == ShapeTier::Auto)
          r.problem(t->get("tiers"), p + "tiers", "must list sphere, capsule, box, hull or mesh (got '" + tn + "')");
        else
          k.top_tier = std::max(k.top_tier, *v);
      }
    }
    if (auto tr = r.numbers(*t, "trunk_radius_m", p + "trunk_radius_m", k.states.size(), k.states.size(), false, tl)) {
      for (double v : *tr) {
        if (!(v >= 0 && v <= kMaxSizeM)) r.problem(t->get("trunk_radius_m"), p + "trunk_radius_m", "each must be 0 (the model) or a radius in m");
        k.trunk_radius_by_state.push_back(static_cast<float>(v));
      }
    }
    read_handling(r, *t, p, tl, k);
    if (k.mobility == Mobility::Munition && k.max_speed_kmh <= 0)
      r.problem(tl, p + "max_speed_kmh", "a munition needs its speed");
    out.names_ += (out.names_.empty() ? "" : ", ") + k.name;
    out.kinds_.push_back(std::move(k));
  }
  for (const auto& k : out.kinds_)  // a vehicle's munition must be a munition kind of this file
    if (!k.munition.empty()) {
      const int m = out.find(k.munition);
      if (m < 0 || out.kinds_[static_cast<size_t>(m)].mobility != Mobility::Munition)
        r.problem(root[k.name].as_table()->get("munition"), k.name + ".munition", "'" + k.munition + "' is not a munition kind");
    }
  if (out.kinds_.empty() && problems.empty()) problems.push_back({fname, 0, "kinds", "no kinds defined"});
  if (!problems.empty()) throw InputError(std::move(problems));
  return out;
}

int KindTable::find(const std::string& name) const {
  for (size_t i = 0; i < kinds_.size(); ++i)
    if (kinds_[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace npsnet::world
