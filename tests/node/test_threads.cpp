// The tick on 1 and on several threads (issue 13): the same event log bytes and the same world.
// The scene: the default world and scenario (its Appendix A cases, their fires) plus a crowd of
// 6,000 background vehicles driving in a 4 km square of forest (node/simulation.hpp, threading),
// so that the stages are cut into ranges (the 3-thread run cuts every stage, whatever its size) and
// the crowd collides with itself and with trees.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/jobs.hpp"
#include "node/simulation.hpp"
#include "support/fixture.hpp"
#include "support/scratch.hpp"

using namespace npsnet;

namespace {

struct Outcome {
  std::string events;
  std::vector<Vec3> pos;
  std::vector<int> state;
  int64_t sweep_pairs = 0, contacts = 0;
};

const world::Scenario& crowd_scenario() {
  static const world::Scenario sc = test::default_with_crowd(6000, 13, Vec2(20000, 30000), Vec2(24000, 34000));
  return sc;
}

const world::World& crowd_world() {
  static const world::World w = world::build_world(crowd_scenario());
  return w;
}

Outcome run(int threads, int ticks, size_t max_grain) {
  const auto file = test::scratch_dir() / ("threads-" + std::to_string(threads) + ".jsonl");
  Outcome r;
  {
    node::EventLog log(file);
    node::Simulation sim(crowd_world(), crowd_scenario(), log, 0.1);
    sim.set_threads(threads, max_grain);
    EXPECT_EQ(sim.threads(), threads);
    for (int i = 0; i < ticks; ++i) sim.tick();
    const auto& ents = sim.world().ents;
    r.pos = ents.pos;
    r.state.assign(ents.state.begin(), ents.state.end());
    r.sweep_pairs = sim.stats().sweep_pairs;
    r.contacts = sim.stats().contacts;
  }
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  r.events = ss.str();
  return r;
}

// Events of a type in a JSON Lines log; `pick` counts only those it accepts.
template <class F>
int count(const std::string& text, const std::string& type, F pick) {
  int n = 0;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto ev = nlohmann::json::parse(line);
    if (ev["event"] == type && pick(ev)) ++n;
  }
  return n;
}
bool any(const nlohmann::json&) { return true; }
bool background(const nlohmann::json& v) { return v.is_string() && v.get<std::string>().rfind("bg", 0) == 0; }

}  // namespace

TEST(Threads, CrowdEventLogIsTheSameBytesOnOneTwoAndThreeThreads) {
  const int ticks = 100;  // 10 s: the scenario's fires (2-5 s) and their detonations (6 s on) are in it
  const Outcome one = run(1, ticks, 0);
  // The crowd collides: vehicles with each other and with the forest, many times.
  const int crowd = count(one.events, "collision", [](const nlohmann::json& ev) { return background(ev["a"]); });
  const int crowd_pairs =
      count(one.events, "collision", [](const nlohmann::json& ev) { return background(ev["a"]) && background(ev["b"]); });
  EXPECT_GT(crowd, 50) << "the crowd should collide";
  EXPECT_GT(crowd_pairs, 10) << "vehicle-vehicle contacts in the crowd";
  EXPECT_GT(count(one.events, "detonation", any), 0);
  std::printf("crowd: %d collisions (%d vehicle pairs), %lld contacts, %lld swept pairs in %d ticks\n", crowd,
              crowd_pairs, static_cast<long long>(one.contacts), static_cast<long long>(one.sweep_pairs), ticks);
  // 2 threads as the node runs; 3 threads with every stage split three ways however small.
  for (auto [threads, grain] : {std::pair<int, size_t>{2, 0}, {3, 1}}) {
    const Outcome many = run(threads, ticks, grain);
    EXPECT_EQ(many.events.size(), one.events.size()) << threads << " threads";
    EXPECT_TRUE(many.events == one.events) << threads << " threads: the event logs differ";
    ASSERT_EQ(many.pos.size(), one.pos.size());
    size_t moved = 0;
    for (size_t e = 0; e < one.pos.size(); ++e) {
      EXPECT_EQ(many.pos[e], one.pos[e]) << "entity " << e << ", " << threads << " threads";
      moved += many.pos[e] == one.pos[e] ? 0 : 1;
      if (moved > 5) break;
    }
    EXPECT_EQ(many.state, one.state);
    EXPECT_EQ(many.sweep_pairs, one.sweep_pairs);
    EXPECT_EQ(many.contacts, one.contacts);
  }
}

TEST(Threads, JobsSplitIntoFixedRangesAndRethrowTheFirstError) {
  core::Jobs jobs(3);
  EXPECT_EQ(jobs.chunks(10, 1), 3);
  EXPECT_EQ(jobs.chunks(10, 4), 2);
  EXPECT_EQ(jobs.chunks(3, 100), 1);
  std::vector<int> owner(1000, -1);
  jobs.for_chunks(owner.size(), 1, [&](int c, size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) owner[i] = c;
  });
  for (size_t i = 0; i < owner.size(); ++i) {
    const int c = i < 333 ? 0 : i < 666 ? 1 : 2;  // chunk c = [1000 c / 3, 1000 (c + 1) / 3)
    EXPECT_EQ(owner[i], c) << i;
  }
  // Items 500 and 900 are bad: the error of the lower one comes back, after all chunks ran.
  std::vector<int> ran(3, 0);
  try {
    jobs.for_chunks(owner.size(), 1, [&](int c, size_t b, size_t e) {
      ran[c] = 1;
      for (size_t i = b; i < e; ++i)
        if (i == 500 || i == 900) throw std::runtime_error("bad " + std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "bad 500");
  }
  EXPECT_EQ(ran, std::vector<int>({1, 1, 1}));
  // Several chunks a thread: up to threads * per_thread (capped at kMaxPerThread), the same fixed
  // ranges whoever claims them, every item once, the lowest chunk's error first.
  EXPECT_EQ(jobs.chunks(1000, 1, 4), 12);
  EXPECT_EQ(jobs.chunks(1000, 100, 4), 10);
  EXPECT_EQ(jobs.chunks(1000, 1, 1000), 3 * core::Jobs::kMaxPerThread);
  std::vector<int> seen(1000, 0);
  std::vector<int> owner4(1000, -1);
  jobs.for_chunks(owner4.size(), 1, [&](int c, size_t b, size_t e) {
    for (size_t i = b; i < e; ++i) owner4[i] = c, ++seen[i];
  }, 4);
  for (size_t c = 0; c < 12; ++c)  // chunk c = [1000 c / 12, 1000 (c + 1) / 12)
    for (size_t i = 1000 * c / 12; i < 1000 * (c + 1) / 12; ++i) EXPECT_EQ(owner4[i], static_cast<int>(c)) << i;
  EXPECT_EQ(seen, std::vector<int>(1000, 1));
  std::vector<int> ran4(12, 0);
  try {
    jobs.for_chunks(1000, 1, [&](int c, size_t b, size_t e) {
      ran4[c] = 1;
      for (size_t i = b; i < e; ++i)
        if (i == 950 || i == 700) throw std::runtime_error("bad " + std::to_string(i));
    }, 4);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "bad 700");
  }
  EXPECT_EQ(ran4, std::vector<int>(12, 1));
  // run_chunks: the pool's ranges, or one call on the caller without a pool.
  int calls = 0;
  EXPECT_EQ(core::run_chunks(&jobs, 1000, 1, [&](int, size_t, size_t) {}, 4), 12);
  EXPECT_EQ(core::run_chunks(nullptr, 1000, 1, [&](int c, size_t b, size_t e) { calls += 1 + c + static_cast<int>(b) + (e == 1000 ? 0 : 99); }, 4), 1);
  EXPECT_EQ(calls, 1);
  // Reusable after an error, and a pool of one runs on the caller.
  int sum = 0;
  core::Jobs single(1);
  single.for_chunks(100, 1, [&](int c, size_t b, size_t e) { sum += c + static_cast<int>(e - b); });
  EXPECT_EQ(sum, 100);
}

// Who runs which chunk (core/jobs.hpp): the caller claims from the first chunk up, the workers
// from the last down, so with one worker the caller's chunks are always a prefix of the job and
// the worker's the rest (the same items stay on the same thread from stage to stage). Each chunk
// sleeps a little so that the worker, woken by the job, takes part in most rounds.
TEST(Threads, CallerClaimsFromTheFrontTheWorkerFromTheBack) {
  core::Jobs jobs(2);
  const auto caller = std::this_thread::get_id();
  int rounds_shared = 0;
  for (int round = 0; round < 20; ++round) {
    std::vector<int> on_caller(8, -1);
    jobs.for_chunks(8, 1, [&](int c, size_t, size_t) {
      on_caller[c] = std::this_thread::get_id() == caller;
      std::this_thread::sleep_for(std::chrono::microseconds(300));
    }, 4);
    const auto first_worker = std::find(on_caller.begin(), on_caller.end(), 0);
    EXPECT_TRUE(std::all_of(on_caller.begin(), first_worker, [](int v) { return v == 1; })) << "round " << round;
    EXPECT_TRUE(std::all_of(first_worker, on_caller.end(), [](int v) { return v == 0; })) << "round " << round;
    rounds_shared += first_worker != on_caller.end() && first_worker != on_caller.begin();
  }
  EXPECT_GT(rounds_shared, 0);  // the worker took part (each round lasts 8 x 300 us at most)
}
