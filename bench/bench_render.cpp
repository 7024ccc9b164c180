// Frames/s of the renderer (OSMesa, llvmpipe) on the default world: 40,303 fixed objects, the
// Appendix A vehicles and 500 background vehicles, with HUD and map inset, from a ground
// vehicle's eye (3 m above the ground) along a camera path. Reported: the median frame time over
// the path, as median_ms and median_fps counters. Paths:
//   forest: a 600 m circle around the centre of the densest 2 km square of fixed objects, looking
//           along the drive with the view swinging +-30 degrees (the worst case for objects);
//   tank1:  the first vehicle's drive along its heading at 40 km/h (the proving ground).
// BM_PlayerCamera: the player's cameras (driver, chase, orbit, map: node/cameras.hpp) at 960x540
// with HUD and map, around player1 driving at 40 km/h (issue 9).
// Run with LP_NUM_THREADS=2 (the target: >= 30 frames/s at 960x540 on 2 cores):
//   LP_NUM_THREADS=2 build/bench/bench_render [--benchmark_filter=PlayerCamera]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>

#include "support/dirs.hpp"
#include "input/action.hpp"
#include "node/cameras.hpp"
#include "render/renderer.hpp"
#include "world/scenario.hpp"

using namespace npsnet;

namespace {

struct Scene {
  world::Scenario sc;
  world::World w;
  Vec2 dense_centre{0, 0};
  int dense_count = 0;
};

Scene& scene() {
  static Scene s = [] {
    Scene x;
    x.sc = world::load_scenario(std::string(npsnet::dirs::source()) + "/scenarios/default.toml");
    x.w = world::build_world(x.sc);
    std::map<std::pair<int, int>, int> cells;
    for (const auto& p : x.w.fixed.pos) ++cells[{static_cast<int>(p.x() / 2000), static_cast<int>(p.y() / 2000)}];
    for (const auto& [c, n] : cells)
      if (n > x.dense_count) {
        x.dense_count = n;
        x.dense_centre = Vec2(c.first * 2000.0 + 1000, c.second * 2000.0 + 1000);
      }
    return x;
  }();
  return s;
}

// Renderers by frame size, made once; released in main() before the GL library's own teardown.
std::map<std::pair<int, int>, std::unique_ptr<render::Renderer>> g_renderers;

render::Renderer& renderer(int w, int h) {
  auto& r = g_renderers[{w, h}];
  if (!r) {
    render::RenderOptions o;
    o.width = w;
    o.height = h;
    o.shader_dir = std::string(npsnet::dirs::source()) + "/shaders";
    r = std::make_unique<render::Renderer>(o, scene().w);
  }
  return *r;
}

// Camera k of the path; `path` 0 = forest, 1 = tank1.
render::Camera path_camera(int path, int k) {
  const Scene& s = scene();
  const world::World& w = s.w;
  const double t = k * 0.1;
  Vec3 p;
  double heading;
  if (path == 0) {
    const double a = t * 0.05;  // rad: one lap every ~126 s of path
    const Vec2 c = s.dense_centre;
    const double r = 600;
    p = Vec3(c.x() + r * std::cos(a), c.y() + r * std::sin(a), 0);
    heading = dir_to_heading(Vec2(-std::sin(a), std::cos(a)));  // counter-clockwise drive
  } else {
    const Vec2 d = heading_to_dir(w.ents.heading_deg[0]);
    p = w.ents.pos[0] + Vec3(d.x(), d.y(), 0) * (kmh2mps(40.0) * t);
    heading = w.ents.heading_deg[0];
  }
  p.x() = std::clamp(p.x(), 0.0, w.terrain.width_m());
  p.y() = std::clamp(p.y(), 0.0, w.terrain.depth_m());
  p.z() = w.terrain.height(p.x(), p.y());
  return render::vehicle_eye(p, heading + 30.0 * std::sin(t * 0.7), -2.0, 3.0);
}

// One frame, its time (ms) appended to `ms`.
void timed_render(render::Renderer& r, const render::SceneView& v, const render::Camera& c, const render::Hud& hud,
                  std::vector<double>& ms) {
  const auto t0 = std::chrono::steady_clock::now();
  r.render(v, c, hud, true);
  ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
}

// The median frame time and rate of `ms`, and the objects drawn in the last frame, as counters.
void report_median(benchmark::State& state, const render::Renderer& r, std::vector<double>& ms) {
  std::sort(ms.begin(), ms.end());
  const double med = ms.empty() ? 0 : ms[ms.size() / 2];
  state.counters["median_ms"] = med;
  state.counters["median_fps"] = med > 0 ? 1000.0 / med : 0;
  state.counters["objects_drawn"] = static_cast<double>(r.stats().objects_full + r.stats().objects_simple);
}

void BM_Render(benchmark::State& state) {
  const int path = static_cast<int>(state.range(0));
  const int W = static_cast<int>(state.range(1)), H = static_cast<int>(state.range(2));
  Scene& s = scene();
  render::Renderer& r = renderer(W, H);
  render::Hud hud{true, 40.0, 90.0, 0.0, 0.0, 40, 1900.0, "TANK1 M1A1", "driver"};
  render::SceneView v{&s.w, nullptr, nullptr, 0.0, 0};
  std::vector<double> ms;
  ms.reserve(4096);
  int k = 0;
  for (auto _ : state) {
    const render::Camera c = path_camera(path, k);
    v.t = k * 0.1;
    timed_render(r, v, c, hud, ms);
    ++k;
  }
  report_median(state, r, ms);
  state.counters["terrain_tris"] = static_cast<double>(r.stats().terrain_triangles);
  state.SetLabel(std::string(path == 0 ? "forest" : "tank1") + " " + std::to_string(s.dense_count) +
                 " objects in the densest 2 km square");
}

// The player's four cameras (node/cameras.hpp) around player1, the default run's first vehicle,
// driven along its heading at 40 km/h over the terrain; the orbit camera turns 3 degrees a frame.
// `mode`: 0 driver, 1 chase, 2 orbit, 3 map.
void BM_PlayerCamera(benchmark::State& state) {
  const auto mode = static_cast<input::CameraMode>(state.range(0));
  Scene& s = scene();
  const world::World& w = s.w;
  render::Renderer& r = renderer(960, 540);
  world::Entities ents = w.ents;  // player1 moves in this copy
  const Vec3 start = w.ents.pos[0];
  const Vec2 d = heading_to_dir(w.ents.heading_deg[0]);
  render::SceneView v{&w, &ents, nullptr, 0.0, 0};
  std::vector<double> ms;
  ms.reserve(4096);
  int k = 0;
  for (auto _ : state) {
    Vec3 p = start + Vec3(d.x(), d.y(), 0) * (kmh2mps(40.0) * k * 0.1);
    p.x() = std::clamp(p.x(), 0.0, w.terrain.width_m());
    p.y() = std::clamp(p.y(), 0.0, w.terrain.depth_m());
    p.z() = w.terrain.height(p.x(), p.y());
    ents.pos[0] = p;
    v.t = k * 0.1;
    const render::Camera c = node::player_camera(w, ents, 0, mode, 45.0 + 3.0 * k);
    const render::Hud hud{true, 40.0, ents.heading_deg[0], 0.0, 0.0, 40, 1900.0, "PLAYER1 M1A1",
                          input::camera_name(mode)};
    timed_render(r, v, c, hud, ms);
    ++k;
  }
  report_median(state, r, ms);
  state.SetLabel(std::string("player1 ") + input::camera_name(mode) + " camera, HUD + map");
}

}  // namespace

BENCHMARK(BM_Render)
    ->ArgNames({"path", "w", "h"})
    ->Args({0, 640, 480})
    ->Args({0, 960, 540})
    ->Args({1, 640, 480})
    ->Args({1, 960, 540})
    ->Iterations(300)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK(BM_PlayerCamera)
    ->ArgNames({"mode"})
    ->DenseRange(0, 3)
    ->Iterations(300)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  g_renderers.clear();
  return 0;
}
