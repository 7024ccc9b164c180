// Speed benchmark (issue 6): one step of sphere broad phase + sphere narrow phase on the default
// world's 40,303 fixed objects with N = 500, 5,000, 50,000, 100,000 moving vehicles (half spread
// over the 50 km map, half crowded in one 2 km square), ours vs Bullet 3.24 in double precision (btCollisionWorld +
// btDbvtBroadphase, sphere shapes) vs FCL 0.7 (two DynamicAABBTreeCollisionManagers, fcl::collide
// on spheres), side by side in one run; every vehicle moves between steps (each peer updates its
// structure). Before timing, all three must find the same contact set at every N (else exit 1).
// Beside it: our full continuous step (Detector: swept spheres, tiers up to the mesh) on the
// same vehicles: its first tick (every touching pair a new contact, the whole tier cascade) and
// the ticks after (episodes going on). Prints the ratio table; writes bench/results/broadphase.csv.
//   build/bench/bench_broadphase [--quick]   (bench/CMakeLists.txt links Bullet and FCL; --quick:
//   N <= 5,000, short runs, no CSV)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <random>

#include "support/dirs.hpp"
#include "collision/collision.hpp"
#include "crowd_scene.hpp"
#include "world/pose.hpp"
#include "world/scenario.hpp"

#ifdef NPSNET_BENCH_PEERS
#include <btBulletCollisionCommon.h>

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#endif

using namespace npsnet;

namespace {

using Pair = std::pair<uint32_t, uint32_t>;  // moving-moving (i < j); moving-fixed (i, N + o)

struct Scene {
  world::World w;                 // default world + N vehicles
  std::vector<Vec3> fc;           // fixed sphere centres
  std::vector<float> fr;          // fixed radii
  std::vector<Vec3> mc;           // moving centres (base)
  std::vector<float> mr;          // moving radii
  std::vector<Vec3> dm;           // per-step displacement (alternating sign)
};

world::World& base_world() {
  static world::World w = [] {
    auto sc = world::load_scenario(std::string(npsnet::dirs::source()) + "/scenarios/default.toml");
    return world::build_world(sc);
  }();
  return w;
}

Scene& scene(int n) {
  static std::map<int, Scene> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  Scene& s = cache[n];
  s.w = base_world();
  s.w.ents = world::Entities{};
  bench::add_crowd(s.w, n);
  for (size_t o = 0; o < s.w.fixed.size(); ++o) {
    s.fc.push_back(world::fixed_centre(s.w, o));
    s.fr.push_back(static_cast<float>(world::fixed_radius(s.w, o)));
  }
  for (size_t e = 0; e < s.w.ents.size(); ++e) {
    s.mc.push_back(world::entity_centre(s.w, e));
    s.mr.push_back(static_cast<float>(world::entity_radius(s.w, e)));
    s.dm.push_back(s.w.ents.vel[e] * 0.1);
  }
  return s;
}

Vec3 pos_at(const Scene& s, size_t i, int step) { return s.mc[i] + (step & 1 ? s.dm[i] : Vec3::Zero()); }

// ---- ours: hashed moving grid + fixed gridsquares, sphere test -------------------------------
struct Ours {
  world::FixedGrid fixed;
  collision::MovingGrid grid;
  std::vector<collision::Box> boxes;
  std::vector<Vec3> c;
  std::vector<Pair> pairs;
  void setup(const Scene& s) {
    fixed.build(s.fc, s.fr, base_world().terrain.width_m(), base_world().terrain.depth_m(), thesis::kGridsquareM);
    boxes.resize(s.mc.size());
    c.resize(s.mc.size());
  }
  void step(const Scene& s, int k, std::vector<Pair>& out) {
    out.clear();
    const uint32_t n = static_cast<uint32_t>(s.mc.size());
    for (uint32_t i = 0; i < n; ++i) {
      c[i] = pos_at(s, i, k);
      boxes[i] = collision::swept_box(c[i], c[i], s.mr[i]);
    }
    grid.pairs(boxes, pairs);
    for (const Pair& p : pairs) {
      const double rr = double(s.mr[p.first]) + s.mr[p.second];
      if ((c[p.first] - c[p.second]).squaredNorm() < rr * rr) out.push_back(p);
    }
    for (uint32_t i = 0; i < n; ++i) {
      const Vec3 ci = c[i];
      const double ri = s.mr[i];
      const collision::Box& b = boxes[i];
      fixed.query(b.lo[0], b.lo[1], b.hi[0], b.hi[1], [&](int o, float) {
        const double rr = ri + s.fr[o];
        if ((s.fc[o] - ci).squaredNorm() < rr * rr) out.emplace_back(i, n + o);  // double, as the peers
      });
    }
  }
};

#ifdef NPSNET_BENCH_PEERS
// ---- Bullet -----------------------------------------------------------------------------------
struct Bullet {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btCollisionWorld world{&dispatcher, &broadphase, &config};
  std::vector<std::unique_ptr<btSphereShape>> shapes;
  std::vector<std::unique_ptr<btCollisionObject>> objs;
  std::vector<btCollisionObject*> moving;
  void add(const Vec3& p, float r, int id, bool fixed) {
    shapes.push_back(std::make_unique<btSphereShape>(r));
    auto o = std::make_unique<btCollisionObject>();
    o->setCollisionShape(shapes.back().get());
    btTransform t;
    t.setIdentity();
    t.setOrigin(btVector3(p.x(), p.y(), p.z()));
    o->setWorldTransform(t);
    o->setUserIndex(id);
    if (fixed) {
      o->setCollisionFlags(o->getCollisionFlags() | btCollisionObject::CF_STATIC_OBJECT);
      o->setActivationState(ISLAND_SLEEPING);  // never re-fitted
      world.addCollisionObject(o.get(), btBroadphaseProxy::StaticFilter,
                               btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    } else {
      o->setActivationState(DISABLE_DEACTIVATION);
      world.addCollisionObject(o.get(), btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
      moving.push_back(o.get());
    }
    objs.push_back(std::move(o));
  }
  void setup(const Scene& s) {
    world.setForceUpdateAllAabbs(false);
    const uint32_t n = static_cast<uint32_t>(s.mc.size());
    for (size_t o = 0; o < s.fc.size(); ++o) add(s.fc[o], s.fr[o], static_cast<int>(n + o), true);
    for (uint32_t i = 0; i < n; ++i) add(s.mc[i], s.mr[i], static_cast<int>(i), false);
  }
  void step(const Scene& s, int k, std::vector<Pair>* out) {
    for (size_t i = 0; i < moving.size(); ++i) {
      const Vec3 p = pos_at(s, i, k);
      moving[i]->getWorldTransform().setOrigin(btVector3(p.x(), p.y(), p.z()));
    }
    world.performDiscreteCollisionDetection();
    if (!out) return;
    out->clear();
    const int m = dispatcher.getNumManifolds();
    for (int i = 0; i < m; ++i) {
      const btPersistentManifold* mf = dispatcher.getManifoldByIndexInternal(i);
      bool touch = false;
      for (int c = 0; c < mf->getNumContacts(); ++c) touch |= mf->getContactPoint(c).getDistance() < 0;
      if (!touch) continue;
      const uint32_t a = static_cast<uint32_t>(mf->getBody0()->getUserIndex());
      const uint32_t b = static_cast<uint32_t>(mf->getBody1()->getUserIndex());
      out->emplace_back(std::min(a, b), std::max(a, b));
    }
  }
};

// ---- FCL --------------------------------------------------------------------------------------
struct Fcl {
  fcl::DynamicAABBTreeCollisionManagerd fixed_mgr, moving_mgr;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objs;
  std::vector<fcl::CollisionObjectd*> moving;
  std::vector<intptr_t> ids;
  struct Data {
    std::vector<Pair>* out;
  };
  static bool callback(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* cdata) {
    auto* d = static_cast<Data*>(cdata);
    fcl::CollisionRequestd req;
    fcl::CollisionResultd res;
    if (fcl::collide(o1, o2, req, res) > 0 && d->out) {
      const auto a = static_cast<uint32_t>(reinterpret_cast<intptr_t>(o1->getUserData()));
      const auto b = static_cast<uint32_t>(reinterpret_cast<intptr_t>(o2->getUserData()));
      d->out->emplace_back(std::min(a, b), std::max(a, b));
    }
    return false;  // go on
  }
  fcl::CollisionObjectd* make(const Vec3& p, float r, intptr_t id) {
    auto o = std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Sphered>(r));
    o->setTranslation(fcl::Vector3d(p.x(), p.y(), p.z()));
    o->computeAABB();
    o->setUserData(reinterpret_cast<void*>(id));
    objs.push_back(std::move(o));
    return objs.back().get();
  }
  void setup(const Scene& s) {
    const uint32_t n = static_cast<uint32_t>(s.mc.size());
    std::vector<fcl::CollisionObjectd*> f;
    for (size_t o = 0; o < s.fc.size(); ++o) f.push_back(make(s.fc[o], s.fr[o], n + o));
    for (uint32_t i = 0; i < n; ++i) moving.push_back(make(s.mc[i], s.mr[i], i));
    fixed_mgr.registerObjects(f);
    fixed_mgr.setup();
    moving_mgr.registerObjects(moving);
    moving_mgr.setup();
  }
  void step(const Scene& s, int k, std::vector<Pair>* out) {
    for (size_t i = 0; i < moving.size(); ++i) {
      const Vec3 p = pos_at(s, i, k);
      moving[i]->setTranslation(fcl::Vector3d(p.x(), p.y(), p.z()));
      moving[i]->computeAABB();
    }
    moving_mgr.update();
    Data d{out};
    if (out) out->clear();
    moving_mgr.collide(&d, callback);
    moving_mgr.collide(&fixed_mgr, &d, callback);
  }
};
#endif

const int kNs[] = {500, 5000, 50000, 100000};

struct Peers {
  Ours ours;
#ifdef NPSNET_BENCH_PEERS
  Bullet bullet;
  Fcl fcl;
#endif
  collision::Detector full{collision::Options{collision::Method::Continuous, collision::Tier::Auto, 0.1}};
  size_t contacts = 0;
  double full_first_ms = 0;
  size_t full_first_contacts = 0;
};

Peers& peers(int n) {
  static std::map<int, std::unique_ptr<Peers>> cache;
  auto& p = cache[n];
  if (p) return *p;
  p = std::make_unique<Peers>();
  Scene& s = scene(n);
  p->ours.setup(s);
  std::vector<Pair> a;
  p->ours.step(s, 0, a);
  std::sort(a.begin(), a.end());
  p->contacts = a.size();
#ifdef NPSNET_BENCH_PEERS
  p->bullet.setup(s);
  p->fcl.setup(s);
  std::vector<Pair> b, c;
  p->bullet.step(s, 0, &b);
  p->fcl.step(s, 0, &c);
  std::sort(b.begin(), b.end());
  std::sort(c.begin(), c.end());
  if (a != b || a != c) {
    std::fprintf(stderr, "N=%d: contact sets differ: ours %zu, Bullet %zu, FCL %zu\n", n, a.size(), b.size(), c.size());
    for (const auto* other : {&b, &c}) {
      std::vector<Pair> d;
      std::set_symmetric_difference(a.begin(), a.end(), other->begin(), other->end(), std::back_inserter(d));
      for (size_t k = 0; k < d.size() && k < 6; ++k) {
        const Pair& p = d[k];
        const Vec3 ci = s.mc[p.first];
        const bool fx = p.second >= static_cast<uint32_t>(n);
        const Vec3 cj = fx ? s.fc[p.second - n] : s.mc[p.second];
        const double rr = double(s.mr[p.first]) + (fx ? s.fr[p.second - n] : s.mr[p.second]);
        std::fprintf(stderr, "  %s: (%u, %u%s) distance - radii = %.3g m\n", other == &b ? "Bullet" : "FCL", p.first,
                     fx ? p.second - n : p.second, fx ? " fixed" : "", (ci - cj).norm() - rr);
      }
    }
    std::exit(1);
  }
  std::fprintf(stderr, "N=%d: ours, Bullet and FCL agree on %zu contacts\n", n, a.size());
#endif
  // Our full step, first tick (every contact a new episode: the whole tier cascade), untimed by
  // Google Benchmark; BM_OursFull then times the following ticks (episodes going on).
  std::vector<collision::Contact> first;
  const auto t0 = std::chrono::steady_clock::now();
  p->full.detect(s.w, first);
  p->full_first_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  p->full_first_contacts = first.size();
  return *p;
}

void BM_Ours(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  Peers& p = peers(n);
  Scene& s = scene(n);
  std::vector<Pair> out;
  out.reserve(p.contacts * 2 + 16);
  int k = 0;
  for (auto _ : st) {
    p.ours.step(s, ++k, out);
    benchmark::DoNotOptimize(out.data());
  }
  st.counters["contacts"] = static_cast<double>(p.contacts);
}

#ifdef NPSNET_BENCH_PEERS
void BM_Bullet(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  Peers& p = peers(n);
  Scene& s = scene(n);
  int k = 0;
  for (auto _ : st) p.bullet.step(s, ++k, nullptr);
  st.counters["contacts"] = static_cast<double>(p.contacts);
}
void BM_Fcl(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  Peers& p = peers(n);
  Scene& s = scene(n);
  int k = 0;
  std::vector<Pair> out;
  out.reserve(p.contacts * 2 + 16);
  for (auto _ : st) {
    out.clear();
    p.fcl.step(s, ++k, &out);
  }
  st.counters["contacts"] = static_cast<double>(p.contacts);
}
#endif

// Our full step: the continuous Detector (swept spheres, tiers) on the same vehicles.
void BM_OursFull(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  Peers& p = peers(n);
  Scene& s = scene(n);
  std::vector<collision::Contact> out;
  int k = 0;
  for (auto _ : st) {
    ++k;
    for (size_t e = 0; e < s.w.ents.size(); ++e) s.w.ents.pos[e] += (k & 1 ? 1.0 : -1.0) * s.dm[e];
    out.clear();
    p.full.detect(s.w, out);
    benchmark::DoNotOptimize(out.data());
  }
  st.counters["first_tick_ms"] = p.full_first_ms;
  st.counters["first_tick_contacts"] = static_cast<double>(p.full_first_contacts);
}

void args(benchmark::internal::Benchmark* b, bool quick) {
  for (int n : kNs) {
    if (quick && n > 5000) continue;
    b->Arg(n);
  }
  b->Unit(benchmark::kMillisecond)->MinTime(quick ? 0.05 : 0.5)->UseRealTime();
}

struct Capture : benchmark::ConsoleReporter {
  std::map<std::string, std::map<int, double>> ms;  // family -> N -> ms per step
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      const std::string name = r.benchmark_name();
      const auto slash = name.find('/');
      const std::string fam = name.substr(0, slash);
      const int n = std::stoi(name.substr(slash + 1));
      ms[fam][n] = r.GetAdjustedRealTime();
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::string(argv[i]) == "--quick") quick = true;
    else rest.push_back(argv[i]);
  }
  int rc = static_cast<int>(rest.size());
#ifndef NPSNET_BENCH_PEERS
  std::fprintf(stderr,
               "bench_broadphase: built without Bullet and FCL (NPSNET_BENCH_PEERS); the peers' columns "
               "are missing. Link it with Bullet (pkg-config bullet-float64) and fcl, define NPSNET_BENCH_PEERS.\n");
#endif
  args(benchmark::RegisterBenchmark("ours_sphere_step", BM_Ours), quick);
#ifdef NPSNET_BENCH_PEERS
  args(benchmark::RegisterBenchmark("bullet", BM_Bullet), quick);
  args(benchmark::RegisterBenchmark("fcl", BM_Fcl), quick);
#endif
  args(benchmark::RegisterBenchmark("ours_full_continuous", BM_OursFull), quick);
  benchmark::Initialize(&rc, rest.data());
  Capture rep;
  benchmark::RunSpecifiedBenchmarks(&rep);
  // Ratio table and CSV.
#ifdef NPSNET_BENCH_PEERS  // the committed CSV holds all three side by side at every N, or nothing
  std::ofstream csv(quick ? "/dev/null" : std::string(npsnet::dirs::source()) + "/bench/results/broadphase.csv");
#else
  std::ofstream csv("/dev/null");
#endif
  csv << "n,contacts,ours_ms,bullet_ms,fcl_ms,ours_full_ms,ours_over_bullet,ours_over_fcl,ours_over_faster_peer,"
         "ours_full_first_tick_ms,full_first_tick_contacts\n";
  std::printf("\n| N | contacts | ours ms | Bullet ms | FCL ms | ours/Bullet | ours/FCL | ours/faster | our full step ms "
              "(later ticks) | our full step, first tick ms (new contacts) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (int n : kNs) {
    if (!rep.ms["ours_sphere_step"].count(n)) continue;
    const double o = rep.ms["ours_sphere_step"][n];
    const double b = rep.ms["bullet"].count(n) ? rep.ms["bullet"][n] : NAN;
    const double f = rep.ms["fcl"].count(n) ? rep.ms["fcl"][n] : NAN;
    const double full = rep.ms["ours_full_continuous"].count(n) ? rep.ms["ours_full_continuous"][n] : NAN;
    const double faster = std::min(b, f);
    const Peers& pp = peers(n);
    std::printf("| %d | %zu | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.1f (%zu) |\n", n, pp.contacts, o, b, f,
                o / b, o / f, o / faster, full, pp.full_first_ms, pp.full_first_contacts);
    csv << n << ',' << pp.contacts << ',' << o << ',' << b << ',' << f << ',' << full << ',' << o / b << ','
        << o / f << ',' << o / faster << ',' << pp.full_first_ms << ',' << pp.full_first_contacts << '\n';
  }
  return 0;
}
