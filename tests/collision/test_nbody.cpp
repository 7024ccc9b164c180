// More than two bodies: 3 and 5 vehicles touching in one tick are all detected in that tick,
// resolved together, momentum conserved, and the result does not depend on entity order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>

#include "collision/collision.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

namespace {

struct Body {
  std::string id;
  double x, y, heading, speed;
};

// `n` HMMWVs on a circle of radius rho0 r around (1000, 1000) (r: the model's true radius),
// heading for the centre, reaching rho1 r at the end of the tick.
std::vector<Body> converging(int n, double rho0, double rho1, double dt) {
  auto w = test::flat_world();
  const double r = w.models[w.kinds[w.kinds.find("hmmwv")].models[0]].true_radius;
  const double rho = rho0 * r, speed = (rho0 - rho1) * r / dt;
  std::vector<Body> b;
  for (int i = 0; i < n; ++i) {
    const double bearing = 360.0 * i / n;  // compass bearing of the body seen from the centre
    const Vec2 d = heading_to_dir(bearing);
    b.push_back({test::numbered("v", i), 1000 + rho * d.x(), 1000 + rho * d.y(), wrap360(bearing + 180), speed});
  }
  return b;
}

struct Outcome {
  size_t contacts = 0;
  std::map<std::string, Vec3> vel;  // by id
  std::map<std::string, Vec3> shift;
  std::map<std::string, Vec3> pos;  // at the end of the tick
  Vec3 momentum_before{0, 0, 0}, momentum_after{0, 0, 0};
};

Outcome run(const std::vector<Body>& bodies, const std::vector<int>& perm, double dt) {
  auto w = test::flat_world();
  for (int i : perm) {
    const Body& b = bodies[static_cast<size_t>(i)];
    const int e = test::add_vehicle(w, b.id, "hmmwv", b.x, b.y, b.heading, b.speed);
    w.ents.pos[e] += w.ents.vel[e] * dt;  // end of the tick
  }
  test::index_fixed(w);
  collision::Detector d(collision::Options{collision::Method::Continuous, collision::Tier::Auto, dt});
  std::vector<collision::Contact> c;
  d.detect(w, c);
  world::Changes ch;
  collision::respond(w, c, ch);
  Outcome o;
  o.contacts = c.size();
  const double m = w.kinds[w.kinds.find("hmmwv")].mass_kg;
  for (size_t e = 0; e < w.ents.size(); ++e) {
    o.momentum_before += m * w.ents.vel[e];
    o.vel[w.ents.id[e]] = w.ents.vel[e];
    o.pos[w.ents.id[e]] = w.ents.pos[e];
  }
  for (const auto& x : ch.entities) {
    EXPECT_TRUE(x.set_vel);
    o.vel[w.ents.id[static_cast<size_t>(x.entity)]] = x.vel;
    o.shift[w.ents.id[static_cast<size_t>(x.entity)]] = x.shift;
  }
  for (const auto& [id, v] : o.vel) o.momentum_after += m * v;
  for (const auto& r : ch.collisions) {
    EXPECT_EQ(r.result_a, world::Result::Bounce);
    EXPECT_EQ(r.result_b, world::Result::Bounce);
  }
  return o;
}

void check(int n, double rho0, double rho1, double dt, size_t expected_contacts) {
  const auto bodies = converging(n, rho0, rho1, dt);
  const double speed = bodies[0].speed;
  std::vector<int> perm(static_cast<size_t>(n));
  std::iota(perm.begin(), perm.end(), 0);
  const Outcome ref = run(bodies, perm, dt);
  EXPECT_EQ(ref.contacts, expected_contacts);
  // Momentum: equal and opposite impulses; the bodies start with zero total momentum.
  EXPECT_NEAR((ref.momentum_after - ref.momentum_before).norm(), 0.0, 1e-6 * ref.momentum_before.norm() + 1e-6);
  // Every body bounces back out of the ring (Figure 7: off each other, slower): a response
  // that stopped them all would keep zero momentum too, but none would move outward.
  ASSERT_EQ(ref.vel.size(), static_cast<size_t>(n));
  for (const auto& [id, v] : ref.vel) {
    EXPECT_LT(v.norm(), speed) << id << ": bounce diminishes speed";
    const Vec2 out = (ref.pos.at(id) - Vec3(1000, 1000, 0)).head<2>().normalized();
    EXPECT_GT(v.head<2>().dot(out), 0.05 * speed) << id << ": moves back out of the ring";
  }
  std::mt19937 rng(7);
  for (int trial = 0; trial < 10; ++trial) {
    std::shuffle(perm.begin(), perm.end(), rng);
    const Outcome o = run(bodies, perm, dt);
    EXPECT_EQ(o.contacts, ref.contacts);
    for (const auto& [id, v] : ref.vel) {
      EXPECT_EQ(o.vel.at(id), v) << id << " trial " << trial;  // bit for bit
      EXPECT_EQ(o.shift.at(id), ref.shift.at(id)) << id << " trial " << trial;
    }
  }
}

}  // namespace

TEST(NBody, ThreeVehiclesMeetingInOneTickAreResolvedTogether) {
  // 120 degrees apart: the angles between headings (120, 240) lie outside every Figure 8 band.
  // Pairs touch (true spheres) below rho = 1.15 r: all three in the tick from 3 r to 0.3 r.
  check(3, 3.0, 0.3, 0.1, 3);
}

TEST(NBody, FiveVehiclesMeetingInOneTickAreResolvedTogether) {
  // 72 degrees apart (angles 72, 144, 216, 288: outside every band); every pair meets in the tick.
  check(5, 3.0, 0.3, 0.1, 10);
}

TEST(NBody, ASecondSweepCatchesTheContactTheFirstImpulseCreates) {
  // Three in a row: a runs into b, which touches c at rest. After a's impulse, b approaches c;
  // solved together, c moves off too and nobody still approaches anybody.
  auto w = test::flat_world();
  const int k = w.kinds.find("hmmwv");
  const double r = w.kinds[k].radius_by_state[0];  // the sphere tier's (thesis) radius
  test::add_vehicle(w, "a", "hmmwv", 1000 - 2 * r + 0.5, 1000, 60, 10);  // heading 60: not head-on
  test::add_vehicle(w, "b", "hmmwv", 1000, 1000, 0, 0);
  test::add_vehicle(w, "c", "hmmwv", 1000 + 2 * r - 0.5, 1000, 130, 0);  // angles outside the bands
  test::index_fixed(w);
  collision::Detector d(collision::Options{collision::Method::Continuous, collision::Tier::Sphere, 0.1});
  std::vector<collision::Contact> c;
  d.detect(w, c);
  ASSERT_EQ(c.size(), 2u);
  world::Changes ch;
  collision::respond(w, c, ch);
  std::vector<Vec3> v(3);
  for (size_t e = 0; e < 3; ++e) v[e] = w.ents.vel[e];
  for (const auto& x : ch.entities) v[static_cast<size_t>(x.entity)] = x.vel;
  EXPECT_GT(v[2].x(), 0.0) << "c was pushed on";
  for (const auto& ct : c) {
    Vec3 n(ct.normal.x(), ct.normal.y(), 0);
    n.normalize();
    EXPECT_LE((v[static_cast<size_t>(ct.a)] - v[static_cast<size_t>(ct.b)]).dot(n), 1e-9);
  }
  const double m = w.kinds[k].mass_kg;
  Vec3 p0 = m * w.ents.vel[0], p1 = m * (v[0] + v[1] + v[2]);
  EXPECT_NEAR((p1 - p0).norm(), 0.0, 1e-6 * p0.norm());
}
