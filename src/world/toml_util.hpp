// Small helpers to read toml++ tables with FILE:LINE: field: message problems.
#pragma once
#include <toml++/toml.h>

#include <optional>
#include <string>
#include <vector>

#include "world/error.hpp"

namespace npsnet::world {

// "must be LO to HI UNIT (got V)" with numbers as people write them (%g), never 310 digits.
std::string range_message(double lo, double hi, const std::string& unit, double got);

// Parses `file`; a syntax error becomes InputError with its line.
toml::table parse_toml_file(const std::string& file);
// Parses `text` as the contents of `file` (named in problems; nothing is read from disk).
toml::table parse_toml_text(std::string_view text, const std::string& file);

class TomlReader {
 public:
  TomlReader(std::string file, std::vector<Problem>& problems) : file_(std::move(file)), problems_(problems) {}
  int line(const toml::node* n) const { return n ? static_cast<int>(n->source().begin.line) : 0; }
  void problem(const toml::node* n, const std::string& field, const std::string& msg) {
    problems_.push_back({file_, line(n), field, msg});
  }
  void problem(int line, const std::string& field, const std::string& msg) {
    problems_.push_back({file_, line, field, msg});
  }
  // Reads a number (integer or float); reports missing (if required), wrong type, NaN/inf.
  std::optional<double> number(const toml::table& t, const std::string& key, const std::string& field,
                               bool required, int table_line);
  // A number within [lo, hi]; out of range: "must be LO to HI UNIT (got V)", readable numbers.
  std::optional<double> number_in(const toml::table& t, const std::string& key, const std::string& field,
                                  bool required, int table_line, double lo, double hi, const std::string& unit = "");
  std::optional<std::string> string(const toml::table& t, const std::string& key, const std::string& field,
                                    bool required, int table_line);
  std::optional<bool> boolean(const toml::table& t, const std::string& key, const std::string& field);
  // An array of numbers of length in [min_n, max_n].
  std::optional<std::vector<double>> numbers(const toml::table& t, const std::string& key, const std::string& field,
                                             size_t min_n, size_t max_n, bool required, int table_line);
  std::optional<std::vector<std::string>> strings(const toml::table& t, const std::string& key,
                                                  const std::string& field, bool required, int table_line);
  // Reports keys of `t` not in `known`.
  void unknown_keys(const toml::table& t, const std::string& prefix, std::initializer_list<const char*> known);
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::vector<Problem>& problems_;
};

}  // namespace npsnet::world
