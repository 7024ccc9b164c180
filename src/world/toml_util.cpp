#include "world/toml_util.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "world/text_file.hpp"

namespace npsnet::world {

toml::table parse_toml_file(const std::string& file) {
  if (!file_exists(file)) throw InputError(file, 0, "file", "file not found");
  return parse_toml_text(read_text_file(file, "file"), file);
}

toml::table parse_toml_text(std::string_view text, const std::string& file) {
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw InputError(file, static_cast<int>(e.source().begin.line), "syntax", std::string(e.description()));
  }
}

std::optional<double> TomlReader::number(const toml::table& t, const std::string& key, const std::string& field,
                                         bool required, int table_line) {
  const toml::node* n = t.get(key);
  if (!n) {
    if (required) problem(table_line, field, "missing");
    return std::nullopt;
  }
  double v;
  if (auto i = n->value_exact<int64_t>()) v = static_cast<double>(*i);
  else if (auto d = n->value_exact<double>()) v = *d;
  else {
    problem(n, field, "must be a number");
    return std::nullopt;
  }
  if (!std::isfinite(v)) {
    problem(n, field, "must be finite (got " + std::string(std::isnan(v) ? "nan" : "inf") + ")");
    return std::nullopt;
  }
  return v;
}

std::string range_message(double lo, double hi, const std::string& unit, double got) {
  char b[160];
  std::snprintf(b, sizeof b, "must be %g to %g%s%s (got %g)", lo, hi, unit.empty() ? "" : " ", unit.c_str(), got);
  return b;
}

std::optional<double> TomlReader::number_in(const toml::table& t, const std::string& key, const std::string& field,
                                            bool required, int table_line, double lo, double hi, const std::string& unit) {
  const auto v = number(t, key, field, required, table_line);
  if (v && (*v < lo || *v > hi)) {
    problem(t.get(key), field, range_message(lo, hi, unit, *v));
    return std::nullopt;
  }
  return v;
}

std::optional<std::string> TomlReader::string(const toml::table& t, const std::string& key, const std::string& field,
                                              bool required, int table_line) {
  const toml::node* n = t.get(key);
  if (!n) {
    if (required) problem(table_line, field, "missing");
    return std::nullopt;
  }
  if (auto s = n->value_exact<std::string>()) return *s;
  problem(n, field, "must be a string");
  return std::nullopt;
}

std::optional<bool> TomlReader::boolean(const toml::table& t, const std::string& key, const std::string& field) {
  const toml::node* n = t.get(key);
  if (!n) return std::nullopt;
  if (auto b = n->value_exact<bool>()) return *b;
  problem(n, field, "must be true or false");
  return std::nullopt;
}

std::optional<std::vector<double>> TomlReader::numbers(const toml::table& t, const std::string& key,
                                                       const std::string& field, size_t min_n, size_t max_n,
                                                       bool required, int table_line) {
  const toml::node* n = t.get(key);
  if (!n) {
    if (required) problem(table_line, field, "missing");
    return std::nullopt;
  }
  const toml::array* a = n->as_array();
  const std::string want = min_n == max_n ? std::to_string(min_n) : std::to_string(min_n) + " to " + std::to_string(max_n);
  if (!a || a->size() < min_n || a->size() > max_n) {
    problem(n, field, "must be an array of " + want + " numbers");
    return std::nullopt;
  }
  std::vector<double> out;
  for (const auto& e : *a) {
    double v;
    if (auto i = e.value_exact<int64_t>()) v = static_cast<double>(*i);
    else if (auto d = e.value_exact<double>()) v = *d;
    else {
      problem(n, field, "must be an array of " + want + " numbers");
      return std::nullopt;
    }
    if (!std::isfinite(v)) {
      problem(n, field, "must be finite (got " + std::string(std::isnan(v) ? "nan" : "inf") + ")");
      return std::nullopt;
    }
    out.push_back(v);
  }
  return out;
}

std::optional<std::vector<std::string>> TomlReader::strings(const toml::table& t, const std::string& key,
                                                            const std::string& field, bool required,
                                                            int table_line) {
  const toml::node* n = t.get(key);
  if (!n) {
    if (required) problem(table_line, field, "missing");
    return std::nullopt;
  }
  const toml::array* a = n->as_array();
  std::vector<std::string> out;
  if (a)
    for (const auto& e : *a) {
      if (auto s = e.value_exact<std::string>()) out.push_back(*s);
      else {
        a = nullptr;
        break;
      }
    }
  if (!a || out.empty()) {
    problem(n, field, "must be a non-empty array of strings");
    return std::nullopt;
  }
  return out;
}

void TomlReader::unknown_keys(const toml::table& t, const std::string& prefix,
                              std::initializer_list<const char*> known) {
  for (const auto& [k, v] : t) {
    bool ok = false;
    for (const char* s : known) ok = ok || k.str() == s;
    if (!ok) problem(&v, prefix + std::string(k.str()), "unknown field");
  }
}

}  // namespace npsnet::world
