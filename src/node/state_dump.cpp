#include "node/state_dump.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "node/event_log.hpp"

namespace npsnet::node {

void write_state(const std::filesystem::path& file, const world::World& w, const std::vector<world::Crater>& craters) {
  nlohmann::json out;
  out["t"] = std::round(w.t * 1000) / 1000;
  auto ents = nlohmann::json::array();
  std::vector<size_t> order;
  for (size_t i = 0; i < w.ents.size(); ++i)
    if (w.ents.active[i] && !w.is_munition(i)) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return w.ents.id[a] < w.ents.id[b]; });
  for (const size_t i : order) {
    const world::Kind& k = w.kind_of_entity(i);
    ents.push_back({{"id", w.ents.id[i]}, {"kind", k.name}, {"state", k.states[w.ents.state[i]]}, {"local", w.ents.local[i] != 0}});
  }
  out["entities"] = ents;
  auto fixed = nlohmann::json::array();
  for (size_t o = 0; o < w.fixed.size(); ++o)
    if (w.fixed.state[o] != 0) fixed.push_back({{"id", w.fixed.id[o]}, {"state", w.kinds[w.fixed.kind[o]].states[w.fixed.state[o]]}});
  out["fixed"] = fixed;
  std::vector<std::array<double, 3>> cs;
  for (const auto& c : craters)
    cs.push_back({std::round(c.point.x() * 10) / 10, std::round(c.point.y() * 10) / 10, std::round(c.radius_m * 10) / 10});
  std::sort(cs.begin(), cs.end());
  cs.erase(std::unique(cs.begin(), cs.end()), cs.end());
  out["craters"] = cs;
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  const auto tmp = file.string() + ".tmp";
  {
    std::ofstream f(tmp);
    f << out.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";  // bad UTF-8 -> U+FFFD
    if (!f) throw OutputError("--state-out " + file.string() + ": cannot write");
  }
  std::filesystem::rename(tmp, file, ec);  // whole or not at all
  if (ec) throw OutputError("--state-out " + file.string() + ": " + ec.message());
}

}  // namespace npsnet::node
