#include "render/hud_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace npsnet::render {

namespace {
std::string fmt(const char* f, double a) {
  char b[64];
  std::snprintf(b, sizeof b, f, a);
  return b;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}
}  // namespace

void draw_hud_and_map(Overlay& overlay, const world::World& w, const SceneView& v, const ViewMath& vm, const Hud& hud,
                      bool map_inset, double reach_m) {
  const int W = vm.width, H = vm.height;
  const float s = static_cast<float>(std::max(1, static_cast<int>(std::lround(H / 300.0))));  // font pixel size
  overlay.begin(W, H);
  const Rgba panel{0.0f, 0.0f, 0.0f, 0.55f}, white{1, 1, 1, 1}, amber{1.0f, 0.78f, 0.25f, 1};
  const world::Entities& e = v.ents ? *v.ents : w.ents;
  const bool driven_ok = v.driven >= 0 && static_cast<size_t>(v.driven) < e.size();
  // scenario clock, top-left
  const std::string clock = "T " + fmt("%.1f", v.t) + " S";
  overlay.rect(4 * s, 4 * s, (static_cast<float>(clock.size()) * 6 + 4) * s, 11 * s, panel);
  overlay.text(6 * s, 6 * s, s, clock, white);
  if (hud.show) {
    std::vector<std::string> lines = {
        hud.label.empty() ? std::string("VEHICLE") : hud.label,
        "SPD " + fmt("%6.1f", hud.speed_kmh) + " KM/H  HDG " + fmt("%05.1f", wrap360(hud.heading_deg)),
        "PITCH " + fmt("%+5.1f", hud.pitch_deg) + "  ROLL " + fmt("%+5.1f", hud.roll_deg),
        "ROUNDS " + std::to_string(hud.rounds) + "  FUEL " + fmt("%.0f", hud.fuel_l) + " L"};
    if (!hud.camera.empty()) lines.push_back("CAMERA " + upper(hud.camera));
    size_t longest = 0;
    for (const auto& l : lines) longest = std::max(longest, l.size());
    const float n = static_cast<float>(lines.size());
    const float ph = (n * 10 + 4) * s, pw = (static_cast<float>(longest) * 6 + 6) * s;
    const float x0 = 4 * s, y0 = static_cast<float>(H) - ph - 4 * s;
    overlay.rect(x0, y0, pw, ph, panel);
    for (size_t k = 0; k < lines.size(); ++k)
      overlay.text(x0 + 3 * s, y0 + (3 + 10 * static_cast<float>(k)) * s, s, lines[k], k == 0 ? amber : white);
  }
  if (map_inset) {
    const float side = std::floor(std::min(W, H) * 0.32f);
    const float mx = static_cast<float>(W) - side - 6 * s, my = 6 * s;
    const double TW = w.terrain.width_m(), TD = w.terrain.depth_m();
    const float aspect = static_cast<float>(TW / std::max(TD, 1.0));
    const float mw = aspect >= 1 ? side : side * aspect, mh = aspect >= 1 ? side / aspect : side;
    overlay.rect(mx - 2, my - 2, mw + 4, mh + 4, {0, 0, 0, 0.8f});
    overlay.map(mx, my, mw, mh);
    const auto to_map = [&](const Vec3& p, float& x, float& y) {
      x = mx + static_cast<float>(std::clamp(p.x() / TW, 0.0, 1.0)) * mw;
      y = my + static_cast<float>(1.0 - std::clamp(p.y() / TD, 0.0, 1.0)) * mh;
    };
    const float dot = std::max(2.0f, s * 1.5f);
    for (size_t i = 0; i < e.size(); ++i) {
      if (i < e.active.size() && !e.active[i]) continue;
      if (static_cast<int>(i) == v.driven || !e.pos[i].allFinite()) continue;
      float x, y;
      to_map(e.pos[i], x, y);
      const int k = e.kind[i];
      Rgba c{0.2f, 0.55f, 1.0f, 1};  // local vehicles
      if (k >= 0 && k < w.kinds.size()) {
        const auto& kind = w.kinds[k];
        if (kind.mobility == world::Mobility::Munition) c = {1.0f, 0.95f, 0.2f, 1};
        else if (e.state[i] + 1u >= kind.states.size() && kind.states.size() > 1) c = {0.05f, 0.05f, 0.05f, 1};
        else if (i < e.local.size() && !e.local[i]) c = {1.0f, 0.3f, 0.2f, 1};
      }
      overlay.rect(x - dot / 2, y - dot / 2, dot, dot, c);
    }
    // the driven vehicle's view triangle (the camera's horizontal field of view, out to reach_m)
    Vec3 apex = vm.eye;
    double heading = dir_to_heading(Vec2(vm.forward.x(), vm.forward.y()));
    if (driven_ok) {
      apex = e.pos[static_cast<size_t>(v.driven)];
      heading = e.heading_deg[static_cast<size_t>(v.driven)];
    }
    const double half = rad2deg(std::atan(vm.tan_half_fov_y * vm.aspect));
    float ax, ay, lx, ly, rx, ry;
    to_map(apex, ax, ay);
    const Vec2 dl = heading_to_dir(heading - half), dr = heading_to_dir(heading + half);
    to_map(apex + Vec3(dl.x(), dl.y(), 0) * reach_m, lx, ly);
    to_map(apex + Vec3(dr.x(), dr.y(), 0) * reach_m, rx, ry);
    overlay.triangle(ax, ay, lx, ly, rx, ry, {1.0f, 1.0f, 1.0f, 0.22f});
    overlay.line(ax, ay, lx, ly, {1, 1, 1, 0.9f});
    overlay.line(ax, ay, rx, ry, {1, 1, 1, 0.9f});
    overlay.line(lx, ly, rx, ry, {1, 1, 1, 0.5f});
    if (driven_ok) {
      overlay.rect(ax - dot, ay - dot, 2 * dot, 2 * dot, {0, 0, 0, 1});
      overlay.rect(ax - dot + 1, ay - dot + 1, 2 * dot - 2, 2 * dot - 2, white);
    }
  }
  overlay.end();
}

}  // namespace npsnet::render
