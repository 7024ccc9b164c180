// bench_budget_error: what the collision budget of the scene-aware auto tier (collision.hpp)
// costs in accuracy, and what it saves in the crowd (issue 13). Three parts:
//
// vehicles (default): a crowd of background vehicles (m1a1, bmp, hmmwv; no snapshots, nobody
//   driving, no viewer: every pair may be lowered) on a flat 2 km world, one tick of 0.1 s (no
//   running episodes), detected with tier auto at budgets from 0 to "ample"; each time the
//   contacts are compared with FCL as the oracle (fcl_oracle.hpp): for every pair whose bounding
//   spheres meet in the tick, FCL's exact mesh-mesh distance on the same triangles, advanced
//   conservatively to the first time within 1 um (the point: the middle of FCL's nearest points).
//   Pairs that come within 1 mm without touching have no verdict and are left out.
// --fixed: the same for vehicle-vs-fixed encounters: the vehicles among trees, telephone poles,
//   buildings, bunkers, watertowers, bushes and rocks (FCL on the shape each object collides as:
//   a tree's or pole's trunk, the others' models); also the error table per tier (thesis, and the
//   continuous method held at sphere, box, hull, mesh, and auto with an ample budget).
// --crowd N: the 100,000-vehicle crowd of bench_broadphase (crowd_scene.hpp) on the default
//   world: the full continuous step (on --threads T, default 1: the node's pool) with the default
//   budget and without one (ample): the first tick (every contact new) and --ticks - 1 after
//   (vehicles moved back and forth), ms and the pairs each tier decided, and where the step's time
//   went (Detector::pass_times: entity pass, kept broad phase, pair loop, and the tiers the budget
//   governs, timed and as charged). --spatial: the same crowd
//   stored in Z order of its cells (crowd_scene.hpp): what a spatial order of the entities gives.
//   --budget-only: the default budget's run alone (to time or profile the budgeted step).
//   --tick-s S: the tick (default 0.1 s, TARGETS.md's step; 1/60 s: a 60 Hz node's, whose
//   frame the default budget is sized for: each sweep a sixth as long; its CSV by default
//   bench/results/crowd_budget_60hz.csv).
// Columns (vehicles, --fixed): budget_ms, pairs (needing a narrow phase, with a verdict), lowered
// (pairs given a tier below their exact one), contacts, truth (FCL contacts), false_pos, misses,
// point error median / p95 (m, over the contacts both find that do not touch from the tick's
// start), detect_ms (our detect, wall, one thread).
// Usage: bench_budget_error [--vehicles N] [--side M] [--fixed] [--crowd N [--threads T] [--ticks K] [--spatial] [--budget-only] [--tick-s S]] [--csv FILE]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include <CLI/CLI.hpp>

#include "support/dirs.hpp"
#include "support/fixture.hpp"

#ifndef NPSNET_BENCH_PEERS
int main() {
  std::fprintf(stderr, "bench_budget_error: built without FCL (NPSNET_BENCH_PEERS): no oracle.\n");
  return 2;
}
#else
#include "crowd_scene.hpp"
#include "fcl_oracle.hpp"
#include "support/fcl_mesh.hpp"

using namespace npsnet;

namespace {

using Key = std::tuple<int, int, bool>;  // vehicle a, b (entity or fixed object), b_fixed

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1) + 0.5))];
}

struct Truth {
  bool hit = false, verdict = true, started_inside = false;
  Vec3 point{0, 0, 0};
};

Key key_of(int a, int b, bool fixed) { return fixed ? Key{a, b, true} : Key{std::min(a, b), std::max(a, b), false}; }

// FCL's answer for every pair an ample budget sends to the narrow phase (vehicle pairs, or
// vehicle-vs-fixed pairs when `fixed`).
std::map<Key, Truth> oracle(const world::World& w, const std::vector<collision::TierChoice>& pairs, bool fixed, double dt) {
  const std::vector<collision::Shape> shapes = collision::make_shapes(w);
  std::vector<std::shared_ptr<test::FclMesh>> meshes;
  for (const auto& s : shapes) meshes.push_back(test::fcl_mesh(s));
  auto model = [&](int e) { return w.kinds[w.ents.kind[e]].models[w.ents.state[e]]; };
  const auto& ents = w.ents;
  std::map<Key, Truth> truth;
  for (const auto& c : pairs) {
    if (c.b_fixed != fixed) continue;
    const int a = c.a, b = c.b;
    const Mat3 ra = world::pose_rotation(ents.heading_deg[a], ents.pitch_deg[a], ents.roll_deg[a]);
    bench::FclToi o;
    if (fixed) {
      const int mb = w.kinds[w.fixed.kind[b]].models[w.fixed.state[b]];
      o = bench::fcl_toi(meshes[model(a)], ra, ents.pos[a], ents.vel[a] * dt, meshes[mb],
                         world::pose_rotation(w.fixed.heading_deg[b], 0, 0), w.fixed.pos[b], Vec3::Zero());
    } else {
      o = bench::fcl_toi(meshes[model(a)], ra, ents.pos[a], ents.vel[a] * dt, meshes[model(b)],
                         world::pose_rotation(ents.heading_deg[b], ents.pitch_deg[b], ents.roll_deg[b]), ents.pos[b],
                         ents.vel[b] * dt);
    }
    Truth tr;
    tr.hit = o.hit, tr.started_inside = o.started_inside, tr.point = o.point;
    tr.verdict = !(o.graze || !o.converged);
    truth[key_of(a, b, fixed)] = tr;
  }
  return truth;
}

struct Score {
  int contacts = 0, fp = 0, miss = 0, lowered = 0;
  std::vector<double> err;
  double ms = 0;
};

// One tick of `det` on w, scored against the truth (pairs without a verdict left out).
Score score(collision::Detector& det, const world::World& w, const std::map<Key, Truth>& truth, bool fixed) {
  std::vector<collision::Contact> out;
  const auto t0 = std::chrono::steady_clock::now();
  det.detect(w, out);
  Score s;
  s.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  for (const auto& c : det.tier_choices()) s.lowered += c.b_fixed == fixed && c.chosen < c.exact;
  std::map<Key, const collision::Contact*> ours;
  for (const auto& c : out) ours[key_of(c.a, c.b, c.b_fixed)] = &c;
  for (const auto& [key, tr] : truth) {
    if (!tr.verdict) continue;
    const auto it = ours.find(key);
    const bool we = it != ours.end();
    s.contacts += we;
    if (we && !tr.hit) ++s.fp;
    if (!we && tr.hit) ++s.miss;
    if (we && tr.hit && !tr.started_inside) s.err.push_back((it->second->point - tr.point).norm());
  }
  return s;
}

// Every vehicle drawn with its heading and speed (10-25 m/s) first and placed so that the
// thesis spheres of it and of everything placed before are kStartSpacing apart where they start
// the tick (the true shapes, at most 1/0.9 of the thesis spheres: no contact from the tick's
// start, so every contact has a point to compare) and kEndSpacing where they end it (so that
// some meet in the tick). With `objects`, as many fixed objects first, the kinds in turn.
constexpr double kStartSpacing = 1.12, kEndSpacing = 0.8;
constexpr double kTickS = 0.1;  // the one tick every part detects
world::World scene(int n, double side, int objects) {
  world::World w = test::flat_world();
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0, 1);
  const double x0 = 1000 - side / 2;
  std::vector<Vec2> at, back_of;  // where each item ends the tick, and its way back to its start
  std::vector<double> rad;
  auto free_spot = [&](double r, Vec2& p, const Vec2& back) {
    for (int tries = 0; tries < 100; ++tries) {
      p = Vec2(x0 + side * u(rng), x0 + side * u(rng));
      bool apart = true;
      for (size_t j = 0; j < at.size() && apart; ++j)
        apart = (at[j] - p).norm() >= kEndSpacing * (r + rad[j]) &&
                (at[j] + back_of[j] - p - back).norm() >= kStartSpacing * (r + rad[j]);
      if (apart) return true;
    }
    return false;
  };
  auto placed = [&](const Vec2& p, const Vec2& back, double r) { at.push_back(p), back_of.push_back(back), rad.push_back(r); };
  const char* fixed_kinds[] = {"tree", "telephone_pole", "building", "bunker", "watertower", "bush", "rock"};
  for (int i = 0; i < objects; ++i) {
    const char* k = fixed_kinds[i % 7];
    const double r = w.kinds[w.kinds.find(k)].radius_m;
    Vec2 p;
    if (!free_spot(r, p, Vec2::Zero())) continue;
    const int o = test::add_fixed(w, "o" + std::to_string(i), k, p.x(), p.y());
    w.fixed.heading_deg[o] = static_cast<float>(360 * u(rng));
    placed(p, Vec2::Zero(), r);
  }
  const char* kinds[] = {"m1a1", "bmp", "hmmwv"};
  for (int i = 0; i < n; ++i) {
    const double r = w.kinds[w.kinds.find(kinds[i % 3])].radius_m;
    const double h = 360 * u(rng), v = 10 + 15 * u(rng);
    const Vec2 back = -heading_to_dir(h) * v * kTickS;
    Vec2 p;
    if (!free_spot(r, p, back)) continue;
    const int e = test::add_vehicle(w, "bg" + std::to_string(i), kinds[i % 3], p.x(), p.y(), h, v);
    w.ents.snapshots[e] = 0;
    placed(p, back, r);
  }
  test::index_fixed(w);
  return w;
}

int accuracy(int n, double side, bool fixed, std::string csv) {
  const double dt = kTickS;
  const world::World w = scene(n, side, fixed ? n : 0);
  // The pairs that need a narrow phase: the tier choices of an ample budget.
  collision::Detector ample(collision::options_from("continuous", "auto", dt));
  ample.set_budget_ms(1e9);
  std::vector<collision::Contact> out;
  ample.detect(w, out);
  const auto truth = oracle(w, ample.tier_choices(), fixed, dt);
  int verdicts = 0, truth_hits = 0, started_inside = 0;
  for (const auto& [k, tr] : truth) {
    verdicts += tr.verdict;
    truth_hits += tr.verdict && tr.hit;
    started_inside += tr.verdict && tr.hit && tr.started_inside;
  }
  if (csv.empty()) csv = std::string(npsnet::dirs::source()) + "/bench/results/budget_error" + (fixed ? "_fixed" : "") + ".csv";
  std::ofstream f(csv);
  f << "budget_ms,pairs,lowered,contacts,truth,false_pos,misses,point_err_median_m,point_err_p95_m,detect_ms\n";
  std::printf("%d vehicles%s in %.0f m x %.0f m: %zu %s pairs need a narrow phase, FCL: %d touch (%d from the tick's "
              "start: no point error), %zu without verdict\n", n, fixed ? " and fixed objects" : "", side, side,
              truth.size(), fixed ? "vehicle-fixed" : "vehicle-vehicle", truth_hits, started_inside, truth.size() - verdicts);
  std::printf("%10s %8s %8s %9s %9s %7s %12s %12s %10s\n", "budget_ms", "lowered", "contacts", "false_pos", "misses",
              "truth", "err_med_m", "err_p95_m", "detect_ms");
  for (double budget : {0.0, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0}) {
    collision::Detector det(collision::options_from("continuous", "auto", dt));
    det.set_budget_ms(budget);
    const Score s = score(det, w, truth, fixed);
    std::printf("%10.1f %8d %8d %9d %9d %7d %12.4g %12.4g %10.2f\n", budget, s.lowered, s.contacts, s.fp, s.miss,
                truth_hits, percentile(s.err, 0.5), percentile(s.err, 0.95), s.ms);
    f << budget << ',' << verdicts << ',' << s.lowered << ',' << s.contacts << ',' << truth_hits << ',' << s.fp << ','
      << s.miss << ',' << percentile(s.err, 0.5) << ',' << percentile(s.err, 0.95) << ',' << s.ms << '\n';
  }
  if (!fixed) return 0;
  // The error table per tier, vehicle-vs-fixed.
  const std::string tcsv = std::string(npsnet::dirs::source()) + "/bench/results/accuracy_fixed.csv";
  std::ofstream t(csv.find("budget_error_fixed.csv") != std::string::npos ? tcsv : csv + ".tiers.csv");
  t << "method,pairs,truth,contacts,false_pos,misses,point_err_median_m,point_err_p95_m,detect_ms\n";
  std::printf("\n| method | misses | false positives | contact-point error median / p95 (m) | detect ms |\n|---|---|---|---|---|\n");
  const std::pair<const char*, const char*> methods[] = {{"thesis", "auto"}, {"continuous", "sphere"}, {"continuous", "box"},
                                                         {"continuous", "hull"}, {"continuous", "mesh"}, {"continuous", "auto"}};
  for (const auto& [m, tier] : methods) {
    collision::Detector det(collision::options_from(m, tier, dt));
    det.set_budget_ms(1e9);
    const Score s = score(det, w, truth, fixed);
    const std::string name = std::string(m) == "thesis" ? "thesis" : std::string(m) + "-" + tier;
    std::printf("| %s | %d / %d | %d / %d | %.3g / %.3g | %.2f |\n", name.c_str(), s.miss, truth_hits, s.fp,
                verdicts - truth_hits, percentile(s.err, 0.5), percentile(s.err, 0.95), s.ms);
    t << name << ',' << verdicts << ',' << truth_hits << ',' << s.contacts << ',' << s.fp << ',' << s.miss << ','
      << percentile(s.err, 0.5) << ',' << percentile(s.err, 0.95) << ',' << s.ms << '\n';
  }
  return 0;
}

// The full continuous step in the crowd, with the default budget and without one.
int crowd(int n, int threads, int ticks, bool spatial, bool budget_only, double dt, std::string csv) {
  auto sc = world::load_scenario(std::string(npsnet::dirs::source()) + "/scenarios/default.toml");
  world::World w = world::build_world(sc);
  w.ents = world::Entities{};
  bench::add_crowd(w, n, spatial);
  for (auto& s : w.ents.snapshots) s = 0;  // background traffic: nobody snapshots, drives or watches it
  std::vector<Vec3> step;
  for (size_t e = 0; e < w.ents.size(); ++e) step.push_back(w.ents.vel[e] * dt);
  if (csv.empty()) {  // (the 0.1 s tick's file is not written over by a run at another tick)
    const std::string tag = dt == kTickS ? "" : std::abs(dt * 60 - 1) < 1e-6 ? "_60hz" : "_tick_" + std::to_string(dt) + "s";
    csv = std::string(npsnet::dirs::source()) + "/bench/results/crowd_budget" + tag + ".csv";
  }
  std::ofstream f(csv);
  f << "vehicles,threads,budget_ms,tick,ms,contacts,narrow_pairs,lowered,decided_sphere,decided_box,decided_hull,decided_mesh,"
       "entities_ms,broad_ms,pairs_ms,tiers_ms,charged_ms\n";
  std::printf("| budget (ms) | tick | ms | contacts | pairs given a tier | lowered | decided by sphere / box / hull / mesh |"
              " entity pass / broad phase / pair loop / tiers (ms) | tiers as charged (ms) |\n"
              "|---|---|---|---|---|---|---|---|---|\n");
  core::Jobs jobs(threads);
  for (double budget : {world::kDefaultCollisionBudgetMs, 1e9}) {
    if (budget_only && budget != world::kDefaultCollisionBudgetMs) break;
    collision::Detector det(collision::options_from("continuous", "auto", dt));
    det.set_budget_ms(budget);
    if (threads > 1) det.set_jobs(&jobs);
    std::vector<double> later;
    for (int k = 0; k < ticks; ++k) {
      if (k > 0)
        for (size_t e = 0; e < w.ents.size(); ++e) w.ents.pos[e] += (k & 1 ? 1.0 : -1.0) * step[e];
      const collision::DetectStats before = det.stats();
      std::vector<collision::Contact> out;
      const auto t0 = std::chrono::steady_clock::now();
      det.detect(w, out);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const collision::DetectStats& s = det.stats();
      int64_t d[5];
      for (int t = 0; t < 5; ++t) d[t] = s.tier_decided[t] - before.tier_decided[t];
      const long long lowered = s.tier_lowered - before.tier_lowered;
      const std::string b = budget > 1e8 ? "none" : std::to_string(budget).substr(0, 4);
      const collision::PassTimes& pt = det.pass_times();
      std::printf("| %s | %d | %.1f | %zu | %zu | %lld | %lld / %lld / %lld / %lld | %.2f / %.2f / %.2f / %.2f | %.2f |\n", b.c_str(), k,
                  ms, out.size(), det.tier_choices().size(), lowered, (long long)d[1], (long long)d[2], (long long)d[3],
                  (long long)d[4], pt.entities, pt.broad, pt.pairs, pt.tiers, pt.charged);
      f << n << ',' << threads << ',' << b << ',' << k << ',' << ms << ',' << out.size() << ',' << det.tier_choices().size() << ',' << lowered
        << ',' << d[1] << ',' << d[2] << ',' << d[3] << ',' << d[4] << ',' << pt.entities << ',' << pt.broad << ',' << pt.pairs
        << ',' << pt.tiers << ',' << pt.charged << '\n';
      std::fflush(stdout);
    }
    if (ticks % 2 == 0)  // back where it started (odd ticks end there)
      for (size_t e = 0; e < w.ents.size(); ++e) w.ents.pos[e] -= step[e];
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int n = 3000, crowd_n = 0, threads = 1, ticks = 4;
  double crowd_dt = kTickS;
  bool spatial = false, budget_only = false;
  double side = 600;
  bool fixed = false;
  std::string csv;
  CLI::App app{"bench_budget_error: accuracy against the collision budget (FCL oracle), and the crowd's step"};
  app.add_option("--vehicles", n, "vehicles in the square")->capture_default_str();
  app.add_option("--side", side, "the square's side (m)")->capture_default_str();
  app.add_flag("--fixed", fixed, "vehicle-vs-fixed encounters (and the error table per tier)");
  app.add_option("--crowd", crowd_n, "the full continuous step in an N-vehicle crowd on the default world, with and without the budget");
  app.add_option("--threads", threads, "--crowd: threads of the detector's pool (the node's --threads)")->capture_default_str()->check(CLI::Range(1, core::Jobs::kMaxThreads));
  app.add_option("--ticks", ticks, "--crowd: ticks per budget (tick 0: every contact new)")->capture_default_str()->check(CLI::Range(1, 1000));
  app.add_flag("--spatial", spatial, "--crowd: the vehicles stored in Z order of their cells (neighbours near in memory)");
  app.add_option("--tick-s", crowd_dt, "--crowd: the tick (s): 0.1 as TARGETS.md's peers; 1/60 a 60 Hz node's, the rate the default budget is sized for")
      ->capture_default_str()->check(CLI::Range(1e-4, 1.0));
  app.add_flag("--budget-only", budget_only, "--crowd: only the default budget's run (not the unbudgeted one)");
  app.add_option("--csv", csv, "where the CSV goes (default: bench/results/...)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (crowd_n > 0) return crowd(crowd_n, threads, ticks, spatial, budget_only, crowd_dt, csv);
  return accuracy(n, side, fixed, csv);
}
#endif
