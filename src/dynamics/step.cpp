#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <cmath>

#include "core/atan_float.hpp"
#include "core/prefetch.hpp"
#include "dynamics/drive.hpp"
#include "dynamics/dynamics.hpp"
#include "world/pose.hpp"

namespace npsnet::dynamics {
namespace {

using world::Mobility;

// Turn rates (deg/s) and waypoint capture radius: vehicle handling, not thesis constants.
double turn_rate_dps(Mobility m) {
  switch (m) {
    case Mobility::Ground: return 30.0;
    case Mobility::Ship: return 6.0;
    case Mobility::Air: return 15.0;
    default: return 0.0;
  }
}
constexpr double kWaypointCaptureM = 15.0;
constexpr double kAirMinClearanceM = 30.0;
// A driver holds the course while the waypoint lies within this angle of the heading (0.01 deg:
// 0.5 m off at the 3 km of a background leg, corrected as the waypoint nears): a vehicle on a
// straight leg then needs neither the atan2 of its bearing nor a new sin and cos (vehicle
// handling, not a thesis constant).
constexpr double kCourseHoldDeg = 0.01;
const double kCourseHoldTan = std::tan(kCourseHoldDeg * kPi / 180);

double turn_towards(double heading, double wanted, double max_step) {
  double d = wrap360(wanted - heading);
  if (d > 180) d -= 360;
  return wrap360(heading + std::clamp(d, -max_step, max_step));
}

// The direction of heading h: the memo's when h is a float's value (core/heading_memo.hpp: the
// same bits as its sin and cos, kept for the stages after), else its sin and cos.
Vec2 dir_of_float(double h, int e, core::HeadingMemo* memo) {
  const float f = static_cast<float>(h);
  if (memo && static_cast<double>(f) == h) return memo->dir(static_cast<size_t>(e), f);
  return heading_to_dir(h);
}

// Whether `to` lies within kCourseHoldDeg of the unit direction d (ahead of it).
bool on_course(const Vec2& d, const Vec2& to) {
  const double ahead = d.dot(to), off = d.x() * to.y() - d.y() * to.x();
  return ahead > 0 && std::abs(off) <= ahead * kCourseHoldTan;
}

// A ground vehicle moved by step_vehicle, its terrain following still to do (the direction of
// its stored heading).
struct ToFollow {
  int e;
  Vec2 dir;
};

// flatten: the terrain lookups (Terrain::height, is_water) inline here.
// The vehicle moves along its stored (float) heading, the one terrain following, collision and
// the network see. A ground vehicle's terrain following is left to the caller: returns true with
// `follow` set (it reads and writes only the vehicle's own pose: step() does it for a few
// vehicles together, after their moves).
[[gnu::flatten]] bool step_vehicle(world::World& w, int e, double dt, core::HeadingMemo* memo, ToFollow& follow) {
  auto& ents = w.ents;
  const world::Kind& k = w.kinds[ents.kind[e]];
  const bool dead = ents.state[e] + 1 >= static_cast<int>(k.states.size());
  if (dead) {
    ents.vel[e].setZero();
    return false;
  }
  // Steering: fleeing overrides the route; otherwise the current waypoint, if any.
  double heading = ents.heading_deg[e];
  Vec2 d = dir_of_float(heading, e, memo);  // the direction of `heading`
  double speed = std::min<double>(ents.cruise_mps[e], ents.max_mps[e]);
  if (k.fuel_l > 0 && ents.fuel_l[e] <= 0) speed = 0;  // an empty tank stops the vehicle
  auto& route = ents.route[e];
  if (ents.flee_until[e] > w.t) {
    speed = ents.max_mps[e];
  } else if (!route.empty() && ents.leg[e] < static_cast<int>(route.size())) {
    const Vec2 here(ents.pos[e].x(), ents.pos[e].y());
    Vec2 to = route[ents.leg[e]] - here;
    if (to.norm() < std::max(kWaypointCaptureM, speed * dt)) {
      ents.leg[e] += 1;
      if (ents.loop_route[e] && ents.leg[e] >= static_cast<int>(route.size())) ents.leg[e] = 0;
      if (ents.leg[e] < static_cast<int>(route.size())) to = route[ents.leg[e]] - here;
    }
    if (to.norm() > 1e-6 && !on_course(d, to)) {
      heading = static_cast<float>(turn_towards(heading, dir_to_heading(to), turn_rate_dps(k.mobility) * dt));
      d = dir_of_float(heading, e, memo);
    }
  }
  const double d_heading = heading;  // the heading d points along
  // (Made whole from its clamped parts: x and y stored one by one into a vector then read as a
  // pair stalled each vehicle on a store that could not be forwarded, 26 % of this function's samples.)
  const Vec3 moved = ents.pos[e] + Vec3(d.x(), d.y(), 0) * (speed * dt);
  Vec3 next(std::clamp(moved.x(), 0.0, w.terrain.width_m()), std::clamp(moved.y(), 0.0, w.terrain.depth_m()), moved.z());
  switch (k.mobility) {
    case Mobility::Ground:
      if (w.is_water(next.x(), next.y())) {  // shore: stop and turn away
        next = ents.pos[e];
        heading = static_cast<float>(wrap360(heading + 90));
      }
      break;
    case Mobility::Ship:
      if (!w.is_water(next.x(), next.y())) {
        next = ents.pos[e];
        heading = static_cast<float>(wrap360(heading + 90));
      }
      next.z() = w.water_level_m;
      break;
    case Mobility::Air:
      next.z() = std::max(ents.pos[e].z(), w.terrain.height(next.x(), next.y()) + kAirMinClearanceM);
      break;
    default: break;
  }
  ents.vel[e] = (next - ents.pos[e]) / dt;
  ents.pos[e] = next;
  ents.heading_deg[e] = static_cast<float>(heading);
  if (k.mobility == Mobility::Ship || k.mobility == Mobility::Air) ents.pitch_deg[e] = ents.roll_deg[e] = 0;
  burn_fuel(w, e, speed, dt);
  if (k.mobility != Mobility::Ground) return false;
  // Terrain following along the stored heading: d, unless the shore turned the vehicle away.
  follow = {e, heading == d_heading ? d : dir_of_float(heading, e, memo)};
  return true;
}

// March the segment from `a` to `b` along the heightfield in steps of half a post; bisect the
// first sample found below the ground. Returns true with the impact point.
bool march(const world::Terrain& t, const Vec3& a, const Vec3& b, Vec3& hit) {
  const double len = (b - a).head<2>().norm();
  const int n = std::max(1, static_cast<int>(std::ceil(len / (0.5 * t.spacing_m()))));
  auto below = [&](const Vec3& p) { return p.z() <= t.height(p.x(), p.y()); };
  Vec3 prev = a;
  if (below(a)) {
    hit = a;
    return true;
  }
  for (int i = 1; i <= n; ++i) {
    const Vec3 p = a + (b - a) * (static_cast<double>(i) / n);
    if (below(p)) {
      Vec3 lo = prev, hi = p;
      for (int it = 0; it < 30; ++it) {
        const Vec3 mid = 0.5 * (lo + hi);
        (below(mid) ? hi : lo) = mid;
      }
      hit = hi;
      hit.z() = t.height(hit.x(), hit.y());
      return true;
    }
    prev = p;
  }
  return false;
}

void step_munition(world::World& w, int e, double dt, std::vector<GroundImpact>& impacts) {
  auto& ents = w.ents;
  const world::Kind& k = w.kinds[ents.kind[e]];
  const Vec3 start = ents.pos[e];
  Vec3 vel = ents.vel[e];
  if (k.guided && ents.target[e] >= 0 && ents.active[ents.target[e]]) {
    // Guided: pure pursuit of the target's sphere centre; within this step's reach it meets it.
    const Vec3 aim = world::entity_centre(w, ents.target[e]);
    const Vec3 to = aim - start;
    const double speed = kmh2mps(k.max_speed_kmh);
    vel = to.normalized() * speed;
    if (to.norm() <= speed * dt) {
      ents.pos[e] = aim - to.normalized() * (0.25 * world::entity_radius(w, ents.target[e]));
      ents.vel[e] = vel;
      return;
    }
  }
  // Ballistic: exact for constant gravity at any dt (x += v dt - g dt^2 / 2, v -= g dt).
  const bool ballistic = !(k.guided && ents.target[e] >= 0);
  const Vec3 end = ballistic ? Vec3(start + vel * dt - Vec3(0, 0, 0.5 * kGravity * dt * dt)) : Vec3(start + vel * dt);
  if (ballistic) vel.z() -= kGravity * dt;
  ents.vel[e] = vel;
  ents.heading_deg[e] = static_cast<float>(dir_to_heading(vel.head<2>()));
  ents.pitch_deg[e] = static_cast<float>(rad2deg(std::atan2(vel.z(), vel.head<2>().norm())));
  Vec3 hit;
  if (march(w.terrain, start, end, hit) || !w.terrain.contains(end.x(), end.y())) {
    if (!w.terrain.contains(end.x(), end.y()) && !march(w.terrain, start, end, hit)) hit = end;
    ents.pos[e] = hit;
    ents.active[e] = 0;
    impacts.push_back({e, hit});
    return;
  }
  ents.pos[e] = end;
}

}  // namespace

// (defined here, beside step_vehicle, so that its flatten inlines it; drive.cpp calls it too)
bool burn_fuel(world::World& w, int e, double speed_mps, double dt) {
  const world::Kind& k = w.kinds[w.ents.kind[e]];
  if (k.fuel_l <= 0) return true;
  const double limit = std::max(1e-6, static_cast<double>(w.ents.max_mps[e]));
  const double litres = k.fuel_lph * std::min(1.0, speed_mps / limit) * dt / 3600.0;
  w.ents.fuel_l[e] = static_cast<float>(std::max(0.0, w.ents.fuel_l[e] - litres));
  return w.ents.fuel_l[e] > 0;
}

void follow_terrain(world::World& w, int e) { follow_terrain_along(w, e, heading_to_dir(w.ents.heading_deg[e])); }

namespace {
// A ground vehicle's terrain following in its parts, so that four vehicles' can go side by side
// (follow_terrain_four): its footprint's corners; from their heights, its height and the rise of
// its pitch and roll (over the footprint's length and width); those stored.
struct Footing {
  double half_len, half_wid;
  double x[4], y[4];  // front right, front left, back right, back left
};
struct Settle {
  double z;
  double rise[2];  // pitch (front up +, over 2 half_len), roll (right side down +, over 2 half_wid)
};
Footing footing(const world::World& w, int e, const Vec2& f) {
  const auto& ents = w.ents;
  const world::Kind& k = w.kinds[ents.kind[e]];
  const world::Model& m = w.models[k.models[0]];
  Footing ft;
  ft.half_len = std::max(0.5, 0.5 * static_cast<double>(m.bbox_max.y() - m.bbox_min.y()));
  ft.half_wid = std::max(0.5, 0.5 * static_cast<double>(m.bbox_max.x() - m.bbox_min.x()));
  const Vec2 r(f.y(), -f.x());  // right of forward
  const Vec2 c(ents.pos[e].x(), ents.pos[e].y());
  const Vec2 p[4] = {c + f * ft.half_len + r * ft.half_wid, c + f * ft.half_len - r * ft.half_wid,
                     c - f * ft.half_len + r * ft.half_wid, c - f * ft.half_len - r * ft.half_wid};
  for (int i = 0; i < 4; ++i) ft.x[i] = p[i].x(), ft.y[i] = p[i].y();
  return ft;
}
Settle settle(const double (&hts)[4]) {
  const double fr = hts[0], fl = hts[1], br = hts[2], bl = hts[3];
  const double hf = 0.5 * (fr + fl), hb = 0.5 * (br + bl), hr = 0.5 * (fr + br), hl = 0.5 * (fl + bl);
  return {0.25 * (hf + hb + hr + hl), {hf - hb, hl - hr}};
}
void seat(world::World& w, int e, double z, float pitch, float roll) {
  w.ents.pos[e].z() = z;
  w.ents.pitch_deg[e] = pitch, w.ents.roll_deg[e] = roll;
}
// Four vehicles' (all different) together, the same bits as one after the other: their heights'
// and slopes' chains of divisions and loads side by side (one vehicle's chain is too long for the
// core to overlap the next vehicle's with it: perf, 100,000 vehicles), the slopes two vehicles to
// a vector.
void follow_terrain_four(world::World& w, const ToFollow* v) {
  Footing ft[4];
  for (int i = 0; i < 4; ++i) ft[i] = footing(w, v[i].e, v[i].dir);
  double h[4][4];
  for (int i = 0; i < 4; ++i) w.terrain.heights4(ft[i].x, ft[i].y, h[i]);
  Settle st[4];
  for (int i = 0; i < 4; ++i) st[i] = settle(h[i]);
  float angle[2][4];
  for (int i = 0; i < 4; i += 2)
    atan2_deg_float4({st[i].rise[0], st[i].rise[1], st[i + 1].rise[0], st[i + 1].rise[1]},
                     {2 * ft[i].half_len, 2 * ft[i].half_wid, 2 * ft[i + 1].half_len, 2 * ft[i + 1].half_wid},
                     angle[i / 2]);
  for (int i = 0; i < 4; ++i) seat(w, v[i].e, st[i].z, angle[i / 2][2 * (i % 2)], angle[i / 2][2 * (i % 2) + 1]);
}
}  // namespace

void follow_terrain_along(world::World& w, int e, const Vec2& f) {
  // The four corners once each, in one Terrain::heights4 (the bits of four height() calls);
  // float(rad2deg(atan2(rise, run))), the same bits, mostly without libm (core/atan_float.hpp).
  const Footing ft = footing(w, e, f);
  double hts[4];
  w.terrain.heights4(ft.x, ft.y, hts);
  const Settle st = settle(hts);
  float pitch, roll;  // (both at once: the same bits as one by one)
  atan2_deg_float2(st.rise[0], 2 * ft.half_len, st.rise[1], 2 * ft.half_wid, pitch, roll);
  seat(w, e, st.z, pitch, roll);
}

void step(world::World& w, double dt, std::vector<GroundImpact>& impacts, core::Jobs* jobs, core::HeadingMemo* memo) {
  auto& ents = w.ents;
  const size_t n = ents.size();
  if (memo) memo->resize(n);
  // A player drives its vehicle (drive.hpp); munitions come second, below.
  auto moves = [&](size_t e) { return ents.active[e] && ents.local[e] && !ents.driven[e]; };
  // Each range also notes the span of its munitions, so that the munitions' pass (on this thread,
  // in index order) walks that span only, not every entity again.
  // (Only the ranges this call splits into are set and read: at 500 vehicles, 4 of the 512.)
  constexpr size_t kGrain = 128;  // vehicles per chunk below which one thread does it all
  constexpr int kChunksPerThread = 4;  // claimed as threads come free (core/jobs.hpp)
  const int ranges = jobs ? jobs->chunks(n, kGrain, kChunksPerThread) : 1;
  std::array<std::pair<size_t, size_t>, core::Jobs::kMaxChunks> span;
  std::fill_n(span.begin(), ranges, std::pair<size_t, size_t>{n, 0});
  // Vehicles are stored in no spatial order: each one's terrain posts (world/terrain.hpp) and its
  // current waypoint are asked of the cache kPrefetchAhead vehicles before it is stepped, so that
  // the misses overlap instead of stalling one by one (no effect on any result). At 100,000
  // vehicles the first terrain lookup of each took a third of the stage's time (perf).
  constexpr size_t kPrefetchAhead = 8;
  // A range's ground vehicles follow the terrain kFollowBatch at a time, after their moves: one
  // vehicle's heights, slopes and angles are a long chain of dependent divisions and loads, and
  // four vehicles' chains side by side overlap (follow_terrain_four; the same bits: each reads
  // only its own pose).
  constexpr int kFollowBatch = 8;
  auto vehicles = [&](int c, size_t e0, size_t e1) {
    ToFollow batch[kFollowBatch];
    int batched = 0;
    auto follow_batch = [&] {
      int b = 0;
      for (; b + 3 < batched; b += 4) follow_terrain_four(w, batch + b);
      for (; b < batched; ++b) follow_terrain_along(w, batch[b].e, batch[b].dir);
      batched = 0;
    };
    for (size_t e = e0; e < e1; ++e) {
      if (e + kPrefetchAhead < e1) {
        const size_t f = e + kPrefetchAhead;
        w.terrain.prefetch(ents.pos[f].x(), ents.pos[f].y());
        const auto& r = ents.route[f];
        if (static_cast<size_t>(ents.leg[f]) < r.size()) core::prefetch(r.data() + ents.leg[f]);
      }
      if (!moves(e)) continue;
      if (w.kinds[ents.kind[e]].mobility == Mobility::Munition) span[c] = {std::min(span[c].first, e), e + 1};
      else if (step_vehicle(w, static_cast<int>(e), dt, memo, batch[batched]) && ++batched == kFollowBatch)
        follow_batch();
    }
    follow_batch();
  };
  core::run_chunks(jobs, n, kGrain, vehicles, kChunksPerThread);  // in `ranges` ranges (Jobs::chunks)
  size_t m0 = n, m1 = 0;
  for (int c = 0; c < ranges; ++c) m0 = std::min(m0, span[c].first), m1 = std::max(m1, span[c].second);
  for (size_t e = m0; e < m1; ++e)
    if (moves(e) && w.kinds[ents.kind[e]].mobility == Mobility::Munition) step_munition(w, static_cast<int>(e), dt, impacts);
}

std::optional<world::Launch> fire(const world::World& w, int shooter, int munition_kind, const Vec3& target_point,
                                  int target) {
  const auto& ents = w.ents;
  const world::Kind& sk = w.kinds[ents.kind[shooter]];
  if (ents.state[shooter] + 1 >= static_cast<int>(sk.states.size()) || ents.rounds[shooter] <= 0) return std::nullopt;
  const world::Kind& mk = w.kinds[munition_kind];
  const Vec3 muzzle = ents.pos[shooter] + Vec3(0, 0, std::max(1.0, sk.height_m * 0.8));
  Vec3 to = target_point - muzzle;
  const double v0 = kmh2mps(mk.max_speed_kmh);
  const double horiz = to.head<2>().norm();
  Vec3 vel;
  if (mk.guided) {
    vel = to.normalized() * v0;
  } else {
    // Lowest ballistic arc: tan(theta) = (v^2 - sqrt(v^4 - g(g x^2 + 2 y v^2))) / (g x).
    const double g = kGravity, y = to.z();
    const double disc = v0 * v0 * v0 * v0 - g * (g * horiz * horiz + 2 * y * v0 * v0);
    const double theta = disc < 0 || horiz < 1e-6 ? kPi / 4 : std::atan((v0 * v0 - std::sqrt(disc)) / (g * horiz));
    const Vec2 d = horiz < 1e-6 ? heading_to_dir(ents.heading_deg[shooter]) : Vec2(to.head<2>() / horiz);
    vel = Vec3(d.x() * std::cos(theta), d.y() * std::cos(theta), std::sin(theta)) * v0;
  }
  world::Launch l;
  l.shooter = shooter, l.kind = munition_kind, l.target = target;
  l.muzzle = muzzle, l.vel = vel, l.aim = target_point;
  return l;
}

}  // namespace npsnet::dynamics
