// Method and tier names (collision.hpp), and the tiers a kind declares.
#include <cmath>
#include <stdexcept>

#include "collision/collision.hpp"

namespace npsnet::collision {

Method parse_method(const std::string& s) {
  if (const auto m = world::collision_method_from_name(s)) return *m;
  throw std::invalid_argument(std::string("collision_method: ") + world::kCollisionMethodChoices + " (got '" + s + "')");
}

Tier parse_tier(const std::string& s) {
  if (const auto t = world::shape_tier_from_name(s)) return *t;
  throw std::invalid_argument(std::string("collision_tier: ") + world::kShapeTierChoices + " (got '" + s + "')");
}

Tier top_tier(const world::Kind& k) {
  if (k.top_tier != Tier::Auto) return k.top_tier;
  if (k.mobility == world::Mobility::Fixed || k.mobility == world::Mobility::Munition) return Tier::Sphere;
  return Tier::Mesh;
}

void Detector::set_dt(double dt_s) {
  if (!(dt_s > 0) || !std::isfinite(dt_s)) throw std::invalid_argument("collision: dt must be a positive finite number of seconds");
  opt_.dt_s = dt_s;
}

Options options_from(const std::string& method, const std::string& tier, double dt_s) {
  if (!(dt_s > 0) || !std::isfinite(dt_s)) throw std::invalid_argument("collision: dt must be a positive finite number of seconds");
  return Options{parse_method(method), parse_tier(tier), dt_s};
}

}  // namespace npsnet::collision
