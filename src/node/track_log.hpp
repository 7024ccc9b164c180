// --track-every S (issue 11): positions for the dead-reckoning error of remote entities.
// Every k = max(1, round(S / dt)) ticks, at the frames that are multiples of k (so two nodes with
// the same --dt and --start-at sample the same ticks, a late joiner too), after the tick, one
// `track` event per active vehicle (munitions are not tracked):
//   {"event":"track","t":T,"frame":F,"id":ID,"source":"local"|"remote","pos":[x,y,z]}
// t and frame are the world's after the tick (t = frame x dt: the time the local positions are
// at, the time stamped on the Entity State the node publishes from them); pos is in the local
// frame (m, x east, y north, z up) at full double precision (17 significant digits):
//  * local: the vehicle's true position, the one its Entity States are made from;
//  * remote: the position this node holds for another node's vehicle (dead-reckoned and blended
//    from its owner's Entity States, net/remote_table.hpp), what its collision detection used.
// `npsnet dr-error LOG...` (dr_error.hpp) matches each remote sample to its owner's local one.
#pragma once
#include "node/event_log.hpp"
#include "world/world.hpp"

namespace npsnet::node {

class TrackLog {
 public:
  TrackLog(double every_s, double dt);
  long every_ticks() const { return every_; }
  // After a tick: the samples of w.frame when it is a multiple of every_ticks().
  void after_tick(const world::World& w, EventLog& log) const;

 private:
  long every_;
};

}  // namespace npsnet::node
