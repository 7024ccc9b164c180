// bench_budget_error: what the collision budget of the scene-aware auto tier (collision.hpp)
// costs in accuracy (issue 13). A crowd of background vehicles (m1a1, bmp, hmmwv; no snapshots,
// nobody driving, no viewer: every pair may be lowered) on a flat 2 km world, one tick of 0.1 s
// (no running episodes), detected with tier auto at budgets from 0 to "ample"; each time the
// contacts are compared with FCL as the oracle, as bench_accuracy does: for every pair whose
// bounding spheres meet in the tick, FCL's exact mesh-mesh distance on the same triangles,
// advanced conservatively to the first time within 1 um (the point: the middle of FCL's nearest
// points). Pairs that come within 1 mm without touching have no verdict and are left out.
// Columns: budget_ms (modelled narrow-phase time allowed), pairs (needing a narrow phase),
// lowered (pairs given a tier below their exact one), contacts, truth (FCL contacts), false_pos
// (our contacts FCL does not find), misses (FCL contacts we do not find), point error median /
// p95 (m, over the contacts both find that do not touch from the tick's start), detect_ms (our detect, wall, one thread).
// Usage: bench_budget_error [vehicles] [side_m] [--csv FILE]  (default 3000 600, bench/results/budget_error.csv)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "support/fixture.hpp"

#ifndef NPSNET_BENCH_PEERS
int main() {
  std::fprintf(stderr, "bench_budget_error: built without FCL (NPSNET_BENCH_PEERS): no oracle.\n");
  return 2;
}
#else
#include <fcl/narrowphase/distance.h>

#include "fcl_oracle.hpp"
#include "support/fcl_mesh.hpp"

using namespace npsnet;

namespace {

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1) + 0.5))];
}

struct Truth {
  bool hit = false, verdict = true, started_inside = false;
  Vec3 point{0, 0, 0};
};

}  // namespace

int main(int argc, char** argv) {
  int n = 3000;
  double side = 600;
  std::string csv = std::string(NPSNET_SOURCE_DIR) + "/bench/results/budget_error.csv";
  std::vector<std::string> pos;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
    else pos.push_back(argv[i]);
  }
  if (pos.size() > 0) n = std::stoi(pos[0]);
  if (pos.size() > 1) side = std::stod(pos[1]);
  const double dt = 0.1;
  world::World w = test::flat_world();
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0, 1);
  const char* kinds[] = {"m1a1", "bmp", "hmmwv"};
  const double x0 = 1000 - side / 2;
  // Placed apart (their thesis spheres apart where they end the tick), 10-25 m/s: the contacts
  // are the ones made in the tick.
  std::vector<Vec2> at;
  std::vector<double> rad;
  for (int i = 0, tries = 0; i < n && tries < 100 * n; ++tries) {
    const Vec2 p(x0 + side * u(rng), x0 + side * u(rng));
    const double r = w.kinds[w.kinds.find(kinds[i % 3])].radius_m;
    bool apart = true;
    for (size_t j = 0; j < at.size() && apart; ++j) apart = (at[j] - p).norm() >= r + rad[j];
    if (!apart) continue;
    const int e = test::add_vehicle(w, "bg" + std::to_string(i), kinds[i % 3], p.x(), p.y(), 360 * u(rng), 10 + 15 * u(rng));
    w.ents.snapshots[e] = 0;
    at.push_back(p), rad.push_back(r), ++i;
  }
  test::index_fixed(w);
  // Shapes and FCL meshes per model.
  std::vector<collision::Shape> shapes;
  std::vector<std::shared_ptr<test::FclMesh>> meshes;
  for (int m = 0; m < w.models.size(); ++m) {
    shapes.push_back(collision::make_shape(w.models[m]));
    meshes.push_back(test::fcl_mesh(shapes.back()));
  }
  auto model = [&](int e) { return w.kinds[w.ents.kind[e]].models[w.ents.state[e]]; };
  // The pairs that need a narrow phase: the tier choices of an ample budget.
  collision::Detector ample(collision::options_from("continuous", "auto", dt));
  ample.set_budget_ms(1e9);
  std::vector<collision::Contact> out;
  ample.detect(w, out);
  const auto pairs = ample.tier_choices();
  // The truth for each pair: FCL distance, conservative advancement over the tick.
  std::map<std::pair<int, int>, Truth> truth;
  int no_verdict = 0, truth_hits = 0, started_inside = 0;
  for (const auto& c : pairs) {
    const int a = std::min(c.a, c.b), b = std::max(c.a, c.b);
    Truth tr;
    const Mat3 ra = world::pose_rotation(w.ents.heading_deg[a], w.ents.pitch_deg[a], w.ents.roll_deg[a]);
    const Mat3 rb = world::pose_rotation(w.ents.heading_deg[b], w.ents.pitch_deg[b], w.ents.roll_deg[b]);
    const bench::FclToi o = bench::fcl_toi(meshes[model(a)], ra, w.ents.pos[a], w.ents.vel[a] * dt, meshes[model(b)], rb,
                                           w.ents.pos[b], w.ents.vel[b] * dt);
    tr.hit = o.hit, tr.started_inside = o.started_inside, tr.point = o.point;
    const bool near = o.graze || !o.converged;
    tr.verdict = !near;
    no_verdict += !tr.verdict;
    truth_hits += tr.hit && tr.verdict;
    started_inside += tr.hit && tr.started_inside;
    truth[{a, b}] = tr;
  }
  std::ofstream f(csv);
  f << "budget_ms,pairs,lowered,contacts,truth,false_pos,misses,point_err_median_m,point_err_p95_m,detect_ms\n";
  std::printf("%d vehicles in %.0f m x %.0f m: %zu pairs need a narrow phase, FCL: %d touch (%d from the tick's start: "
              "no point error), %d without verdict\n", n, side, side, pairs.size(), truth_hits, started_inside, no_verdict);
  std::printf("%10s %8s %8s %9s %9s %7s %12s %12s %10s\n", "budget_ms", "lowered", "contacts", "false_pos", "misses",
              "truth", "err_med_m", "err_p95_m", "detect_ms");
  for (double budget : {0.0, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0}) {
    collision::Detector det(collision::options_from("continuous", "auto", dt));
    det.set_budget_ms(budget);
    out.clear();
    const auto t0 = std::chrono::steady_clock::now();
    det.detect(w, out);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    int fp = 0, miss = 0, contacts = 0, lowered = 0;
    for (const auto& c : det.tier_choices()) lowered += c.chosen < c.exact;
    std::vector<double> err;
    std::map<std::pair<int, int>, const collision::Contact*> ours;
    for (const auto& c : out) ours[{std::min(c.a, c.b), std::max(c.a, c.b)}] = &c;
    for (const auto& [key, tr] : truth) {
      if (!tr.verdict) continue;
      const auto it = ours.find(key);
      const bool we = it != ours.end();
      contacts += we;
      if (we && !tr.hit) ++fp;
      if (!we && tr.hit) ++miss;
      if (we && tr.hit && !tr.started_inside) err.push_back((it->second->point - tr.point).norm());
    }
    std::printf("%10.1f %8d %8d %9d %9d %7d %12.4g %12.4g %10.2f\n", budget, lowered, contacts, fp, miss, truth_hits,
                percentile(err, 0.5), percentile(err, 0.95), ms);
    f << budget << ',' << pairs.size() - no_verdict << ',' << lowered << ',' << contacts << ',' << truth_hits << ','
      << fp << ',' << miss << ',' << percentile(err, 0.5) << ',' << percentile(err, 0.95) << ',' << ms << '\n';
  }
  return 0;
}
#endif
