// Method and tier names (collision.hpp), and the tiers a kind declares.
#include <cmath>
#include <stdexcept>

#include "collision/collision.hpp"

namespace npsnet::collision {

Method parse_method(const std::string& s) {
  if (s == "thesis") return Method::Thesis;
  if (s == "continuous") return Method::Continuous;
  throw std::invalid_argument("collision_method: must be \"continuous\" or \"thesis\" (got '" + s + "')");
}

Tier parse_tier(const std::string& s) {
  if (s == "auto") return Tier::Auto;
  if (s == "sphere") return Tier::Sphere;
  if (s == "capsule" || s == "box") return Tier::Box;
  if (s == "hull") return Tier::Hull;
  if (s == "mesh") return Tier::Mesh;
  throw std::invalid_argument("collision_tier: must be one of auto, sphere, capsule, box, hull, mesh (got '" + s + "')");
}

const char* method_name(Method m) { return m == Method::Thesis ? "thesis" : "continuous"; }

const char* tier_name(Tier t) {
  switch (t) {
    case Tier::Auto: return "auto";
    case Tier::Sphere: return "sphere";
    case Tier::Box: return "box";
    case Tier::Hull: return "hull";
    case Tier::Mesh: return "mesh";
  }
  return "?";
}

Tier top_tier(const world::Kind& k) {
  if (k.top_tier > 0) return static_cast<Tier>(k.top_tier);
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
