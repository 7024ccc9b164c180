// What another simulator's round is here: models/munitions.toml (its header says the order of
// decision) applied to a Fire / Detonation munition descriptor (entity type, warhead code).
//  * load(file) reads the table (node/table_file.hpp); every problem as FILE:LINE: field:
//    message (world::InputError). Kind names are looked up when a round is resolved, in the
//    world's kinds (a scenario's own kinds file may lack some: such entries are skipped);
//    `npsnet check` checks them against the bundled kinds (check_kinds).
//  * effect(descriptor, kinds): the munition kind whose radii apply (-1: the kinds have no
//    munition at all), the name events give it (the kind's, or the generic class's: "smoke"),
//    the warhead class name ("other" when no class covers the code) and what it may do: crater,
//    blast, a hit destroying its target. The names live as long as the table and the kinds.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "net/pdu.hpp"
#include "node/type_pattern.hpp"
#include "world/kinds.hpp"

namespace npsnet::node {

struct MunitionEffect {
  int kind = -1;
  const char* name = "";
  const char* warhead = "other";
  bool crater = true, blast = true, hit_destroys = true;
};

class MunitionTable {
 public:
  static MunitionTable load(const std::filesystem::path& file);
  // models/munitions.toml of the source tree.
  static std::filesystem::path default_file();
  // Problems of kind names that `kinds` has no munition kind for.
  std::vector<world::Problem> check_kinds(const world::KindTable& kinds) const;

  MunitionEffect effect(const net::MunitionDescriptor& d, const world::KindTable& kinds) const;

 private:
  struct TypeEntry {
    TypePattern type;
    std::string kind;
  };
  struct WarheadClass {
    std::string name;
    int lo = 0, hi = 0;
    std::string kind;  // "" = a generic effect (the flags below)
    bool crater = false, blast = false, hit_destroys = false;
  };
  struct Named {
    std::string kind;
    int line = 0;
    std::string field;
  };
  const WarheadClass* warhead_class(std::uint16_t code) const;

  std::string file_;
  std::string default_kind_;
  std::vector<TypeEntry> types_;       // most specific first
  std::vector<WarheadClass> warheads_;
  std::vector<Named> named_;           // every kind name the file gives, for check_kinds
};

}  // namespace npsnet::node
