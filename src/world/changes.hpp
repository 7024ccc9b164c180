// The only way the world changes outside the integrator (dynamics::step / drive move poses): a
// list of changes that dynamics::fire (launches), dynamics::react_to_fire (autonomous reactions),
// collision::respond and collision::detonate decide from a const world, applied in one place by
// world::apply (launches, damage-state swaps, craters, velocity changes, deaths). Also the records
// the node turns into events. The order of a tick is node/simulation.hpp's.
// Threading: deciding reads the world only (any number of threads); apply runs alone.
#pragma once
#include <string>
#include <vector>

#include "world/world.hpp"

namespace npsnet::world {

// Outcome of a collision for one side (the event log's outcome_a / outcome_b).
enum class Result : uint8_t { None, Slowed, Bounce, Stop, Kill, Explode, DamageFixed, DestroyFixed };
const char* result_name(Result r);

struct EntityChange {
  int entity = -1;
  int to_kind = -1;           // -1: unchanged; else the kind the owner's Entity State names
                              // (applied first, before to_state)
  int to_state = -1;          // -1: unchanged; states only ever move forward, except:
  bool owner_state = false;   // to_state is what the entity's owner (another node) says: set
                              // as it is, also backwards (a repair)
  bool set_vel = false;
  Vec3 vel{0, 0, 0};          // new velocity (m/s) when set_vel
  float cruise_mps = -1;      // new wanted speed; -1: unchanged
  Vec3 shift{0, 0, 0};        // separation move (m)
  bool deactivate = false;    // munition spent
  // autonomous reactions (dynamics/autonomous.hpp); negative: unchanged
  float heading_deg = -1;     // new compass heading (flee)
  float flee_until = -1;      // fleeing until this scenario time (s)
  float calm_until = -1;      // no new reaction before this scenario time (s)
};

// A round fired (dynamics::fire decides it): apply takes one of the shooter's rounds and makes the
// munition entity, named "m<entities ever made>", in `slot` when that is a spent munition's
// (reclaimed: the arrays do not grow with every round), else a new one.
struct Launch {
  int slot = -1;
  int shooter = -1;
  int kind = -1;              // munition kind
  int target = -1;            // entity a guided round tracks, or -1
  Vec3 muzzle{0, 0, 0};       // start position (m)
  Vec3 vel{0, 0, 0};          // m/s
  Vec3 aim{0, 0, 0};          // aim point (m)
};

struct FixedChange {
  int object = -1;
  int to_state = -1;
};

struct Crater {
  Vec3 point{0, 0, 0};
  double radius_m = 0, depth_m = 0;
};

// A collision decided this tick (one per contact episode).
// b = -1 (and not b_fixed): the ground itself (an aircraft meeting the terrain, dynamics/drive.hpp).
struct CollisionRecord {
  int a = -1, b = -1;
  bool b_fixed = false;
  Vec3 point{0, 0, 0};
  double closing_speed_mps = 0, angle_deg = 0;
  const char* method = "";    // a string literal (no allocation per record)
  const char* tier = "";      // the shape tier that decided it: sphere, box, hull, mesh (thesis L3:
                              // mesh, its polygons); terrain (ground); network (another node's)
  Result result_a = Result::None, result_b = Result::None;
};

// A detonation: of a local munition entity, or of another node's round (munition = -1: no
// entity here; kind, shooter and round name say what it was).
struct DetonationRecord {
  int munition = -1;          // entity index of the round, or -1
  int kind = -1;              // munition kind
  int shooter = -1;           // entity index of the shooter, or -1
  std::string round;          // the round's name in events
  int target = -1;            // entity hit, or -1 for the ground
  Vec3 point{0, 0, 0};
  const char* result = "";    // "entity_impact", "ground_impact" (remote rounds: node/munition_effects.hpp)
  bool decides_fixed = true;  // this node decides the blast damage of fixed objects (its round)
  // What this detonation does (our rounds: everything their kind has; another node's round: as
  // its warhead and detonation result say, node/munition_effects.hpp):
  bool crater = true;         // a crater where the point is within crater_radius_m of the ground
  bool blast = true;          // blast damage within blast_radius_m (and the explosion drawn)
  bool hit_destroys = true;   // the entity hit (target) is destroyed
  int quantity = 1;           // rounds in the burst at this point: each adds its blast levels
  // Events of another node's round: the munition's name when not a kind of ours (a generic
  // effect, e.g. "smoke"), warhead and fuse class names ("" = not logged). String literals or
  // table-owned strings that outlive the tick.
  const char* munition_name = "";
  const char* warhead = "";
  const char* fuse = "";
};

// Another node's entity as its owner's Entity States say (node/remote_entities.hpp), decided in
// stage 1 of the tick (net in, node/simulation.hpp) and applied first:
//  Join: a new world entity `name` of `kind` at index `entity`, which must be ents.size() when
//        applied (joins of one Changes are numbered in order); not local, not active, no node.
//  Activate: it takes part (not local, not autonomous, force as sent); Deactivate: it left the exercise or timed
//        out (inactive, standing still); Pose: its dead-reckoned pose and velocity (world axes).
struct Mirror {
  enum class Op : uint8_t { Join, Activate, Deactivate, Pose };
  Op op = Op::Pose;
  int entity = -1;
  int kind = -1;     // Join
  uint8_t force = 0; // Activate: the DIS Force ID its owner sends
  std::string name;  // Join (a join is rare: the name is its one allocation)
  Vec3 pos{0, 0, 0}, vel{0, 0, 0};
  float heading_deg = 0, pitch_deg = 0, roll_deg = 0;
};

struct Changes {
  std::vector<Mirror> mirrors;
  std::vector<EntityChange> entities;
  std::vector<FixedChange> fixed;
  std::vector<Crater> craters;
  std::vector<CollisionRecord> collisions;
  std::vector<DetonationRecord> detonations;
  std::vector<Launch> launches;
  void clear() {
    mirrors.clear(), entities.clear(), fixed.clear(), craters.clear(), collisions.clear(), detonations.clear(), launches.clear();
  }
};

// What apply did, for the event log and the renderer.
struct DamageRecord {
  bool fixed = false;
  int index = -1;
  int from_state = 0, to_state = 0;
};
struct Applied {
  std::vector<DamageRecord> damage;
  std::vector<PostRect> terrain_patches;
  std::vector<int> killed;    // entities that became wrecks this tick
  std::vector<int> launched;  // the munition entity of each launch, in order
  void clear() { damage.clear(), terrain_patches.clear(), killed.clear(), launched.clear(); }
};

// Applies the changes in order (mirrors, entities, fixed objects, craters, launches); a state never moves backwards (except an owner_state of a remote
// entity, which is set as its owner says); a crater lowers the terrain and
// re-seats fixed objects standing in it. Appends what happened to `out`.
void apply(World& w, const Changes& c, Applied& out);

}  // namespace npsnet::world
