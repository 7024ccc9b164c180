// Collision method and shape tier names (collision_names.hpp).
#include "world/collision_names.hpp"

namespace npsnet::world {

namespace {
constexpr struct {
  const char* name;
  ShapeTier tier;
} kTiers[] = {{"auto", ShapeTier::Auto}, {"sphere", ShapeTier::Sphere}, {"capsule", ShapeTier::Box},
              {"box", ShapeTier::Box},   {"hull", ShapeTier::Hull},     {"mesh", ShapeTier::Mesh}};
}  // namespace

std::optional<CollisionMethod> collision_method_from_name(std::string_view s) {
  if (s == "thesis") return CollisionMethod::Thesis;
  if (s == "continuous") return CollisionMethod::Continuous;
  return std::nullopt;
}

std::optional<ShapeTier> shape_tier_from_name(std::string_view s) {
  for (const auto& t : kTiers)
    if (s == t.name) return t.tier;
  return std::nullopt;
}

const char* collision_method_name(CollisionMethod m) { return m == CollisionMethod::Thesis ? "thesis" : "continuous"; }

const char* shape_tier_name(ShapeTier t) {
  switch (t) {
    case ShapeTier::Auto: return "auto";
    case ShapeTier::Sphere: return "sphere";
    case ShapeTier::Box: return "box";
    case ShapeTier::Hull: return "hull";
    case ShapeTier::Mesh: return "mesh";
  }
  return "?";
}

}  // namespace npsnet::world
