#include "npsnet_dirs.hpp"
#include "node/munition_table.hpp"

#include <algorithm>

#include "node/dis_mapping.hpp"
#include "node/table_file.hpp"

namespace npsnet::node {

namespace {
int munition_kind_named(const world::KindTable& kinds, const std::string& name) {
  return kind_named(kinds, name, [](const world::Kind& k) { return k.mobility == world::Mobility::Munition; });
}
}  // namespace

std::filesystem::path MunitionTable::default_file() {
  return std::filesystem::path(NPSNET_SOURCE_DIR) / "models" / "munitions.toml";
}

MunitionTable MunitionTable::load(const std::filesystem::path& file) {
  TableFile tf(file, {"default", "munition", "warhead"});
  world::TomlReader& r = tf.reader();
  MunitionTable out;
  out.file_ = tf.file();
  auto kind_of = [&](const toml::table& t, const std::string& p, bool required) {
    const auto k = r.string(t, "kind", p + "kind", required, r.line(&t)).value_or("");
    if (!k.empty()) out.named_.push_back({k, r.line(t.get("kind")), p + "kind"});
    return k;
  };
  if (const auto* d = tf.default_table({"kind"}, "the kind of a round no class covers"))
    out.default_kind_ = kind_of(*d, "default.", true);
  tf.each("munition", {"dis_type", "kind"}, [&](const toml::table& t, const std::string& p) {
    auto pat = read_type_pattern(r, t, "dis_type", p + "dis_type", r.line(&t));
    auto k = kind_of(t, p, true);
    if (pat) out.types_.push_back({*pat, k});
  });
  tf.each("warhead", {"name", "codes", "kind", "crater", "blast", "hit_destroys"},
          [&](const toml::table& t, const std::string& p) {
    WarheadClass c;
    c.name = r.string(t, "name", p + "name", true, r.line(&t)).value_or("");
    if (const auto codes = r.numbers(t, "codes", p + "codes", 2, 2, true, r.line(&t))) {
      const double lo = (*codes)[0], hi = (*codes)[1];
      if (!(lo >= 0 && hi <= 65535 && lo <= hi))
        r.problem(t.get("codes"), p + "codes", "must be [from, to] with 0 <= from <= to <= 65535");
      c.lo = static_cast<int>(lo), c.hi = static_cast<int>(hi);
    }
    c.kind = kind_of(t, p, false);
    const bool def = !c.kind.empty();  // a kind does all a kind does unless told otherwise
    c.crater = r.boolean(t, "crater", p + "crater").value_or(def);
    c.blast = r.boolean(t, "blast", p + "blast").value_or(def);
    c.hit_destroys = r.boolean(t, "hit_destroys", p + "hit_destroys").value_or(def);
    for (const auto& o : out.warheads_)
      if (c.lo <= o.hi && o.lo <= c.hi) r.problem(t.get("codes"), p + "codes", "overlaps warhead class '" + o.name + "'");
    out.warheads_.push_back(std::move(c));
  });
  tf.finish();
  sort_most_specific(out.types_);
  return out;
}

std::vector<world::Problem> MunitionTable::check_kinds(const world::KindTable& kinds) const {
  std::vector<world::Problem> ps;
  for (const auto& n : named_)
    if (munition_kind_named(kinds, n.kind) < 0)
      ps.push_back({file_, n.line, n.field, "no munition kind '" + n.kind + "' in " + kinds.file().string()});
  return ps;
}

const MunitionTable::WarheadClass* MunitionTable::warhead_class(std::uint16_t code) const {
  for (const auto& c : warheads_)
    if (code >= c.lo && code <= c.hi) return &c;
  return nullptr;
}

MunitionEffect MunitionTable::effect(const net::MunitionDescriptor& d, const world::KindTable& kinds) const {
  MunitionEffect fx;
  const WarheadClass* wc = warhead_class(d.warhead);
  if (wc) fx.warhead = wc->name.c_str();
  auto as_kind = [&](int k) {
    fx.kind = k;
    fx.name = kinds[k].name.c_str();
    return fx;
  };
  int k = -1;
  if (wc && wc->kind.empty()) {  // 1. a payload that does not explode, whatever the type
    k = munition_kind_named(kinds, default_kind_);
    if (k < 0) k = munition_kind_for(kinds, d.munition_type);
    fx.kind = k;
    fx.name = wc->name.c_str();
    fx.crater = wc->crater, fx.blast = wc->blast, fx.hit_destroys = wc->hit_destroys;
    return fx;
  }
  for (int j = 0; j < kinds.size(); ++j)  // 2. one of our own rounds
    if (kinds[j].mobility == world::Mobility::Munition && same_type(kinds[j].dis, d.munition_type)) return as_kind(j);
  for (const auto& e : types_)  // 3. the most specific type entry
    if (e.type.matches(d.munition_type) && (k = munition_kind_named(kinds, e.kind)) >= 0) return as_kind(k);
  if (wc && (k = munition_kind_named(kinds, wc->kind)) >= 0) {  // 4. the warhead's class
    fx = as_kind(k);
    fx.crater = wc->crater, fx.blast = wc->blast, fx.hit_destroys = wc->hit_destroys;
    return fx;
  }
  if ((k = munition_kind_named(kinds, default_kind_)) >= 0) return as_kind(k);  // 5.
  k = munition_kind_for(kinds, d.munition_type);  // the kinds file has none of the table's kinds
  return k >= 0 ? as_kind(k) : fx;
}

}  // namespace npsnet::node
