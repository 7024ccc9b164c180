#include "npsnet_dirs.hpp"
#include "node/entity_type_table.hpp"

#include <algorithm>

#include "node/dis_mapping.hpp"
#include "node/table_file.hpp"

namespace npsnet::node {

namespace {
int vehicle_kind_named(const world::KindTable& kinds, const std::string& name) {
  return kind_named(kinds, name,
                    [](const world::Kind& k) { return k.mobile() && k.mobility != world::Mobility::Munition; });
}
}  // namespace

std::filesystem::path EntityTypeTable::default_file() {
  return std::filesystem::path(NPSNET_SOURCE_DIR) / "models" / "entity_types.toml";
}

EntityTypeTable EntityTypeTable::load(const std::filesystem::path& file) {
  TableFile tf(file, {"default", "entity"});
  world::TomlReader& r = tf.reader();
  EntityTypeTable out;
  out.file_ = tf.file();
  // kind = "..." or track = "...", exactly one.
  auto target = [&](const toml::table& t, const std::string& p, Entry& e) {
    e.kind = r.string(t, "kind", p + "kind", false, r.line(&t)).value_or("");
    e.track = r.string(t, "track", p + "track", false, r.line(&t)).value_or("");
    e.line = r.line(t.get("kind"));
    e.field = p + "kind";
    if (e.kind.empty() == e.track.empty()) r.problem(&t, p + "kind", "give either kind (a vehicle kind) or track (what it is)");
  };
  if (const auto* d = tf.default_table({"kind", "track"}, "the kind of an entity no entry covers"))
    target(*d, "default.", out.default_);
  tf.each("entity", {"dis_type", "kind", "track"}, [&](const toml::table& t, const std::string& p) {
    Entry e;
    target(t, p, e);
    if (auto pat = read_type_pattern(r, t, "dis_type", p + "dis_type", r.line(&t))) {
      e.type = *pat;
      out.entries_.push_back(std::move(e));
    }
  });
  tf.finish();
  sort_most_specific(out.entries_);
  return out;
}

std::vector<world::Problem> EntityTypeTable::check_kinds(const world::KindTable& kinds) const {
  std::vector<world::Problem> ps;
  auto check = [&](const Entry& e) {
    if (!e.kind.empty() && vehicle_kind_named(kinds, e.kind) < 0)
      ps.push_back({file_, e.line, e.field, "no vehicle kind '" + e.kind + "' in " + kinds.file().string()});
  };
  check(default_);
  for (const auto& e : entries_) check(e);
  return ps;
}

EntityChoice EntityTypeTable::resolve(const net::EntityType& t, const world::KindTable& kinds) const {
  for (int k = 0; k < kinds.size(); ++k)  // 1. one of our own vehicle kinds
    if (kinds[k].mobile() && kinds[k].mobility != world::Mobility::Munition && same_type(kinds[k].dis, t)) return {k};
  auto choose = [&](const Entry& e) -> EntityChoice {
    if (!e.track.empty()) return {-1, e.track.c_str()};
    return {vehicle_kind_named(kinds, e.kind)};
  };
  for (const auto& e : entries_)  // 2. the most specific entry whose kind this kinds file has
    if (e.type.matches(t))
      if (const EntityChoice c = choose(e); c.kind >= 0 || *c.track) return c;
  if (const EntityChoice c = choose(default_); c.kind >= 0 || *c.track) return c;  // 3.
  return {vehicle_kind_for(kinds, t)};  // a kinds file without the table's kinds
}

}  // namespace npsnet::node
