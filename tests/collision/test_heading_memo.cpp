// One heading memo for the tick (core/heading_memo.hpp): the detector reading the directions
// dynamics noted finds the same contacts, bit for bit, as a detector with its own memo, and the
// shared memo then holds every active entity's heading.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>

#include "collision/collision.hpp"
#include "dynamics/dynamics.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

namespace {
uint64_t bits(double x) { return std::bit_cast<uint64_t>(x); }
}  // namespace

TEST(HeadingMemo, TheDetectorSharingTheDynamicsMemoFindsTheSameContacts) {
  // 600 vehicles driving in a 1 km square of the default world (its trees, houses and towers):
  // they meet each other and the fixed objects. No response: they drive on through.
  const world::Scenario sc = test::default_with_crowd(600, 21, Vec2(20000, 30000), Vec2(21000, 31000));
  world::World a = world::build_world(sc), b = a;
  const auto opt = collision::options_from("continuous", "auto", 0.1);
  collision::Detector shared_det(opt), own_det(opt);
  core::HeadingMemo memo;
  shared_det.set_heading_memo(&memo);
  std::vector<dynamics::GroundImpact> ia, ib;
  std::vector<collision::Contact> ka, kb;
  size_t contacts = 0, fixed = 0;
  for (int t = 0; t < 150; ++t) {
    dynamics::step(a, 0.1, ia, nullptr, &memo);
    dynamics::step(b, 0.1, ib);
    // A heading changed after dynamics (as dynamics::drive turns a player's vehicle): the
    // detector meets it first and notes it in the shared memo.
    const int turned = t % 50;
    a.ents.heading_deg[turned] = b.ents.heading_deg[turned] = std::fmod(a.ents.heading_deg[turned] + 7.0f, 360.0f);
    ka.clear(), kb.clear();
    shared_det.detect(a, ka);
    own_det.detect(b, kb);
    ASSERT_EQ(memo.key(turned), (uint64_t{1} << 32) | std::bit_cast<uint32_t>(a.ents.heading_deg[turned])) << "tick " << t;
    ASSERT_EQ(ka.size(), kb.size()) << "tick " << t;
    for (size_t i = 0; i < ka.size(); ++i) {
      const auto &x = ka[i], &y = kb[i];
      ASSERT_TRUE(x.a == y.a && x.b == y.b && x.b_fixed == y.b_fixed) << "tick " << t << " contact " << i;
      ASSERT_EQ(bits(x.fraction), bits(y.fraction)) << "tick " << t << " contact " << i;
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(bits(x.point[c]), bits(y.point[c])) << "tick " << t << " contact " << i;
        ASSERT_EQ(bits(x.normal[c]), bits(y.normal[c])) << "tick " << t << " contact " << i;
      }
      ASSERT_STREQ(x.tier, y.tier);
      fixed += x.b_fixed;
    }
    contacts += ka.size();
  }
  EXPECT_GT(contacts, 20u) << "the crowd meets itself and the objects";
  EXPECT_GT(fixed, 0u);
  EXPECT_LT(fixed, contacts);
  // The memo now holds every active entity's stored heading and its direction, bit for bit.
  ASSERT_GE(memo.size(), a.ents.size());
  for (size_t e = 0; e < a.ents.size(); ++e) {
    if (!a.ents.active[e]) continue;
    ASSERT_EQ(memo.key(e), (uint64_t{1} << 32) | std::bit_cast<uint32_t>(a.ents.heading_deg[e])) << e;
    const Vec2 d = heading_to_dir(a.ents.heading_deg[e]);
    EXPECT_EQ(bits(memo.kept_dir(e).x()), bits(d.x())) << e;
    EXPECT_EQ(bits(memo.kept_dir(e).y()), bits(d.y())) << e;
  }
}
