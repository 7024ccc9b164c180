#include "node/track_log.hpp"

#include <algorithm>
#include <cmath>

namespace npsnet::node {

TrackLog::TrackLog(double every_s, double dt) : every_(std::max(1L, std::lround(every_s / dt))) {}

void TrackLog::after_tick(const world::World& w, EventLog& log) const {
  if (w.frame % every_ != 0) return;
  const auto& ents = w.ents;
  const double t = std::round(w.t * 1000.0) / 1000.0;
  for (size_t e = 0; e < ents.size(); ++e) {
    if (!ents.active[e] || w.is_munition(e)) continue;
    const Vec3& p = ents.pos[e];
    log.write({{"event", "track"}, {"t", t}, {"frame", w.frame}, {"id", ents.id[e]},
               {"source", ents.local[e] ? "local" : "remote"}, {"pos", {p.x(), p.y(), p.z()}}});
  }
}

}  // namespace npsnet::node
