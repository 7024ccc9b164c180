// The shape the node's DIS data tables share (models/munitions.toml, models/entity_types.toml,
// each read by its own table class): a TOML file read whole, its top-level keys checked, a
// required [default] table, arrays of tables [[name]] each read by a function, every problem as
// FILE:LINE: field: message, thrown together (world::InputError) once the whole file is read,
// so nothing is used half-read. Entries matched by a TypePattern are kept most specific first.
#pragma once
#include <algorithm>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include "world/kinds.hpp"
#include "world/toml_util.hpp"

namespace npsnet::node {

class TableFile {
 public:
  // Parses `file` (a syntax error throws at once) and reports top-level keys not in `top_keys`.
  TableFile(const std::filesystem::path& file, std::initializer_list<const char*> top_keys);
  TableFile(const TableFile&) = delete;
  TableFile& operator=(const TableFile&) = delete;

  const std::string& file() const { return file_; }
  world::TomlReader& reader() { return r_; }
  // The [default] table, its keys checked against `keys`; missing: the problem "a [default]
  // table with <what> is required" and nullptr.
  const toml::table* default_table(std::initializer_list<const char*> keys, const std::string& what);
  // Calls fn(table, "name[i].") for each table of the array of tables `name` (absent: never),
  // after checking its keys against `keys`; what is not an array of tables is a problem.
  void each(const char* name, std::initializer_list<const char*> keys,
            const std::function<void(const toml::table&, const std::string&)>& fn);
  // Throws world::InputError with every problem found, if any.
  void finish() const;

 private:
  std::string file_;
  toml::table root_;
  std::vector<world::Problem> problems_;
  world::TomlReader r_;
};

// Sorts entries with a TypePattern `type` most specific first (more fields given), stable.
template <class Entry>
void sort_most_specific(std::vector<Entry>& entries) {
  std::stable_sort(entries.begin(), entries.end(),
                   [](const Entry& a, const Entry& b) { return a.type.given > b.type.given; });
}

// The index of the kind named `name` when fits(kind) holds, else -1 (also for "").
template <class Fits>
int kind_named(const world::KindTable& kinds, const std::string& name, Fits&& fits) {
  const int k = name.empty() ? -1 : kinds.find(name);
  return k >= 0 && fits(kinds[k]) ? k : -1;
}

}  // namespace npsnet::node
