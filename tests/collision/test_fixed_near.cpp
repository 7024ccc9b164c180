// The fixed objects near each vehicle, kept from tick to tick (Detector::near_, collision.hpp):
// a detector that keeps them finds the same contacts, episodes and tests tick after tick as one
// whose world's grid is built again before every tick (nothing kept), for vehicles of every speed
// crossing a dense wood, a village and open ground.
#include <gtest/gtest.h>

#include <random>

#include "collision/collision.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

namespace {

struct Tick {
  std::vector<std::tuple<int, int, bool, double, std::string>> contacts;  // a, b, fixed, fraction, tier
  int64_t fixed_tests = 0;
  bool operator==(const Tick&) const = default;
};

world::World wood_and_traffic(uint64_t seed) {
  auto w = test::flat_world();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  // A wood: a tree about every 6 m over 300 m x 300 m; a village of buildings; rocks.
  for (int j = 0; j < 50; ++j)
    for (int i = 0; i < 50; ++i)
      test::add_fixed(w, test::numbered("t", j * 50 + i), "tree", 400 + 6 * i + 3 * u(rng), 400 + 6 * j + 3 * u(rng));
  for (int i = 0; i < 30; ++i)
    test::add_fixed(w, test::numbered("b", i), i % 5 ? "building" : "rock", 900 + 40 * (i % 6) + 10 * u(rng),
                    900 + 40 * (i / 6) + 10 * u(rng));
  // Traffic through them: slow and fast, straight and turning, some from outside the map.
  for (int v = 0; v < 80; ++v) {
    const double speed = v % 10 == 0 ? 120 + 200 * u(rng) : 2 + 25 * u(rng);
    const int e = test::add_vehicle(w, test::numbered("v", v), v % 7 ? "m1a1" : "hmmwv", 350 + 800 * u(rng),
                                    350 + 800 * u(rng), 360 * u(rng), speed);
    if (v == 79) w.ents.pos[e].x() = -30;  // off the map's west edge
  }
  test::index_fixed(w);
  return w;
}

std::vector<Tick> run(bool keep, int ticks, double dt) {
  world::World w = wood_and_traffic(21);
  collision::Detector d(collision::Options{collision::Method::Continuous, collision::Tier::Auto, dt});
  std::vector<Tick> out;
  for (int t = 0; t < ticks; ++t) {
    for (size_t e = 0; e < w.ents.size(); ++e) {
      w.ents.pos[e] += w.ents.vel[e] * dt;
      if (e % 3 == 0) {  // every third turns: heading and velocity together
        w.ents.heading_deg[e] = static_cast<float>(wrap360(w.ents.heading_deg[e] + 40 * dt));
        const Vec2 h = heading_to_dir(w.ents.heading_deg[e]);
        w.ents.vel[e] = Vec3(h.x(), h.y(), 0) * w.ents.vel[e].norm();
      }
    }
    if (!keep) test::index_fixed(w);  // a new grid: nothing near is kept
    std::vector<collision::Contact> c;
    const int64_t before = d.stats().fixed_tests;
    d.detect(w, c);
    Tick k;
    for (const auto& x : c) k.contacts.emplace_back(x.a, x.b, x.b_fixed, x.fraction, std::string(x.tier));
    k.fixed_tests = d.stats().fixed_tests - before;
    out.push_back(std::move(k));
  }
  return out;
}

}  // namespace

TEST(FixedNear, KeptObjectsGiveTheSameContactsAsAskingTheGridEveryTick) {
  const double dt = 1.0 / 60;
  const auto kept = run(true, 240, dt), fresh = run(false, 240, dt);
  ASSERT_EQ(kept.size(), fresh.size());
  size_t fixed_contacts = 0;
  int64_t tests = 0;
  for (size_t t = 0; t < kept.size(); ++t) {
    EXPECT_EQ(kept[t], fresh[t]) << "tick " << t;
    for (const auto& c : kept[t].contacts) fixed_contacts += std::get<2>(c);
    tests += kept[t].fixed_tests;
  }
  // The scene has work for the cache: many objects tested, contacts with them found.
  EXPECT_GT(tests, 10000);
  EXPECT_GT(fixed_contacts, 50u);
}
