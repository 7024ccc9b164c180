// Collision methods and shape tiers by name: the one table that scenario files
// (collision_method, collision_tier), kinds.toml (`tiers`) and collision/ read. The enums are
// collision::Method and collision::Tier (collision/collision.hpp); they live here because the
// world room validates the files that name them.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

namespace npsnet::world {

// "thesis": the 1991 method (ch. III.C-D); "continuous": swept tests (issue 6).
enum class CollisionMethod : uint8_t { Thesis, Continuous };
// Shape tiers, cheapest first; Auto = each pair takes the cheapest tier that decides it.
enum class ShapeTier : uint8_t { Auto, Sphere, Box, Hull, Mesh };

std::optional<CollisionMethod> collision_method_from_name(std::string_view s);  // "thesis" | "continuous"
std::optional<ShapeTier> shape_tier_from_name(std::string_view s);  // "capsule" is a name for Box
const char* collision_method_name(CollisionMethod m);
const char* shape_tier_name(ShapeTier t);
// collision_budget_ms (scenario): the modelled narrow-phase time the auto tier may spend per tick
// (collision/collision.hpp, scene-aware tiers). Default: a quarter of a 60 Hz frame (16.7 ms).
inline constexpr double kDefaultCollisionBudgetMs = 1000.0 / 60.0 / 4.0;
// For messages: the names each field accepts.
inline constexpr const char* kCollisionMethodChoices = "must be \"continuous\" or \"thesis\"";
inline constexpr const char* kShapeTierChoices = "must be one of auto, sphere, capsule, box, hull, mesh";

}  // namespace npsnet::world
