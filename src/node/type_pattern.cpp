#include "node/type_pattern.hpp"

#include <cmath>
#include <cstdio>

namespace npsnet::node {

bool TypePattern::matches(const net::EntityType& t) const {
  const std::array<int, 7> v{t.kind, t.domain, t.country, t.category, t.subcategory, t.specific, t.extra};
  for (size_t i = 0; i < v.size(); ++i)
    if (field[i] >= 0 && field[i] != v[i]) return false;
  return true;
}

std::optional<TypePattern> read_type_pattern(world::TomlReader& r, const toml::table& t, const char* key,
                                             const std::string& field, int table_line) {
  const auto v = r.numbers(t, key, field, 1, 7, true, table_line);
  if (!v) return std::nullopt;
  TypePattern p;
  p.given = static_cast<int>(v->size());
  for (size_t i = 0; i < v->size(); ++i) {
    const double hi = i == 2 ? 65535 : 255;  // country is 16 bits, the others 8
    const double x = (*v)[i];
    if (x != std::floor(x) || x < -1 || x > hi) {
      char b[128];
      std::snprintf(b, sizeof b, "field %zu must be -1 (any) or an integer 0 to %g (got %g)", i + 1, hi, x);
      r.problem(t.get(key), field, b);
      return std::nullopt;
    }
    p.field[i] = static_cast<int>(x);
  }
  return p;
}

}  // namespace npsnet::node
