// Snapshot policy: for each collision or detonation of a vehicle with `snapshots = true`
// (background traffic never), one `imminent` frame from about 0.5 s before and one `result`
// frame about 1 s after, both from one camera placed to see the pair, like the thesis's
// figures A.2-A.9; plus a periodic frame every S seconds from the eye of this node's first live
// vehicle (never from inside a wreck; with none alive, from outside above the first wreck).
// Files NNNN-<kind>-<a>-<b>-imminent.png / -result.png, each logged as a `snapshot` event;
// periodic ones NNNN-periodic-tSSSSS.S.png, whose event also says `camera` ("driver" or
// "outside") and `vehicle` (the one it follows).
//
// Budget: at most max_frames frames per run and max_per_minute in any 60 s of scenario time.
// A frame over budget is not rendered; it is logged as a `snapshot_skipped` event (`file`,
// `reason`), so the event log stays complete, and the first skip is warned about on stderr. An
// imminent/result pair is taken or skipped whole (both frames counted when the event happens).
//
// The imminent frame needs the past. We keep a ring buffer of the last ~0.5 s of world states
// (what a frame needs of the entity arrays, and fixed-object states, copied into preallocated slots
// each tick: no strings or routes) and render
// from it, rather than look ahead: looking ahead would mean simulating every tick twice, and on
// a networked node the future depends on PDUs not yet received. The terrain is not buffered:
// imminent frames are rendered before this tick's craters are applied (before_apply).
// Timing: an event logged at tick t (the `t` of its event) gets the state logged at t - 0.5 s
// (`scene_t` of the snapshot event); when dt does not divide 0.5 s, the two buffered states
// around t - 0.5 s are interpolated (positions and attitudes).
#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "node/event_log.hpp"
#include "world/changes.hpp"

namespace npsnet::render {
class Renderer;
struct Camera;
}

namespace npsnet::node {

inline constexpr double kImminentLeadS = 0.5;  // imminent frame: this long before the contact
inline constexpr double kResultDelayS = 1.0;   // result frame: this long after
inline constexpr int kDefaultMaxFrames = 200;    // snapshot budget per run (--max-snapshots)
inline constexpr int kDefaultMaxPerMinute = 60;  // per 60 s of scenario time (--max-snapshots-per-minute)

struct SnapshotOptions {
  std::filesystem::path dir;
  int width = 960, height = 540;
  double every_s = 0;  // periodic frames from a live vehicle; 0 = none
  bool window = false;
  int max_frames = kDefaultMaxFrames;             // per run
  int max_per_minute = kDefaultMaxPerMinute;      // in any 60 s of scenario time
};

class Snapshots {
 public:
  // Throws std::runtime_error when no GL context can be made or a shader/model is missing.
  // Every method that writes a PNG throws OutputError (naming the file) when it cannot.
  Snapshots(const SnapshotOptions& o, const world::World& w, double dt, EventLog& log);
  ~Snapshots();
  // Before this tick's changes are applied: record the events to snapshot, render imminent frames.
  void before_apply(const world::World& w, const world::Changes& c);
  // After apply: effects, terrain patches, due result frames, periodic frames, buffer the state.
  void after_tick(const world::World& w, const world::Changes& c, const world::Applied& a);
  // The window frame (with --window): `cam`, with the HUD of the driven vehicle showing camera
  // mode `mode`. False once the window is closed.
  bool present(const world::World& w, const render::Camera& cam, const std::string& mode);
  // The player's vehicle (-1: none; the first vehicle of this node then stands in): periodic
  // frames, the start view and the window's HUD follow it.
  void set_driven(int e) { driven_ = e; }
  // The cameras of the frames after_tick will render at the end of this tick (due result frames,
  // the start view, a due periodic frame; none once the snapshot budget has no frame left at
  // this time, since after_tick would skip them all; when some frames are left, all due), from the world
  // `w` as it stands before collision detection: the views whose pairs the collision detector
  // decides at the exact tier (run.cpp, Simulation::before_detect).
  void cameras_due(const world::World& w, std::vector<render::Camera>& out) const;
  const SnapshotOptions& options() const { return opt_; }
  render::Renderer& renderer() { return *r_; }
  bool pending() const { return !pending_.empty(); }
  int written() const { return written_; }
  int skipped() const { return skipped_; }

 private:
  struct State {
    double t = -1;
    world::Entities ents;
    std::vector<uint8_t> fixed_state;
  };
  // A result frame to come. Collisions are framed again at their due time from where the pair is
  // then (the vehicle may have driven on past a stump: both stay in view, side by side).
  struct Pending {
    double due_t = 0;
    std::string base;
    Vec3 eye{0, 0, 0}, target{0, 0, 0};
    int subject = -1;         // the vehicle the snapshot is about (its HUD)
    int a = -1, b = -1;       // collision: entity a, and b (an entity, a fixed object, or -1: ground)
    bool b_fixed = false;
    Vec3 b_point{0, 0, 0};
  };
  static constexpr int kDriven = -2;  // hud_entity: the driven vehicle's HUD
  // Renders `cam` (the HUD of hud_entity, showing camera mode `mode`) and writes PNG `name`.
  void write(const world::World& w, const std::string& name, const State* past, const render::Camera& cam, double t,
             const std::string& mode, int hud_entity = kDriven, const nlohmann::json& extra = {});
  int driven(const world::World& w) const;
  render::Camera result_camera(const world::World& w, const Pending& p) const;
  // The periodic frame's vehicle (-1: none) and camera; alive: from its driver's station.
  int periodic_camera(const world::World& w, render::Camera& cam, bool& alive) const;
  int driven_ = -1;
  bool start_view_ = false;
  // The buffered state of scenario time `t` (interpolated), or the oldest one; null when none.
  const State* past_state(double t);
  // Frames the budget still allows at scenario time t (the per-run and the per-minute limit).
  int frames_left(double t) const;
  // Takes `n` frames from the budget at scenario time t, or logs `files` as skipped.
  bool budget(const world::World& w, int n, const std::vector<std::string>& files);

  SnapshotOptions opt_;
  EventLog& log_;
  std::unique_ptr<render::Renderer> r_;
  std::vector<State> ring_;
  size_t head_ = 0, filled_ = 0;
  State lerp_;                 // an interpolated past state (storage reused)
  std::vector<double> taken_;  // scenario times of the frames taken in the last 60 s
  int skipped_ = 0, taken_total_ = 0;
  double dt_ = 0.1;
  std::vector<Pending> pending_;
  int counter_ = 0, written_ = 0;
  double next_periodic_ = 0;
};

}  // namespace npsnet::node
