// Median time of one collision step (detect + respond), thesis and continuous methods, on the full default world:
// 40,303 fixed objects, the Appendix A vehicles and 500 background vehicles, after 10 s of
// driving. Also the whole node tick (dynamics + collision + apply + events) for comparison.
//   build/bench/bench_collision_step --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "node/simulation.hpp"

using namespace npsnet;

namespace {
struct Scene {
  world::Scenario sc;
  world::World w;
};
Scene& scene() {
  static Scene s = [] {
    Scene x;
    x.sc = world::load_scenario(std::string(NPSNET_SOURCE_DIR) + "/scenarios/default.toml");
    x.w = world::build_world(x.sc);
    return x;
  }();
  return s;
}
}  // namespace

static void collision_step(benchmark::State& state, const char* method) {
  auto& s = scene();
  node::EventLog log;
  node::Simulation sim(s.w, s.sc, log, 0.1);
  for (int i = 0; i < 100; ++i) sim.tick();  // 10 s in: vehicles spread along their routes
  collision::Detector det(collision::options_from(method, "auto", 0.1));
  std::vector<collision::Contact> contacts;
  world::Changes changes;
  contacts.reserve(1024);
  for (auto _ : state) {
    contacts.clear();
    changes.clear();
    det.detect(sim.world(), contacts);
    collision::respond(sim.world(), contacts, changes);
    benchmark::DoNotOptimize(changes.collisions.data());
  }
  state.counters["vehicles"] = static_cast<double>(sim.world().ents.size());
}
BENCHMARK_CAPTURE(collision_step, thesis, "thesis")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(collision_step, continuous, "continuous")->Unit(benchmark::kMicrosecond);

static void BM_NodeTick500(benchmark::State& state) {
  auto& s = scene();
  node::EventLog log;
  node::Simulation sim(s.w, s.sc, log, 0.1);
  for (auto _ : state) sim.tick();
}
BENCHMARK(BM_NodeTick500)->Unit(benchmark::kMicrosecond)->Iterations(400);

BENCHMARK_MAIN();
