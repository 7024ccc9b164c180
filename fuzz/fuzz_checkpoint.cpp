// Fuzz target (h): a --checkpoint file (node/checkpoint.hpp) through what a restarted node does
// with it: read_checkpoint_text (JSON Lines, every field checked), then, when it reads, the
// restore into a fresh Simulation of fuzz/data/scenarios/net.toml (checkpoint_slots: ids, kinds,
// states, the map) and one tick of that world (dynamics and collision meet the values put back).
// Rejection (InputError) is the expected answer to bad input; anything else escaping is a bug.
#include "fuzz_support.hpp"
#include "node/checkpoint.hpp"
#include "node/simulation.hpp"
#include "world/error.hpp"
#include "world/scenario.hpp"

namespace {

struct Fixture {
  npsnet::world::Scenario scenario = npsnet::world::load_scenario(npsnet::fuzz::data_dir() / "scenarios" / "net.toml");
  npsnet::world::World world = npsnet::world::build_world(scenario);
  npsnet::node::EventLog log{"/dev/null"};
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace npsnet;
  static Fixture f;
  const std::string name = "fuzz-checkpoint.jsonl";
  try {
    const node::Checkpoint c = node::read_checkpoint_text(fuzz::text(data, size), name);
    (void)node::checkpoint_mismatch(c, c.key);
    node::Simulation sim(f.world, f.scenario, f.log, 0.1);
    node::restore_checkpoint(sim, c, name);
    sim.tick();
  } catch (const world::InputError&) {
  }
  return 0;
}
