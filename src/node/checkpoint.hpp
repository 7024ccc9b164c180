// --checkpoint FILE: this node's own vehicles, kept on disk as the node runs, so that a process
// killed and started again gets back what its catch-up cannot replay (issue 11): the damage other
// nodes' rounds did to its vehicles (a Detonation does not say who stood in its blast) and where
// its killed or stopped vehicles stood (a collision the headless catch-up never sees).
//
// Format: JSON Lines. Line 1 is the header {"checkpoint": 1, "exercise", "node", "start_at"
// (UNIX s, null when none), "dt", "scenario" (FNV-1a of the scenario file, hex), "frame", "t",
// "vehicles": N}; then N lines, one own vehicle each (local, this node's, not a munition):
// {"id", "kind", "state" (index into the kind's states), "active", "pos" [m, local frame], "vel"
// [m/s], "hpr" [deg], "cruise_mps", "max_mps", "fuel_l", "rounds", "leg", "flee_until",
// "calm_until"}: the world's state at the end of tick `frame`, full precision (doubles and floats
// round-trip bit for bit).
// Written whole or not at all (FILE.tmp, then rename): a node killed at any moment leaves the
// previous checkpoint or the new one, never a part.
// Then, with a RoundIdentity, R lines (header "rounds": R), one round of ours in flight each:
// {"round", "kind", "shooter", "target", "pos", "vel", "aim", "event", "site", "application", "entity"}.
// When: after every live tick in which an own vehicle's damage state, activity or wanted speed
// changed (a kill, a blast, a stop) or one of its rounds was fired or spent, and at least every
// kCheckpointEveryS of scenario time.
// Use (run.cpp, tests/node/wire_support.hpp): a node joining a running exercise (a restart)
// whose checkpoint has its key (same exercise, node, --start-at, dt and scenario bytes) catches up
// headless to the checkpoint's frame, puts those vehicles back (restore_checkpoint), and catches
// up on from there to the join. A checkpoint of another exercise is not used (said on stderr) and
// is overwritten by the new run.
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/math.hpp"
#include "world/world.hpp"

namespace npsnet::node {

class Simulation;

inline constexpr double kCheckpointEveryS = 1.0;  // ours: at most 1 s of own vehicles' travel lost

// What ties a checkpoint to one exercise and node.
struct CheckpointKey {
  int exercise = 1;
  int node = 1;
  std::optional<double> start_at;  // --start-at (UNIX s)
  double dt = 0.1;
  std::string scenario;  // scenario_digest() of the scenario file
  bool operator==(const CheckpointKey&) const = default;
};

// FNV-1a 64 of the file's bytes, 16 hex digits ("" when it cannot be read).
std::string scenario_digest(const std::filesystem::path& file);

struct CheckpointVehicle {
  std::string id, kind;
  int state = 0;
  bool active = true;
  Vec3 pos = Vec3::Zero(), vel = Vec3::Zero();
  float heading = 0, pitch = 0, roll = 0;
  float cruise_mps = 0, max_mps = 0, fuel_l = 0;
  int rounds = 0, leg = 0;
  float flee_until = 0, calm_until = 0;
};

// A round of ours in flight (fired, not yet detonated): its Fire PDU went out, so a restart that
// puts it back must detonate it under the same DIS identity (the Fire's event number and
// munition entity id), as the old process would have.
struct CheckpointRound {
  std::string id, kind, shooter, target;  // target: an entity id, or "" (a point)
  Vec3 pos = Vec3::Zero(), vel = Vec3::Zero(), aim = Vec3::Zero();
  int event = 0;                    // the Fire PDU's event number
  int site = 0, application = 0, entity = 0;  // the munition's DIS entity id
};

struct Checkpoint {
  CheckpointKey key;
  int64_t frame = 0;  // the world's frame after the tick it was taken at
  double t = 0;
  std::vector<CheckpointVehicle> vehicles;
  std::vector<CheckpointRound> rounds;
};

// The network identity of our round m (its Fire PDU's event number and munition id), when it
// has one (the net bridge: NetBridge::round_identity); rounds without one are not kept.
using RoundIdentity = std::function<bool(int m, CheckpointRound& r)>;

// The own vehicles of key.node in w, and (with `identity`) its rounds in flight, as a checkpoint
// of w's current frame.
Checkpoint take_checkpoint(const world::World& w, const CheckpointKey& key, const RoundIdentity& identity = {});
// Writes c to file (FILE.tmp, then rename). Throws OutputError ("--checkpoint FILE: why").
void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c);
// Reads file: nullopt when there is none. Throws world::InputError (FILE:LINE: field: message)
// when it is not a checkpoint.
std::optional<Checkpoint> read_checkpoint(const std::filesystem::path& file);
// The same from the file's bytes (`name` for the messages; fuzz/fuzz_checkpoint.cpp).
Checkpoint read_checkpoint_text(std::string_view bytes, const std::string& name);
// Why c is not of this key ("" when it is).
std::string checkpoint_mismatch(const Checkpoint& c, const CheckpointKey& key);
// Why a join at frame join_frame cannot use c ("" when it can: this key, taken no later).
std::string checkpoint_unusable(const Checkpoint& c, const CheckpointKey& key, int64_t join_frame);
// The world slot of each of c's vehicles in w (by id), checked: throws world::InputError
// (FILE:LINE: field: message, `file` naming it) when w lacks one of them as a vehicle of
// c.key.node, has it as another kind, or with fewer states.
std::vector<int> checkpoint_slots(const world::World& w, const Checkpoint& c, const std::filesystem::path& file);
// Puts c's vehicles back into sim's world (each by id: its damage, place, motion and route
// progress; the detector forgets its last orientation, so the move is no turn), and its rounds
// in flight (launched again where and as fast as they were, owner and target by id; a target
// that is not here, another node's vehicle, makes the round fly on unguided), checked as
// checkpoint_slots does. Returns the world slot of each of c.rounds (the caller gives them their
// network identity: NetBridge::adopt_round).
std::vector<int> restore_checkpoint(Simulation& sim, const Checkpoint& c, const std::filesystem::path& file);

// The net bridge's side (checkpoint_net.cpp; without the net room: no rounds are kept):
// its rounds' identities as a RoundIdentity, and the rounds restore_checkpoint put back (their
// slots) given their old identity on it.
class NetBridge;
RoundIdentity round_identities(const NetBridge* bridge);
void adopt_rounds(NetBridge* bridge, const Checkpoint& c, const std::vector<int>& slots);

// After each live tick: takes the checkpoint when it is due (see "When" above) and hands it to
// its own thread, which writes it: the tick pays for the copy of the own vehicles' state (take_
// checkpoint), not for the text and the file (2.3 ms of 2.5 ms for 518 vehicles). One write at a
// time; a checkpoint due while one is being written waits, and a newer one replaces it (the file
// is at most one checkpoint behind the tick, and never a part of one). A write that fails is
// thrown (OutputError) from the next after_tick or flush, on the tick's thread. flush() waits
// until the last checkpoint taken is on disk; the destructor does the same (errors dropped: call
// flush first to hear them).
class CheckpointWriter {
 public:
  CheckpointWriter(std::filesystem::path file, CheckpointKey key, RoundIdentity identity = {});
  ~CheckpointWriter();
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;
  void after_tick(const world::World& w);
  void flush();
  int writes() const { return writes_; }  // checkpoints taken (each written unless a newer replaced it first)

 private:
  struct Shared;
  std::filesystem::path file_;
  CheckpointKey key_;
  RoundIdentity identity_;
  std::vector<uint64_t> sig_;  // per own entity, as last taken: state, active, wanted speed
  double last_t_ = -1e300;
  int writes_ = 0;
  std::unique_ptr<Shared> shared_;  // the writer thread and what it is handed
};

}  // namespace npsnet::node
