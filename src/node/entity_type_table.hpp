// What another simulator's entity is here: models/entity_types.toml (its header says the order
// of decision) applied to an Entity State's entity type.
//  * load(file) (read by node/table_file.hpp): every problem as FILE:LINE: field: message
//    (world::InputError). Kind names are looked up when a type is resolved, in the world's
//    kinds (a scenario's own kinds file may lack some: such entries are skipped); check_kinds
//    reports them against a kinds table.
//  * resolve(type, kinds): the vehicle kind it is shown and simulated as, or kind -1 and `track`
//    = what it is (e.g. "lifeform") when it is tracked but not put into the world. The strings
//    live as long as the table.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "net/pdu.hpp"
#include "node/type_pattern.hpp"
#include "world/kinds.hpp"

namespace npsnet::node {

struct EntityChoice {
  int kind = -1;
  const char* track = "";  // kind -1: what it is ("lifeform", "cultural_feature", ...)
};

class EntityTypeTable {
 public:
  static EntityTypeTable load(const std::filesystem::path& file);
  // models/entity_types.toml of the source tree.
  static std::filesystem::path default_file();
  std::vector<world::Problem> check_kinds(const world::KindTable& kinds) const;
  EntityChoice resolve(const net::EntityType& t, const world::KindTable& kinds) const;

 private:
  struct Entry {
    TypePattern type;
    std::string kind, track;  // exactly one is set
    int line = 0;
    std::string field;
  };
  std::string file_;
  Entry default_;
  std::vector<Entry> entries_;  // most specific first
};

}  // namespace npsnet::node
