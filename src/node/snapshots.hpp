// Snapshot policy: for each collision or detonation of a vehicle with `snapshots = true`
// (background traffic never), one `imminent` frame from about 0.5 s before and one `result`
// frame about 1 s after, both from one camera placed to see the pair, like the thesis's
// figures A.2-A.9; plus a periodic frame every S seconds from the driven vehicle's eye.
// Files NNNN-<kind>-<a>-<b>-imminent.png / -result.png, each logged as a `snapshot` event.
//
// The imminent frame needs the past. We keep a ring buffer of the last ~0.5 s of world states
// (entity arrays and fixed-object states, copied into preallocated slots each tick) and render
// from it, rather than look ahead: looking ahead would mean simulating every tick twice, and on
// a networked node the future depends on PDUs not yet received. The terrain is not buffered:
// imminent frames are rendered before this tick's craters are applied (before_apply).
#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "node/event_log.hpp"
#include "world/changes.hpp"

namespace npsnet::render {
class Renderer;
}

namespace npsnet::node {

inline constexpr double kImminentLeadS = 0.5;  // imminent frame: this long before the contact
inline constexpr double kResultDelayS = 1.0;   // result frame: this long after

struct SnapshotOptions {
  std::filesystem::path dir;
  int width = 960, height = 540;
  double every_s = 0;  // periodic frames from the driven vehicle; 0 = none
  bool window = false;
};

class Snapshots {
 public:
  // Throws std::runtime_error when no GL context can be made or a shader/model is missing.
  Snapshots(const SnapshotOptions& o, const world::World& w, double dt, EventLog& log);
  ~Snapshots();
  // Before this tick's changes are applied: record the events to snapshot, render imminent frames.
  void before_apply(const world::World& w, const world::Changes& c);
  // After apply: effects, terrain patches, due result frames, periodic frames, buffer the state.
  void after_tick(const world::World& w, const world::Changes& c, const world::Applied& a);
  // The window frame (with --window): the driven vehicle's view. False once the window is closed.
  bool present(const world::World& w);
  bool pending() const { return !pending_.empty(); }
  int written() const { return written_; }

 private:
  struct State {
    double t = -1;
    world::Entities ents;
    std::vector<uint8_t> fixed_state;
  };
  struct Pending {
    double due_t;
    std::string base;
    Vec3 eye, target;
  };
  void write(const world::World& w, const std::string& name, const State* past, const Vec3& eye,
             const Vec3& target, double t);
  int driven(const world::World& w) const;

  SnapshotOptions opt_;
  EventLog& log_;
  std::unique_ptr<render::Renderer> r_;
  std::vector<State> ring_;
  size_t head_ = 0, filled_ = 0;
  std::vector<Pending> pending_;
  int counter_ = 0, written_ = 0;
  double next_periodic_ = 0;
};

}  // namespace npsnet::node
