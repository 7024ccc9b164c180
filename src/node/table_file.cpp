#include "node/table_file.hpp"

namespace npsnet::node {

TableFile::TableFile(const std::filesystem::path& file, std::initializer_list<const char*> top_keys)
    : file_(file.string()), root_(world::parse_toml_file(file_)), r_(file_, problems_) {
  r_.unknown_keys(root_, "", top_keys);
}

const toml::table* TableFile::default_table(std::initializer_list<const char*> keys, const std::string& what) {
  const auto* d = root_["default"].as_table();
  if (!d) {
    r_.problem(1, "default", "a [default] table with " + what + " is required");
    return nullptr;
  }
  r_.unknown_keys(*d, "default.", keys);
  return d;
}

void TableFile::each(const char* name, std::initializer_list<const char*> keys,
                     const std::function<void(const toml::table&, const std::string&)>& fn) {
  const toml::node* n = root_.get(name);
  if (!n) return;
  const toml::array* a = n->as_array();
  if (!a) return r_.problem(n, name, "must be an array of tables [[" + std::string(name) + "]]");
  for (size_t i = 0; i < a->size(); ++i) {
    const std::string p = std::string(name) + "[" + std::to_string(i) + "].";
    const auto* t = a->get(i)->as_table();
    if (!t) {
      r_.problem(a->get(i), p, "must be a table");
      continue;
    }
    r_.unknown_keys(*t, p, keys);
    fn(*t, p);
  }
}

void TableFile::finish() const {
  if (!problems_.empty()) throw world::InputError(problems_);
}

}  // namespace npsnet::node
