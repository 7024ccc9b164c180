// Fuzz target (a): one UDP datagram through the node's whole receive path, then one tick:
// NetBridge::receive (the session's parser and filter, remote entities joining / updating /
// leaving, cultural features, Fire, Detonation, Collision) -> Simulation::tick (remote poses,
// dynamics, collision, world::apply, craters, the event log) -> the bridge's publishing.
// The node is node 1 (site 1, app 1, exercise 1) of fuzz/data/scenarios/net.toml (a 2.5 km world
// with 28 objects: a tick costs little); each input
// starts from a fresh copy of that world, so a finding replays alone. The event log is written
// to /dev/null (every line serialised), or to $NPSNET_FUZZ_EVENTS when set (to read a replay).
// Its session is offline (no socket): what the tick publishes is encoded and counted, and sent
// nowhere. The bundled entity-type and munition tables (not fuzzed) are loaded once; opening a
// socket and parsing the two TOML tables per input was a fifth of the target's time.
#include <cstdlib>
#include <memory>

#include "fuzz_support.hpp"
#include "node/net_bridge.hpp"
#include "world/scenario.hpp"

namespace {

using namespace npsnet;

struct Fixture {
  world::Scenario scenario = world::load_scenario(fuzz::data_dir() / "scenarios" / "net.toml");
  world::World world = world::build_world(scenario);
  node::BridgeOptions options;
  node::EventLog log{std::getenv("NPSNET_FUZZ_EVENTS") ? std::getenv("NPSNET_FUZZ_EVENTS") : "/dev/null"};
  Fixture() {
    options.offline = true;
    options.munitions = std::make_shared<const node::MunitionTable>(
        node::MunitionTable::load(node::MunitionTable::default_file()));
    options.entity_types = std::make_shared<const node::EntityTypeTable>(
        node::EntityTypeTable::load(node::EntityTypeTable::default_file()));
  }
  std::unique_ptr<net::Session> session() const {
    return std::make_unique<net::Session>(node::session_config(options));
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static Fixture f;
  node::Simulation sim(f.world, f.scenario, f.log, 0.1);
  node::NetBridge bridge(f.options, f.session(), sim, f.log);
  bridge.attach();
  bridge.receive(std::span<const std::uint8_t>(data, size), bridge.clock_s());
  sim.tick();
  f.log.flush();
  return 0;
}
