// bench_tick_scaling: milliseconds per whole node tick against the number of vehicles, on 1 and
// on 2 threads (issue 13). The scene: the default scenario (its world: 50 km of terrain, 40,303
// fixed objects; its Appendix A vehicles and fires) with N background vehicles spread over the
// map ([background] vehicles = N, the default run's traffic at other sizes). The tick is the
// node's whole tick without rendering: net in and net out through an offline NetBridge (dead
// reckoning, Entity State / Fire / Detonation PDUs encoded, not sent: BridgeOptions::offline),
// dynamics, collision (continuous, auto tiers), response, apply, the event log (written to a
// file in $TMPDIR). The same without the bridge (net off, as `npsnet run --no-render`, how the
// old main's 0.5 us per vehicle was measured) for comparison.
// Each N: the world is built once; four Simulations are made from it (net on / off x 1 / 2
// threads), each runs `warm` ticks untimed (the first builds shapes and grids), then they take
// turns, one tick each, for `ticks` rounds, every tick timed alone (steady_clock): the machine's
// other load falls on all four alike. Reported: the median (and the minimum) wall ms per tick,
// and the median CPU ms spent in the tick: a 1-thread node's own thread; a 2-thread node's, the
// whole process's (its worker, but also the other 2-thread node's worker spinning; on a machine
// shared with other work, wall time includes waiting for a core). The
// 1- and 2-thread runs of each kind run the same ticks (their event logs are compared: they must
// be the same bytes, else the bench stops). Before and after, the machine is probed (MachineProbe:
// cache and memory latency, whether two threads run as fast as one, how fast a cache line passes
// between the CPUs), and that and the CPUs the tick's thread ran on are printed and written as
// comment lines at the end of the CSV, with the host's steal during each N's timed ticks
// (CpuClock: the share of the guest's CPU time the hypervisor took back; also printed on each
// N's line). Past 32,767 entities the node numbers its entities under several DIS applications
// (node/ownership.hpp), so the whole tick is measured at every N.
// Usage: bench_tick_scaling [--quick] [--csv FILE] [--n N,N,...] [--one NET,THREADS [--ticks T] [--stages]] [--tick-s S]
//   default N = 500 ... 200,000 -> bench/results/tick_scaling.csv; --quick: 500 and 5,000, no CSV;
//   --n without --csv: no CSV (the committed one is the chart of every N).
//   --one 1,2: only the node with net on (1) or off (0) on that many threads, `warm` + T ticks
//   (default: the table's), its median printed, no CSV: for a profiler (callgrind
//   --toggle-collect='npsnet::node::Simulation::tick()': two runs, T and T + 30, give the
//   instructions of 30 steady ticks; on a build configured with -DNPSNET_ISA=portable: Debian
//   12's valgrind stops on an AVX form of the x86-64-v3 build, CMakeLists.txt).
//   --stages (with --one): also the median ms of each stage of the tick, timed through the
//   Simulation's hooks (before_dynamics, before_detect, before_apply, on_tick): net in and fires,
//   dynamics, collision and response, apply and events, net out, the rest.
//   --prewake 0: no wake-up of the pool ahead of each tick (default 1: as a paced node, run.cpp):
//   the tick's thread wakes the sleeping worker itself (~11 us at 500 vehicles).
//   --pin C: the tick's thread runs on CPU C only (the pool's workers on any): on this machine
//   the two CPUs are not alike (MachineProbe below), so an A/B compares like with like.
//   --tick-s S: the simulated time a tick steps, 0 < S <= 1 (default 0.1 s, the chart's and the
//   committed CSV's; 0.0166666666667 is TARGETS.md's 60 Hz). The same tick counts whatever S.
#include <pthread.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/dirs.hpp"
#include "core/jobs.hpp"
#include "node/net_bridge.hpp"
#include "node/simulation.hpp"

using namespace npsnet;

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The tick's stages, timed from the Simulation's hooks (--stages).
struct StageClock {
  static constexpr int kStages = 6;
  static constexpr const char* kNames[kStages] = {"net in, fires", "dynamics",      "collision, response",
                                                  "apply, events", "net out",       "the rest"};
  std::vector<double> ms[kStages];
  // Within "collision, response": the detector's passes (collision::PassTimes), each tick.
  static constexpr int kPasses = 4;
  static constexpr const char* kPassNames[kPasses] = {"entity pass", "kept broad phase", "pair loop", "tiers"};
  std::vector<double> pass_ms[kPasses];
  std::chrono::steady_clock::time_point last;
  void begin() { last = std::chrono::steady_clock::now(); }
  void mark(int k) {
    const auto now = std::chrono::steady_clock::now();
    ms[k].push_back(std::chrono::duration<double, std::milli>(now - last).count());
    last = now;
  }
};

// The host's steal: of all the guest's CPU time (/proc/stat's "cpu" line: user ... steal, in
// clock ticks), the share the hypervisor gave to something else while a vCPU had work. On this
// KVM guest the slow minutes are the ones the host takes back: 12 % of a 2-thread run of 100,000
// vehicles at 21:15 UTC, 7 Dec, when its tick took 27-30 ms against 14 in a calm minute.
struct CpuClock {
  unsigned long long steal = 0, all = 0;
  static CpuClock now() {
    CpuClock c;
    std::ifstream in("/proc/stat");
    std::string cpu;
    unsigned long long v[8] = {};
    if (in >> cpu && cpu == "cpu")
      for (int k = 0; k < 8 && in >> v[k]; ++k) c.all += v[k];
    c.steal = v[7];
    return c;
  }
  // Per cent of the CPU time since `from` that was stolen (-1: no /proc/stat).
  double steal_pct_since(const CpuClock& from) const {
    return all > from.all ? 100.0 * static_cast<double>(steal - from.steal) / static_cast<double>(all - from.all) : -1;
  }
};
std::string percent_text(double pct) {  // "x.x %", or "unknown" when pct < 0
  char b[32];
  std::snprintf(b, sizeof b, "%.1f %%", pct);
  return pct < 0 ? "unknown" : b;
}

// Ticks whose thread was on each CPU at their end (sched_getcpu), over the whole run.
constexpr int kCpus = 64;
long ticks_on_cpu[kCpus] = {};

std::string cpus_used() {
  std::string s;
  long all = 0;
  for (long n : ticks_on_cpu) all += n;
  for (int c = 0; c < kCpus; ++c)
    if (ticks_on_cpu[c]) s += (s.empty() ? "" : ", ") + ("cpu" + std::to_string(c)) + " " +
                              std::to_string(static_cast<int>(100.0 * ticks_on_cpu[c] / all + 0.5)) + " %";
  return "the tick's thread ended its ticks on " + s;
}

// One node: its event log (a file), Simulation, and, with net, an offline bridge.
struct Node {
  std::filesystem::path file;
  node::EventLog log;
  node::Simulation sim;
  std::unique_ptr<node::NetBridge> bridge;
  std::vector<double> ms;
  Node(const world::World& w, const world::Scenario& sc, int threads, bool net, const std::string& tag, double tick_s)
      : file(std::filesystem::temp_directory_path() / ("npsnet-tick-scaling-" + std::to_string(::getpid()) + tag)),
        log(file),
        sim(w, sc, log, tick_s) {
    sim.set_threads(threads);
    if (net) {
      node::BridgeOptions bo;
      bo.offline = true;
      bridge = std::make_unique<node::NetBridge>(bo, sim, log);
      bridge->attach();
    }
  }
  std::vector<double> cpu_ms;  // CPU time over the tick: the tick's thread alone, or (with a pool) the process's
  std::unique_ptr<StageClock> stages;
  // Times the tick's stages from here on (after the bridge attached its on_tick, which it wraps).
  void time_stages() {
    stages = std::make_unique<StageClock>();
    StageClock& c = *stages;
    sim.before_dynamics = [&c] { c.mark(0); };
    sim.before_detect = [&c](const world::World&) { c.mark(1); };
    sim.before_apply = [&c, this](const world::World&, const world::Changes&) {
      c.mark(2);
      const collision::PassTimes& p = sim.detector().pass_times();
      const double v[StageClock::kPasses] = {p.entities, p.broad, p.pairs, p.tiers};
      for (int k = 0; k < StageClock::kPasses; ++k) c.pass_ms[k].push_back(v[k]);
    };
    sim.on_tick = [&c, inner = sim.on_tick](const node::TickReport& r) {
      c.mark(3);
      if (inner) inner(r);
      c.mark(4);
    };
  }
  // prewake: as a paced node does (node/run.cpp), the pool's workers are woken untimed a little
  // before the tick, so that they spin into its first stage instead of sleeping.
  void timed_tick(bool prewake) {
    if (prewake && sim.jobs()) {
      sim.jobs()->wake();
      const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(core::Jobs::kPrewakeUs);
      while (std::chrono::steady_clock::now() < until) {
      }
    }
    const bool alone = !sim.jobs();
    const double c0 = cpu_now_ms(alone);
    const auto t0 = std::chrono::steady_clock::now();
    if (stages) stages->begin();
    sim.tick();
    if (stages) stages->mark(5);
    ++ticks_on_cpu[std::clamp(sched_getcpu(), 0, kCpus - 1)];
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    cpu_ms.push_back(cpu_now_ms(alone) - c0);
  }
  static double cpu_now_ms(bool this_thread) {
    timespec ts;
    clock_gettime(this_thread ? CLOCK_THREAD_CPUTIME_ID : CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
  }
  static double median_of(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  }
  double median() const { return median_of(ms); }
  double cpu_median() const { return median_of(cpu_ms); }
  double min() const { return *std::min_element(ms.begin(), ms.end()); }
  int collisions() const { return log.counts().count("collision") ? log.counts().at("collision") : 0; }
  std::string events() {
    log.flush();
    return slurp(file);
  }
  ~Node() {
    bridge.reset();
    std::error_code ec;
    std::filesystem::remove(file, ec);
  }
};

// The machine at the time of a run, printed beside the figures. This 2-core guest's two CPUs are
// often not alike, and which one is slower changes (the host moves them): on 4 Dec 17:30 UTC the
// same 500-vehicle tick on one thread took 0.130 ms pinned to cpu0 and 0.144-0.168 ms pinned to
// cpu1, whose loads from memory were then about 30 ns slower (a compute chain ran as fast on
// both); a few minutes later cpu0 was the slower. So a run depends on where the tick's thread runs
// (--pin chooses it; the bench reports where it ran). Probed on each CPU in turn: ns per load of
// a dependent random walk over 1 MiB (the core's own cache) and 64 MiB (memory); a dependent
// multiply chain on two threads at once against one (1.0 when both cores are ours); and the time
// a cache line takes to pass from one CPU to the other: 235-315 ns on 4 Dec 18:10-19:00 UTC, when
// the second thread gained 1.05-1.4x at 500 vehicles, and 58 ns at 19:02, when it gained 1.61x
// (the host placed the two vCPUs apart, then where they share a cache).
volatile uint64_t probe_sink;  // keeps the probes' loops

bool pin_to(int cpu) {  // the calling thread to one CPU
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
}

struct MachineProbe {
  struct Cpu {
    int cpu;
    double walk1_ns, walk64_ns;
  };
  std::vector<Cpu> cpus;
  double two_over_one = 0, handoff_ns = 0;
  // One thread on each of two CPUs passing a counter back and forth (one cache line): ns a pass.
  // What every stage of a tick pays to hand its data from one core to the other.
  static double handoff(int cpu_a, int cpu_b) {
    alignas(64) std::atomic<long> turn{0};
    constexpr long kPasses = 100000;
    auto play = [&turn](int cpu, long first) {
      pin_to(cpu);
      for (long i = first; i < 2 * kPasses; i += 2) {
        while (turn.load(std::memory_order_acquire) != i) {
        }
        turn.store(i + 1, std::memory_order_release);
      }
    };
    const auto t0 = std::chrono::steady_clock::now();
    std::thread a(play, cpu_a, 0), b(play, cpu_b, 1);
    a.join(), b.join();
    return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / (2 * kPasses);
  }
  static double walk_ns(size_t mib) {
    const size_t lines = mib * 1024 * 1024 / 64;  // one 8-byte link a 64-byte line
    std::vector<uint64_t> a(lines * 8);
    std::vector<uint32_t> order(lines);
    for (size_t i = 0; i < lines; ++i) order[i] = static_cast<uint32_t>(i);
    uint64_t r = 88172645463325252ull;  // xorshift: one random cycle through every line
    for (size_t i = lines - 1; i > 0; --i) {
      r ^= r << 13, r ^= r >> 7, r ^= r << 17;
      std::swap(order[i], order[r % (i + 1)]);
    }
    for (size_t i = 0; i < lines; ++i) a[size_t{order[i]} * 8] = size_t{order[(i + 1) % lines]} * 8;
    uint64_t j = 0;
    for (size_t i = 0; i < lines; ++i) j = a[j];  // warm: every line once
    constexpr int kLoads = 1000000;
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < kLoads; ++i) j = a[j];
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / kLoads;
    probe_sink = j;
    return ns;
  }
  static double chain_ms() {
    const auto t0 = std::chrono::steady_clock::now();
    uint64_t x = 1;
    for (int i = 0; i < 10000000; ++i) x = x * 6364136223846793005ull + 1442695040888963407ull;
    probe_sink = x;
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
  static MachineProbe take() {
    MachineProbe m;
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) return m;
    for (int c = 0; c < CPU_SETSIZE && m.cpus.size() < 8; ++c)
      if (CPU_ISSET(c, &allowed)) {
        Cpu r{c, -1, -1};
        std::thread([&] {
          if (pin_to(c)) r.walk1_ns = walk_ns(1), r.walk64_ns = walk_ns(64);
        }).join();
        if (r.walk1_ns >= 0) m.cpus.push_back(r);
      }
    if (m.cpus.size() < 2) return m;
    // The chain on the first CPU alone, then on the first two at once (each thread pinned: a new
    // thread unpinned may start on its parent's CPU and share it for a while).
    auto chain_on = [](int cpu, double& ms) {
      return std::thread([cpu, &ms] { ms = pin_to(cpu) ? chain_ms() : -1; });
    };
    double one = 0, mine = 0, other = 0;
    chain_on(m.cpus[0].cpu, one).join();
    std::thread a = chain_on(m.cpus[0].cpu, mine), b = chain_on(m.cpus[1].cpu, other);
    a.join(), b.join();
    m.two_over_one = std::max(mine, other) / one;
    m.handoff_ns = handoff(m.cpus[0].cpu, m.cpus[1].cpu);
    return m;
  }
  std::string text() const {
    std::string s = "random walk ns a load (1 MiB, 64 MiB):";
    char b[160];
    for (const Cpu& c : cpus) {
      std::snprintf(b, sizeof b, " cpu%d %.1f, %.1f;", c.cpu, c.walk1_ns, c.walk64_ns);
      s += b;
    }
    if (two_over_one > 0)
      std::snprintf(b, sizeof b, " two threads' chain %.2fx one's; a line passed between cpu%d and cpu%d in %.0f ns",
                    two_over_one, cpus[0].cpu, cpus[1].cpu, handoff_ns);
    else std::snprintf(b, sizeof b, " one CPU");
    return s + b;
  }
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> ns = {500, 1000, 2000, 5000, 10000, 20000, 50000, 100000, 200000};
  std::string csv = std::string(npsnet::dirs::source()) + "/bench/results/tick_scaling.csv";
  int one_net = -1, one_threads = 1, ticks_override = 0;
  bool some_n = false, csv_given = false, prewake = true, stages = false;
  int pin = -1;  // --pin C: the tick's thread on CPU C (the pools' workers keep every CPU)
  double tick_s = 0.1;  // --tick-s S
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) ns = {500, 5000}, csv.clear();
    else if (!std::strcmp(argv[i], "--one") && i + 1 < argc &&
             std::sscanf(argv[++i], "%d,%d", &one_net, &one_threads) == 2 && (one_net == 0 || one_net == 1) &&
             one_threads >= 1)
      csv.clear();
    else if (!std::strcmp(argv[i], "--ticks") && i + 1 < argc && (ticks_override = std::atoi(argv[++i])) > 0) {
    }
    else if (!std::strcmp(argv[i], "--prewake") && i + 1 < argc) prewake = std::atoi(argv[++i]) != 0;
    else if (!std::strcmp(argv[i], "--stages")) stages = true;
    else if (!std::strcmp(argv[i], "--pin") && i + 1 < argc && (pin = std::atoi(argv[++i])) >= 0) {
    }
    else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i], csv_given = true;
    else if (!std::strcmp(argv[i], "--tick-s") && i + 1 < argc && (tick_s = std::atof(argv[++i])) > 0 && tick_s <= 1) {
    }
    else if (!std::strcmp(argv[i], "--n") && i + 1 < argc) {
      some_n = true;
      ns.clear();
      std::stringstream ss(argv[++i]);
      for (std::string t; std::getline(ss, t, ',');) ns.push_back(std::stoi(t));
    } else {
      std::fprintf(stderr, "usage: bench_tick_scaling [--quick] [--csv FILE] [--n N,N,...] [--one NET,THREADS [--ticks T] [--stages]] [--prewake 0|1] [--pin CPU] [--tick-s S]\n");
      return 2;
    }
  }
  if (some_n && !csv_given) csv.clear();
  cpu_set_t every_cpu;  // the pools are made with every CPU allowed, then the tick's thread is pinned
  CPU_ZERO(&every_cpu);
  sched_getaffinity(0, sizeof every_cpu, &every_cpu);
  auto pin_tick_thread = [&](bool on) {
    if (pin < 0) return;
    if (!on) sched_setaffinity(0, sizeof every_cpu, &every_cpu);
    else if (!pin_to(pin)) {
      std::fprintf(stderr, "--pin %d: cannot run on that CPU\n", pin);
      std::exit(2);
    }
  };
  const world::Scenario base = world::load_scenario(std::string(npsnet::dirs::source()) + "/scenarios/default.toml");
  std::ofstream out;
  if (!csv.empty()) {
    out.open(csv);
    out << "n,entities,warm_ticks,ticks,net_ms_1t,net_ms_2t,nonet_ms_1t,nonet_ms_2t,net_min_ms_1t,net_min_ms_2t,"
           "nonet_min_ms_1t,nonet_min_ms_2t,net_cpu_ms_1t,net_cpu_ms_2t,nonet_cpu_ms_1t,nonet_cpu_ms_2t,collisions\n";
  }
  const MachineProbe before = MachineProbe::take();
  std::printf("machine before: %s\n", before.text().c_str());
  std::printf("each tick steps %.6g s of simulated time\n", tick_s);
  std::string steal_by_n;  // "N: x %, ..." for the CSV
  std::printf("%8s %9s %6s | %-27s | %-27s | %s\n", "N", "entities", "ticks", "whole tick ms: 1t, 2t, x",
              "net off ms: 1t, 2t, x", "collisions");
  for (int n : ns) {
    world::Scenario sc = base;
    sc.background_vehicles = n;
    const world::World w = world::build_world(sc);
    // Ticks timed: 10 s of simulated time at the smallest N (past the first Entity States and
    // their announce repeats, ticks 1-60, into the steady exercise), 1 s at 100,000 and 0.5 s
    // at 200,000 (about 30 s in all on the 2-core machine; was 41 ... 5 ticks, a median of 7
    // ticks at 100,000 moved by several per cent from run to run).
    const int ticks = ticks_override ? ticks_override
                      : n <= 1000              ? 600
                      : n <= 5000              ? 300
                      : n <= 20000             ? 120
                      : n <= 100000            ? 60
                                               : 30;
    const int warm = n <= 50000 ? 5 : 3;
    if (one_net >= 0) {  // one node alone (profiling)
      pin_tick_thread(false);
      Node nd(w, sc, one_threads, one_net == 1, "-one.jsonl", tick_s);
      pin_tick_thread(true);
      for (int i = 0; i < warm; ++i) nd.sim.tick();
      if (stages) nd.time_stages();
      const CpuClock c0 = CpuClock::now();
      for (int i = 0; i < ticks; ++i) nd.timed_tick(prewake);
      const double stolen = CpuClock::now().steal_pct_since(c0);
      std::printf("%8d %9zu %6d | %s, %d thread(s): median %.3f ms, cpu %.3f ms | %d | %s\n", n, w.ents.size(), ticks,
                  one_net ? "net on" : "net off", one_threads, nd.median(), nd.cpu_median(), nd.collisions(),
                  ("host steal " + percent_text(stolen)).c_str());
      if (nd.bridge)  // what net out sent: the same bits before and after a change to it
        std::printf("  Entity States: digest %016llx, %llu exact DR tests, %llu ground vehicles' sent\n",
                    static_cast<unsigned long long>(nd.bridge->entity_state_digest()),
                    static_cast<unsigned long long>(nd.bridge->exact_dr_tests()),
                    static_cast<unsigned long long>(nd.bridge->ground_es_sent()));
      if (nd.stages)
        for (int k = 0; k < StageClock::kStages; ++k)
          std::printf("  stage %-20s median %.4f ms\n", StageClock::kNames[k], Node::median_of(nd.stages->ms[k]));
      if (nd.stages)
        for (int k = 0; k < StageClock::kPasses; ++k)
          std::printf("    of which %-18s median %.4f ms\n", StageClock::kPassNames[k], Node::median_of(nd.stages->pass_ms[k]));
      continue;
    }
    std::vector<std::unique_ptr<Node>> nodes;  // [net off 1t, net off 2t, net 1t, net 2t]
    pin_tick_thread(false);
    for (int k = 0; k < 4; ++k)
      nodes.push_back(std::make_unique<Node>(w, sc, 1 + k % 2, k >= 2, "-" + std::to_string(k) + ".jsonl", tick_s));
    pin_tick_thread(true);
    for (auto& nd : nodes)
      for (int i = 0; i < warm; ++i) nd->sim.tick();
    const CpuClock c0 = CpuClock::now();
    for (int i = 0; i < ticks; ++i)
      for (auto& nd : nodes) nd->timed_tick(prewake);
    const double stolen = CpuClock::now().steal_pct_since(c0);
    steal_by_n += (steal_by_n.empty() ? "" : ", ") + std::to_string(n) + ": " + percent_text(stolen);
    for (size_t k = 0; k < nodes.size(); k += 2)
      if (nodes[k]->events() != nodes[k + 1]->events()) {
        std::fprintf(stderr, "N = %d: the event logs of 1 and 2 threads differ\n", n);
        return 1;
      }
    double med[4] = {0, 0, 0, 0}, mn[4] = {0, 0, 0, 0}, cpu[4] = {0, 0, 0, 0};
    for (size_t k = 0; k < nodes.size(); ++k)
      med[k] = nodes[k]->median(), mn[k] = nodes[k]->min(), cpu[k] = nodes[k]->cpu_median();
    auto cell = [](double v) { return std::to_string(v); };
    std::printf("%8d %9zu %6d | %8.3f %8.3f %5.2f      | %8.3f %8.3f %5.2f      | %d | %s\n", n, w.ents.size(), ticks,
                med[2], med[3], med[2] / med[3], med[0], med[1], med[0] / med[1], nodes[0]->collisions(),
                ("host steal " + percent_text(stolen)).c_str());
    std::fflush(stdout);
    if (out)
      out << n << ',' << w.ents.size() << ',' << warm << ',' << ticks << ',' << cell(med[2]) << ',' << cell(med[3])
          << ',' << med[0] << ',' << med[1] << ',' << cell(mn[2]) << ',' << cell(mn[3]) << ',' << mn[0] << ','
          << mn[1] << ',' << cell(cpu[2]) << ',' << cell(cpu[3]) << ',' << cpu[0] << ',' << cpu[1] << ','
          << nodes[0]->collisions() << std::endl;
  }
  pin_tick_thread(false);
  const MachineProbe after = MachineProbe::take();
  std::printf("%s\nmachine after: %s\n", cpus_used().c_str(), after.text().c_str());
  if (out)
    out << "# machine before: " << before.text() << "\n# " << cpus_used() << "\n# machine after: " << after.text()
        << "\n# host steal during each N's timed ticks (per cent of the guest's CPU time): " << steal_by_n
        << "\n# each tick steps " << tick_s << " s of simulated time\n";
  return 0;
}
