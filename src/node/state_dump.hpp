// --state-out FILE: what this node's world holds at the end of a run, as one JSON object, so the
// worlds of several nodes can be compared (the fault tests: every node must agree).
//   {"t": s, "entities": [{"id", "kind", "state", "local"}...],   active vehicles, by id
//    "fixed": [{"id", "state"}...],                                 objects not in their first state
//    "craters": [[x, y, radius_m]...]}                              metres, 0.1 m, sorted, unique
// Ids are markings made safe (as in the event log). Throws OutputError when it cannot be written.
#pragma once
#include <filesystem>
#include <vector>

#include "world/changes.hpp"
#include "world/world.hpp"

namespace npsnet::node {

void write_state(const std::filesystem::path& file, const world::World& w, const std::vector<world::Crater>& craters);

}  // namespace npsnet::node
