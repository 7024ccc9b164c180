// render_views: renders views of a scenario's world into PNGs and measures frames/s.
//   render_views [--scenario FILE] [--out DIR] [--size WxH] [--gallery] [--fps N] [--window]
// --gallery: every model of the kinds file in every state, on flat ground (models/ check).
// --fps N: N frames along a ground vehicle's path (the scenario's first vehicle, driving its
//          heading at 40 km/h, eye 3 m up) with HUD and map; prints the median frames/s.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>

#include "core/stopwatch.hpp"
#include "npsnet_dirs.hpp"
#include "render/renderer.hpp"
#include "world/scenario.hpp"

using namespace npsnet;
using core::ms_since;

namespace {

// Row k of the gallery: y of the row and x spacing of its states (rows far enough apart that a
// close-up of one row shows little of the next).
struct Row {
  double y, step;
};
std::vector<Row> gallery_rows(const world::World& w) {
  std::vector<Row> rows;
  double y = 30;
  for (int k = 0; k < w.kinds.size(); ++k) {
    const double r = std::max(3.0, w.kinds[k].radius_m);
    if (k > 0) y += 2.5 * std::max(r, std::max(3.0, w.kinds[k - 1].radius_m)) + 25;
    rows.push_back({y, std::max(12.0, r * 2.6)});
  }
  return rows;
}

world::World gallery_world(const std::filesystem::path& kinds_file) {
  world::World w;
  w.kinds = world::KindTable::load(kinds_file, w.models);
  const auto rows = gallery_rows(w);
  const int n = static_cast<int>(rows.back().y / 2.0) + 40;
  std::vector<float> h(static_cast<size_t>(n * n), 100.0f);
  w.terrain = world::Terrain(n, n, 2.0, h, geo::Geodetic{35.98, -121.25, 0.0});
  // one row per kind, one column per state; vehicles and munitions are entities
  for (int k = 0; k < w.kinds.size(); ++k) {
    const auto& kind = w.kinds[k];
    for (size_t s = 0; s < kind.states.size(); ++s) {
      const Vec3 p(30 + rows[static_cast<size_t>(k)].step * static_cast<double>(s), rows[static_cast<size_t>(k)].y, 100.0);
      if (kind.mobile()) {
        const int e = w.ents.add(kind.name + "_" + std::to_string(s), k, p, 30.0f, static_cast<float>(kind.radius_m));
        w.ents.state[static_cast<size_t>(e)] = static_cast<uint8_t>(s);
      } else {
        w.fixed.add(kind.name + "_" + std::to_string(s), k, p, 30.0f, static_cast<float>(kind.radius_m));
        w.fixed.state.back() = static_cast<uint8_t>(s);
      }
    }
  }
  w.index_fixed();
  return w;
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path scenario = std::filesystem::path(NPSNET_SHADER_DIR).parent_path() / "scenarios/default.toml";
  std::filesystem::path out = "render-out";
  int W = 960, H = 540, fps_frames = 0;
  bool gallery = false, window = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "render_views: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--scenario") scenario = next();
    else if (a == "--out") out = next();
    else if (a == "--size") {
      const std::string v = next();
      if (std::sscanf(v.c_str(), "%dx%d", &W, &H) != 2 || W < 1 || H < 1) {
        std::fprintf(stderr, "render_views: --size %s: want WxH\n", v.c_str());
        return 2;
      }
    } else if (a == "--gallery") gallery = true;
    else if (a == "--window") window = true;
    else if (a == "--fps") fps_frames = std::atoi(next().c_str());
    else {
      std::fprintf(stderr, "render_views: unknown argument %s\n", a.c_str());
      return 2;
    }
  }
  try {
    render::RenderOptions opt;
    opt.width = W;
    opt.height = H;
    opt.window = window;
    opt.shader_dir = NPSNET_SHADER_DIR;
    std::filesystem::create_directories(out);
    if (gallery) {
      const auto kinds = std::filesystem::path(NPSNET_SHADER_DIR).parent_path() / "models/kinds.toml";
      world::World w = gallery_world(kinds);
      opt.fog = false;
      render::Renderer r(opt, w);
      std::printf("%s\n", r.gl_description().c_str());
      render::SceneView v{&w, nullptr, nullptr, 0.0, -1};
      // one close-up per kind row
      const auto rows = gallery_rows(w);
      for (int k = 0; k < w.kinds.size(); ++k) {
        const auto& kind = w.kinds[k];
        const auto& row = rows[static_cast<size_t>(k)];
        const double span = row.step * static_cast<double>(kind.states.size() - 1);
        const double zt = 100 + std::max(0.5, kind.height_m) * 0.4;
        const Vec3 a(30, row.y, zt), b(30 + span, row.y, zt);
        render::Camera c;
        const double dist = std::max(4.0, span * 0.8 + std::max(1.0, kind.radius_m) * 3.0);
        c.target = 0.5 * (a + b);
        c.eye = c.target + Vec3(-0.3 * dist, -dist, 0.45 * dist);
        r.render(v, c, {}, false);
        const auto f = out / ("gallery-" + kind.name + ".png");
        if (!r.write_png(f)) throw std::runtime_error("cannot write " + f.string());
        std::printf("wrote %s (%zu states)\n", f.string().c_str(), kind.states.size());
      }
      return 0;
    }
    const world::Scenario sc = world::load_scenario(scenario);
    world::World w = world::build_world(sc);
    std::printf("world: terrain %dx%d posts at %.1f m, %zu fixed objects, %zu entities, %d models\n",
                w.terrain.cols(), w.terrain.rows(), w.terrain.spacing_m(), w.fixed.size(), w.ents.size(),
                w.models.size());
    auto t0 = std::chrono::steady_clock::now();
    render::Renderer r(opt, w);
    std::printf("renderer ready in %.0f ms: %s\n", ms_since(t0), r.gl_description().c_str());
    const int driven = w.ents.size() ? 0 : -1;
    render::SceneView v{&w, nullptr, nullptr, 0.0, driven};
    render::Hud hud;
    if (driven >= 0) {
      const auto& kind = w.kind_of_entity(0);
      hud = {true, mps2kmh(w.ents.cruise_mps[0]), w.ents.heading_deg[0], w.ents.pitch_deg[0], w.ents.roll_deg[0],
             w.ents.rounds[0], w.ents.fuel_l[0], w.ents.id[0] + " " + kind.name, "outside"};
    }
    if (fps_frames > 0) {
      if (driven < 0) throw std::runtime_error("--fps needs a vehicle in the scenario");
      std::vector<double> ms;
      const Vec2 d = heading_to_dir(w.ents.heading_deg[0]);
      const Vec3 start = w.ents.pos[0];
      for (int f = 0; f < fps_frames; ++f) {
        const double t = f * 0.1;  // 10 Hz scenario time, 40 km/h
        Vec3 p = start + Vec3(d.x(), d.y(), 0) * (kmh2mps(40.0) * t);
        p.z() = w.terrain.height(p.x(), p.y());
        const double yaw = w.ents.heading_deg[0] + 25.0 * std::sin(t * 0.5);  // look around while driving
        v.t = t;
        const render::Camera c = render::vehicle_eye(p, yaw, -2.0, 3.0);
        t0 = std::chrono::steady_clock::now();
        r.render(v, c, hud, true);
        ms.push_back(ms_since(t0));
      }
      const auto st = r.stats();
      std::sort(ms.begin(), ms.end());
      const double med = ms[ms.size() / 2];
      std::printf("fps %dx%d: %d frames, median %.2f ms = %.1f frames/s (min %.2f ms, max %.2f ms)\n", W, H,
                  fps_frames, med, 1000.0 / med, ms.front(), ms.back());
      std::printf("last frame: terrain chunks %d drawn %d culled, %lld triangles; blocks %d visible %d culled; "
                  "objects %lld full %lld simple, %lld triangles\n",
                  st.terrain_chunks_drawn, st.terrain_chunks_culled, static_cast<long long>(st.terrain_triangles),
                  st.blocks_visible, st.blocks_culled, static_cast<long long>(st.objects_full),
                  static_cast<long long>(st.objects_simple), static_cast<long long>(st.object_triangles));
      r.write_png(out / "fps-last-frame.png");
      return 0;
    }
    // 1. driver's eye
    r.render(v, render::vehicle_eye(w.ents.pos[0], w.ents.heading_deg[0], -2.0, 3.0), hud, true);
    r.write_png(out / "view-driver.png");
    // 2. the first two vehicles, as an imminent snapshot would see them
    if (w.ents.size() >= 2) {
      r.render(v, render::look_at_pair(w, w.ents.pos[0], w.ents.pos[1]), hud, true);
      r.write_png(out / "view-pair.png");
    }
    // 3. a crater + explosion + fire next to the first vehicle, 1.5 s after
    const Vec3 at = w.ents.pos[0] + Vec3(25, 15, 0);
    const world::PostRect pr = w.terrain.crater(at.x(), at.y(), 6.0, 2.0);
    r.terrain_changed(pr);
    r.add_crater(Vec3(at.x(), at.y(), w.terrain.height(at.x(), at.y())), 6.0, 0.0);
    r.add_explosion(Vec3(at.x(), at.y(), w.terrain.height(at.x(), at.y())), 0.0, 1.0f);
    r.add_fire(w.ents.pos[0] + Vec3(-20, 30, 0), 0.0, 20.0);
    for (double t : {0.1, 1.0, 4.0}) {
      v.t = t;
      render::Camera c = render::look_at_pair(w, w.ents.pos[0], at);
      r.render(v, c, hud, true);
      char name[64];
      std::snprintf(name, sizeof name, "view-explosion-t%.1f.png", t);
      r.write_png(out / name);
    }
    // 4. from a ground vehicle's eye in the densest 2 km square of fixed objects, four directions
    {
      std::map<std::pair<int, int>, int> cells;
      for (const auto& p : w.fixed.pos) ++cells[{static_cast<int>(p.x() / 2000), static_cast<int>(p.y() / 2000)}];
      auto best = cells.begin();
      for (auto it = cells.begin(); it != cells.end(); ++it)
        if (it->second > best->second) best = it;
      Vec3 p(best->first.first * 2000.0 + 1000, best->first.second * 2000.0 + 1000, 0);
      p.z() = w.terrain.height(p.x(), p.y());
      for (int hdg : {0, 90, 180, 270}) {
        r.render(v, render::vehicle_eye(p, hdg, -2.0, 3.0), hud, true);
        const auto st = r.stats();
        std::printf("forest view (%.0f, %.0f) heading %d: %lld full + %lld simplified objects, %lld terrain triangles\n",
                    p.x(), p.y(), hdg, static_cast<long long>(st.objects_full), static_cast<long long>(st.objects_simple),
                    static_cast<long long>(st.terrain_triangles));
        r.write_png(out / ("view-forest-" + std::to_string(hdg) + ".png"));
      }
    }
    // 5. the highest hill from 4 km, and the lake (water level) from its shore
    {
      int bi = 0, bj = 0;
      for (int j = 0; j < w.terrain.rows(); ++j)
        for (int i = 0; i < w.terrain.cols(); ++i)
          if (w.terrain.post(i, j) > w.terrain.post(bi, bj)) bi = i, bj = j;
      const Vec3 top(bi * w.terrain.spacing_m(), bj * w.terrain.spacing_m(), w.terrain.post(bi, bj));
      render::Camera c;
      const Vec3 from = top + Vec3(-2800, -2800, 0);
      c.eye = Vec3(from.x(), from.y(), std::max(from.z(), w.terrain.height(from.x(), from.y())) + 150);
      c.target = top;
      r.render(v, c, hud, true);
      r.write_png(out / "view-hill.png");
      std::printf("hill top (%.0f, %.0f) %.0f m\n", top.x(), top.y(), top.z());
      if (w.water_level_m > -1e8) {
        // the lowest post is in the lake: look at it from 1.5 km south, 40 m up
        int li = 0, lj = 0;
        for (int j = 0; j < w.terrain.rows(); ++j)
          for (int i = 0; i < w.terrain.cols(); ++i)
            if (w.terrain.post(i, j) < w.terrain.post(li, lj)) li = i, lj = j;
        const Vec3 low(li * w.terrain.spacing_m(), lj * w.terrain.spacing_m(), w.water_level_m);
        c.eye = low + Vec3(0, -1500, 0);
        c.eye.z() = std::max(w.water_level_m, w.terrain.height(c.eye.x(), c.eye.y())) + 40;
        c.target = low;
        r.render(v, c, hud, true);
        r.write_png(out / "view-lake.png");
        std::printf("lake bottom (%.0f, %.0f) %.0f m, water at %.0f m\n", low.x(), low.y(),
                    static_cast<double>(w.terrain.post(li, lj)), w.water_level_m);
      }
    }
    // 6. overview from high above the proving ground
    render::Camera high;
    high.eye = w.ents.pos[0] + Vec3(-3000, -4000, 2500);
    high.target = w.ents.pos[0] + Vec3(2000, 2000, 0);
    v.t = 0;
    r.render(v, high, hud, true);
    r.write_png(out / "view-overview.png");
    std::printf("wrote views to %s\n", out.string().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_views: %s\n", e.what());
    return 2;
  }
  return 0;
}
