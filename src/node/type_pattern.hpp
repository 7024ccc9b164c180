// A DIS entity type pattern of a data table (models/munitions.toml; exact type, then wildcards):
// up to the 7 fields [kind, domain, country, category, subcategory, specific, extra]; -1 in a
// field, or a field left out at the end, matches any value. More fields given = more specific.
#pragma once
#include <array>
#include <optional>
#include <string>

#include "net/pdu.hpp"
#include "world/toml_util.hpp"

namespace npsnet::node {

struct TypePattern {
  std::array<int, 7> field{-1, -1, -1, -1, -1, -1, -1};  // -1 = any
  int given = 0;                                         // fields written (specificity)
  bool matches(const net::EntityType& t) const;
};

// Reads key `key` of table t as a pattern: 1 to 7 integers, each -1 or 0..255 (country
// 0..65535); problems as FILE:LINE: field: message through r.
std::optional<TypePattern> read_type_pattern(world::TomlReader& r, const toml::table& t, const char* key,
                                             const std::string& field, int table_line);

}  // namespace npsnet::node
