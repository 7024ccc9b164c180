// Median time of one collision step (detect + respond), thesis and continuous methods, on the full
// default world: 40,303 fixed objects, the Appendix A vehicles and 500 background vehicles, in a
// moving world: each iteration is one whole node tick (dynamics moves every vehicle by 0.1 s,
// so the pair cache, the near lists and the contacts carried over see what a running node
// sees), and the time reported is the tick's own collision stage, from the Simulation's hooks:
// before_detect (dynamics done) to before_apply (outcomes decided). The ticks start 10 s in
// (vehicles spread along their routes). Also the whole node tick (dynamics + collision + apply +
// events) for comparison.
//   build/bench/bench_collision_step --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <chrono>

#include "support/dirs.hpp"
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
    x.sc = world::load_scenario(std::string(npsnet::dirs::source()) + "/scenarios/default.toml");
    x.w = world::build_world(x.sc);
    return x;
  }();
  return s;
}
}  // namespace

static void collision_step(benchmark::State& state, const char* method) {
  auto& s = scene();
  world::Scenario sc = s.sc;
  sc.collision_method = method;
  node::EventLog log;
  node::Simulation sim(s.w, sc, log, 0.1);
  for (int i = 0; i < 100; ++i) sim.tick();  // 10 s in: vehicles spread along their routes
  using Clock = std::chrono::steady_clock;
  Clock::time_point t0{}, t1{};
  sim.before_detect = [&](const world::World&) { t0 = Clock::now(); };
  sim.before_apply = [&](const world::World&, const world::Changes&) { t1 = Clock::now(); };
  const int64_t contacts0 = sim.stats().contacts;  // the stats count from the first tick
  for (auto _ : state) {
    sim.tick();
    state.SetIterationTime(std::chrono::duration<double>(t1 - t0).count());
  }
  state.counters["entities"] = static_cast<double>(sim.world().ents.size());
  state.counters["contacts/tick"] = static_cast<double>(sim.stats().contacts - contacts0) / static_cast<double>(state.iterations());
}
BENCHMARK_CAPTURE(collision_step, thesis, "thesis")->Unit(benchmark::kMicrosecond)->UseManualTime()->Iterations(400);
BENCHMARK_CAPTURE(collision_step, continuous, "continuous")->Unit(benchmark::kMicrosecond)->UseManualTime()->Iterations(400);

static void BM_NodeTick500(benchmark::State& state) {
  auto& s = scene();
  node::EventLog log;
  node::Simulation sim(s.w, s.sc, log, 0.1);
  for (auto _ : state) sim.tick();
}
BENCHMARK(BM_NodeTick500)->Unit(benchmark::kMicrosecond)->Iterations(400);

BENCHMARK_MAIN();
