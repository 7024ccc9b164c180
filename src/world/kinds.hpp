// Object kinds, loaded from models/kinds.toml: physical data, damage states and their models,
// movement class with its Table 2 limit, and DIS entity type. Referred to by small integer ids.
#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "world/collision_names.hpp"
#include "world/model.hpp"

namespace npsnet::world {

enum class Mobility : uint8_t { Fixed, Ground, Ship, Air, Munition };
const char* mobility_name(Mobility m);

struct DisType {  // IEEE 1278.1 entity type record
  uint8_t kind = 0, domain = 0;
  uint16_t country = 0;
  uint8_t category = 0, subcategory = 0, specific = 0, extra = 0;
  bool operator==(const DisType&) const = default;
};

struct Kind {
  std::string name;
  Mobility mobility = Mobility::Fixed;
  double mass_kg = 0;            // kg
  double radius_m = 0;           // bounding radius (slightly less than the true one, p. 14)
  std::vector<std::string> states;  // damage states in order, states[0] = intact
  std::vector<int> models;          // ModelLibrary index per state
  std::vector<float> radius_by_state;  // bounding radius per state (radius_m scaled by the model's size)
  std::vector<Vec3f> centre_by_state;  // sphere centre in model space per state
  bool explosive = false;        // explodes when killed (fuel, ammunition) or on contact
  double max_speed_kmh = 0;      // Table 2 limit for vehicles, muzzle/cruise speed for munitions
  DisType dis;
  // munitions only
  bool guided = false;           // tracks its target entity (missile); else a ballistic arc
  double blast_radius_m = 0;     // objects within are damaged, graded by distance
  double crater_radius_m = 0;
  double crater_depth_m = 0;
  // vehicles only
  int rounds = 0;                // rounds carried
  double fuel_l = 0;
  double sensor_range_m = 0;     // area of interest (--aoi): default ground 5 km, ship 10 km, air 20 km
  double height_m = 0;           // top of the model above ground (from the intact model)
  // vehicles driven by a player (dynamics/drive.hpp); defaults by mobility when not given
  std::string munition;          // the round it fires ("" = none)
  double fuel_lph = 0;           // litres per hour at top speed, burnt in proportion to speed
  double accel_mps2 = 0;         // at full throttle (m/s^2)
  double brake_mps2 = 0;         // at full brake (m/s^2)
  double turn_radius_m = 0;      // tightest turn at full steer (ground, ship), m
  double climb_mps = 0;          // aircraft: vertical speed at full climb or dive, m/s
  // fixed objects: momentum scale they withstand (Figure 8 constants x resistance)
  double resistance = 1;
  // collision shape tiers (`tiers` in kinds.toml): the highest declared; Auto = not declared
  // (collision::top_tier decides)
  ShapeTier top_tier = ShapeTier::Auto;
  // fixed objects that stand on a trunk (tree, pole): per state, the trunk's radius (m) the
  // collision tiers use instead of the state's model (a vertical cylinder); 0 = the model
  std::vector<float> trunk_radius_by_state;

  int state_index(const std::string& s) const;  // -1 if unknown
  bool mobile() const { return mobility != Mobility::Fixed; }
};

class KindTable {
 public:
  // Parses the TOML; loads every model (paths relative to the kinds file) into `models`.
  // Throws InputError with file:line: field: message for every problem found.
  static KindTable load(const std::filesystem::path& file, ModelLibrary& models);
  // The same from `text`, the contents of `file` (its folder resolves the model paths).
  static KindTable load_text(std::string_view text, const std::filesystem::path& file, ModelLibrary& models);
  int find(const std::string& name) const;  // -1 if unknown
  const Kind& operator[](int i) const { return kinds_[static_cast<size_t>(i)]; }
  int size() const { return static_cast<int>(kinds_.size()); }
  const std::string& names() const { return names_; }  // "a, b, c" for messages
  const std::filesystem::path& file() const { return file_; }

 private:
  std::vector<Kind> kinds_;
  std::string names_;  // built with kinds_: messages name them once per bad entry
  std::filesystem::path file_;
};

}  // namespace npsnet::world
