// Stability where methods fail: grazing contact, bodies that start overlapping, zero relative
// velocity, coincident centres, degenerate polygons, huge and tiny dt, NaN and infinite input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "collision/collision.hpp"
#include "support/fixture.hpp"

using namespace npsnet;
using collision::sphere_sweep;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

TEST(Stability, GrazingContactTouchesOnceAndNearMissDoesNot) {
  // b passes a at exactly ra + rb = 3 m: one touching instant, at t = 0.5.
  const auto h = sphere_sweep(Vec3(0, 0, 0), Vec3(0, 0, 0), 1, Vec3(-10, 3, 0), Vec3(10, 3, 0), 2);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.fraction, 0.5, 1e-12);
  EXPECT_NEAR(h.exit_fraction, h.fraction, 1e-6);
  EXPECT_NEAR(h.normal.y(), 1.0, 1e-9);
  EXPECT_NEAR(h.point.y(), 1.0, 1e-9);
  EXPECT_FALSE(sphere_sweep(Vec3(0, 0, 0), Vec3(0, 0, 0), 1, Vec3(-10, 3 + 1e-6, 0), Vec3(10, 3 + 1e-6, 0), 2).hit);
}

TEST(Stability, BodiesThatStartOverlappingHitAtTimeZero) {
  const auto h = sphere_sweep(Vec3(0, 0, 0), Vec3(1, 0, 0), 1, Vec3(1.5, 0, 0), Vec3(10, 0, 0), 1);
  ASSERT_TRUE(h.hit);
  EXPECT_TRUE(h.started_inside);
  EXPECT_EQ(h.fraction, 0.0);
  EXPECT_GT(h.exit_fraction, 0.0);
  EXPECT_LE(h.exit_fraction, 1.0);
}

TEST(Stability, ZeroRelativeVelocity) {
  // Apart and moving together: never meet. Overlapping and moving together: inside all tick.
  EXPECT_FALSE(sphere_sweep(Vec3(0, 0, 0), Vec3(5, 0, 0), 1, Vec3(3, 0, 0), Vec3(8, 0, 0), 1).hit);
  const auto h = sphere_sweep(Vec3(0, 0, 0), Vec3(5, 0, 0), 1, Vec3(1, 0, 0), Vec3(6, 0, 0), 1);
  EXPECT_TRUE(h.hit && h.started_inside);
  EXPECT_EQ(h.exit_fraction, 1.0);
}

TEST(Stability, HitOnlySweepAnswersAsTheWholeSweep) {
  // Random pairs on a coarse lattice (many exact touches, coincident and resting spheres among
  // them): the hit-only sweep's hit, started_inside and fraction are the whole sweep's, bit for bit.
  std::mt19937 rng(13);
  std::uniform_int_distribution<int> q(-8, 8), rq(0, 6);
  auto p = [&] { return Vec3(q(rng) * 0.5, q(rng) * 0.5, q(rng) * 0.25); };
  int hits = 0, inside = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 a0 = p(), b0 = p();
    const Vec3 a1 = k % 3 ? p() : a0, b1 = k % 5 ? p() : b0;
    const double ra = rq(rng) * 0.5, rb = rq(rng) * 0.5;
    const auto whole = sphere_sweep(a0, a1, ra, b0, b1, rb), only = sphere_sweep(a0, a1, ra, b0, b1, rb, true);
    ASSERT_EQ(only.hit, whole.hit) << k;
    ASSERT_EQ(only.started_inside, whole.started_inside) << k;
    ASSERT_EQ(only.fraction, whole.fraction) << k;
    hits += whole.hit, inside += whole.started_inside;
  }
  EXPECT_GT(hits, 2000);
  EXPECT_GT(hits - inside, 500) << "meetings within the tick, not only overlaps at its start";
}

// The detector's sweep (sphere_sweep_checked: no check of each input) answers as sphere_sweep,
// bit for bit, on the lattice above and on arbitrary doubles, whole and hit-only; and it still
// rejects every NaN or infinite coordinate or radius, through the motion's terms.
TEST(Stability, TheCheckedSweepAnswersAsTheSweep) {
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> q(-8, 8), rq(0, 6);
  std::uniform_real_distribution<double> u(-20, 20), ur(0, 5);
  auto same = [](const collision::Trace& x, const collision::Trace& y) {
    return x.hit == y.hit && x.started_inside == y.started_inside && std::memcmp(&x.fraction, &y.fraction, 8) == 0 &&
           std::memcmp(&x.exit_fraction, &y.exit_fraction, 8) == 0 && std::memcmp(x.normal.data(), y.normal.data(), 24) == 0 &&
           std::memcmp(x.point.data(), y.point.data(), 24) == 0;
  };
  int hits = 0;
  for (int k = 0; k < 40000; ++k) {
    const bool lattice = k % 2;
    auto p = [&] { return lattice ? Vec3(q(rng) * 0.5, q(rng) * 0.5, q(rng) * 0.25) : Vec3(u(rng), u(rng), u(rng)); };
    const Vec3 a0 = p(), b0 = p();
    const Vec3 a1 = k % 3 ? p() : a0, b1 = k % 5 ? p() : b0;
    const double ra = lattice ? rq(rng) * 0.5 : ur(rng), rb = lattice ? rq(rng) * 0.5 : ur(rng);
    for (const bool only : {false, true}) {
      const auto want = sphere_sweep(a0, a1, ra, b0, b1, rb, only);
      ASSERT_TRUE(same(collision::sphere_sweep_checked(a0, a1, ra, b0, b1, rb, only), want)) << k << " " << only;
      hits += want.hit;
    }
  }
  EXPECT_GT(hits, 4000);
  for (const double bad : {double(NAN), kInf, -kInf}) {
    for (int at = 0; at < 14; ++at) {  // each coordinate of a0, a1, b0, b1, then ra, rb
      Vec3 v[4] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 0, 0), Vec3(2, 0, 0)};
      double r[2] = {1, 1};
      if (at < 12) v[at / 3][at % 3] = bad;
      else r[at - 12] = bad;
      EXPECT_THROW(collision::sphere_sweep_checked(v[0], v[1], r[0], v[2], v[3], r[1]), std::invalid_argument) << at << " " << bad;
    }
  }
}

TEST(Stability, CoincidentCentresGiveAUnitNormal) {
  const auto h = sphere_sweep(Vec3(1, 1, 1), Vec3(1, 1, 1), 1, Vec3(1, 1, 1), Vec3(1, 1, 1), 1);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.normal.norm(), 1.0, 1e-12);
  EXPECT_TRUE(finite(h.point));
  const auto g = sphere_sweep(Vec3(0, 0, 0), Vec3(0, 0, 0), 1, Vec3(0, 0, 0), Vec3(0, 4, 0), 1);
  EXPECT_NEAR(g.normal.y(), 1.0, 1e-12) << "along the relative motion";
  // The whole detector and response with two tanks at the same place.
  auto w = test::flat_world();
  test::add_vehicle(w, "a", "m1a1", 500, 500, 10, 0);
  test::add_vehicle(w, "b", "m1a1", 500, 500, 40, 0);
  test::index_fixed(w);
  collision::Detector d(collision::Options{});
  std::vector<collision::Contact> c;
  d.detect(w, c);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(finite(c[0].point));
  EXPECT_NEAR(c[0].normal.norm(), 1.0, 1e-9);
  world::Changes ch;
  collision::respond(w, c, ch);
  for (const auto& x : ch.entities) EXPECT_TRUE(finite(x.vel) && finite(x.shift));
}

TEST(Stability, DegeneratePolygonsAreDroppedNotPropagated) {
  world::Model m;
  m.vertices = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(2, 0, 0), Vec3f(0, 1, 0), Vec3f(0, 0, 1)};
  // A face of three collinear vertices, a face repeating a vertex, and one good triangle.
  m.face_vertices = {0, 1, 2, 0, 0, 3, 0, 1, 3};
  m.faces = {world::Face{0, 3, Vec3f(0, 0, 0)}, world::Face{3, 3, Vec3f(0, 0, 0)}, world::Face{6, 3, Vec3f(0, 0, 1)}};
  m.bbox_min = Vec3f(0, 0, 0), m.bbox_max = Vec3f(2, 1, 1), m.centre = Vec3f(1, 0.5, 0.5);
  const collision::Shape s = collision::make_shape(m);
  EXPECT_EQ(s.tris.size(), 1u);
  // Zero-area triangles in the tri-tri test: no crash, no false hit far away.
  const std::array<Vec3, 3> flat{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  const std::array<Vec3, 3> far{Vec3(0, 5, 0), Vec3(1, 5, 0), Vec3(0, 6, 0)};
  EXPECT_FALSE(collision::tri_tri_overlap(flat, far));
  // Haines' test on a zero-area polygon and a ray against the degenerate faces.
  const float u[3] = {0, 1, 2}, v[3] = {0, 0, 0};
  EXPECT_FALSE(collision::haines_inside(u, v, 3));
  const auto hit = collision::ray_model(m, Vec3(0.2, 0.2, 5), Vec3(0, 0, -1), 0, 10);
  EXPECT_TRUE(hit.hit);
  EXPECT_EQ(hit.face, 2);
  collision::Pose p;
  collision::ShapeScratch scratch;
  EXPECT_TRUE(collision::mesh_overlap(s, p, s, p, scratch));
  EXPECT_TRUE(collision::hull_overlap(s, p, s, p));
}

TEST(Stability, HugeAndTinyDt) {
  for (double dt : {1e-9, 1e-3, 10.0, 1e4}) {
    auto w = test::flat_world();
    // Ends 200 m apart after closing at 20 m/s: they met in the tick only when dt >= ~10 s.
    test::add_vehicle(w, "a", "m1a1", 1100, 1000, 90, 10);
    test::add_vehicle(w, "b", "m1a1", 900, 1000, 270, 10);
    test::index_fixed(w);
    collision::Detector d(collision::Options{collision::Method::Continuous, collision::Tier::Auto, dt});
    std::vector<collision::Contact> c;
    d.detect(w, c);
    if (dt >= 10) {
      ASSERT_EQ(c.size(), 1u) << dt;
      EXPECT_TRUE(c[0].fraction >= 0 && c[0].fraction <= 1);
      EXPECT_TRUE(finite(c[0].point));
    } else {
      EXPECT_TRUE(c.empty()) << dt;
    }
  }
}

TEST(Stability, NaNAndInfiniteInputIsRejectedWithAnError) {
  EXPECT_THROW(sphere_sweep(Vec3(NAN, 0, 0), Vec3(0, 0, 0), 1, Vec3(3, 0, 0), Vec3(3, 0, 0), 1), std::invalid_argument);
  EXPECT_THROW(sphere_sweep(Vec3(0, 0, 0), Vec3(kInf, 0, 0), 1, Vec3(3, 0, 0), Vec3(3, 0, 0), 1), std::invalid_argument);
  EXPECT_THROW(sphere_sweep(Vec3(0, 0, 0), Vec3(0, 0, 0), NAN, Vec3(3, 0, 0), Vec3(3, 0, 0), 1), std::invalid_argument);
  EXPECT_THROW(sphere_sweep(Vec3(0, 0, 0), Vec3(0, 0, 0), -1, Vec3(3, 0, 0), Vec3(3, 0, 0), 1), std::invalid_argument);
  EXPECT_THROW(sphere_sweep(Vec3(-1e300, 0, 0), Vec3(1e300, 0, 0), 1, Vec3(1e300, 0, 0), Vec3(-1e300, 0, 0), 1),
               std::invalid_argument);
  for (int field = 0; field < 3; ++field) {
    auto w = test::flat_world();
    const int a = test::add_vehicle(w, "bad", "m1a1", 500, 500, 0, 0);
    test::add_vehicle(w, "good", "m1a1", 600, 500, 0, 0);
    test::index_fixed(w);
    if (field == 0) w.ents.pos[a].x() = NAN;
    if (field == 1) w.ents.vel[a].y() = kInf;
    if (field == 2) w.ents.heading_deg[a] = NAN;
    collision::Detector d(collision::Options{});
    std::vector<collision::Contact> c;
    try {
      d.detect(w, c);
      ADD_FAILURE() << "no error for field " << field;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("'bad'"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(c.empty());
  }
}
