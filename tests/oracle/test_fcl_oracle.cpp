// FCL 0.7 as the oracle (issue 6): exact mesh-mesh collision and distance on the same triangles
// and poses as ours. Tests only: FCL is never the engine. Built by tests/CMakeLists.txt as
// test_oracle (npsnet_room_tests(oracle npsnet_collision fcl)).
#include <gtest/gtest.h>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <random>

#include "collision/collision.hpp"
#include "support/fcl_mesh.hpp"
#include "support/fixture.hpp"

using namespace npsnet;

namespace {

using Mesh = test::FclMesh;
using test::fcl_mesh;

fcl::Transform3d tf(const collision::Pose& p) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  t.linear() = p.rot;
  t.translation() = p.pos;
  return t;
}

struct Models {
  world::World w = test::flat_world();
  std::vector<collision::Shape> shapes;
  std::vector<std::shared_ptr<Mesh>> meshes;
  Models() {
    for (int i = 0; i < w.models.size(); ++i) {
      shapes.push_back(collision::make_shape(w.models[i]));
      meshes.push_back(fcl_mesh(shapes.back()));
    }
  }
};

double fcl_distance(const Models& m, int a, const collision::Pose& pa, int b, const collision::Pose& pb, Vec3* mid = nullptr) {
  fcl::CollisionObjectd oa(m.meshes[static_cast<size_t>(a)], tf(pa)), ob(m.meshes[static_cast<size_t>(b)], tf(pb));
  fcl::DistanceRequestd req(true);
  fcl::DistanceResultd res;
  fcl::distance(&oa, &ob, req, res);
  if (mid) *mid = 0.5 * (res.nearest_points[0] + res.nearest_points[1]);
  return res.min_distance;
}

}  // namespace

TEST(FclOracle, MeshOverlapAgreesWithFclCollide) {
  Models m;
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> pick(0, m.w.models.size() - 1);
  std::uniform_real_distribution<double> ang(0, 360), off(-1, 1);
  collision::ShapeScratch scratch;
  int both = 0, neither = 0, borderline = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int a = pick(rng), b = pick(rng);
    collision::Pose pa, pb;
    pa.rot = world::pose_rotation(ang(rng), ang(rng) / 8 - 22, ang(rng) / 8 - 22);
    pb.rot = world::pose_rotation(ang(rng), ang(rng) / 8 - 22, ang(rng) / 8 - 22);
    pb.pos = Vec3(off(rng), off(rng), off(rng) * 0.3) * (m.shapes[a].bound_radius + m.shapes[b].bound_radius);
    fcl::CollisionObjectd oa(m.meshes[a], tf(pa)), ob(m.meshes[b], tf(pb));
    fcl::CollisionRequestd req;
    fcl::CollisionResultd res;
    const bool fcl_hit = fcl::collide(&oa, &ob, req, res) > 0;
    const bool ours = collision::mesh_overlap(m.shapes[a], pa, m.shapes[b], pb, scratch);
    if (fcl_hit != ours) {
      // Only where the surfaces graze (FCL's distance within a micrometre) may the answers differ.
      const double d = fcl_distance(m, a, pa, b, pb);
      EXPECT_LT(std::abs(d), 1e-6) << "trial " << trial << " fcl " << fcl_hit << " ours " << ours;
      ++borderline;
    } else {
      (ours ? both : neither)++;
    }
  }
  EXPECT_GT(both, 200);
  EXPECT_GT(neither, 200);
  EXPECT_LT(borderline, 5);
}

TEST(FclOracle, ContinuousMeshTimeAndPointMatchFclAdvancement) {
  // Random encounters of two vehicles: our first-contact time (mesh tier) against FCL distance
  // advanced conservatively to 1 mm, and our point against FCL's nearest points there.
  Models m;
  auto& w = m.w;
  const char* kinds[] = {"m1a1", "bmp", "hmmwv", "f16", "ah64"};
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(0, 1);
  collision::Detector det(collision::Options{collision::Method::Continuous, collision::Tier::Mesh, 0.1});
  const int A = test::add_vehicle(w, "a", "m1a1", 0, 0, 0, 0), B = test::add_vehicle(w, "b", "m1a1", 0, 0, 0, 0);
  int compared = 0, agree_hit = 0, disagree = 0;
  for (int n = 0; n < 400; ++n) {
    const int ka = w.kinds.find(kinds[n % 5]), kb = w.kinds.find(kinds[(n / 5) % 5]);
    w.ents.kind[A] = static_cast<int16_t>(ka), w.ents.kind[B] = static_cast<int16_t>(kb);
    const double dt = 0.02 + u(rng) * 0.98, speed = 1 + u(rng) * 1999;
    for (int e : {A, B}) {
      w.ents.heading_deg[e] = static_cast<float>(u(rng) * 360);
      w.ents.pitch_deg[e] = static_cast<float>((u(rng) - 0.5) * 20);
      w.ents.roll_deg[e] = static_cast<float>((u(rng) - 0.5) * 20);
    }
    const collision::Shape& sa = m.shapes[static_cast<size_t>(w.kinds[ka].models[0])];
    const collision::Shape& sb = m.shapes[static_cast<size_t>(w.kinds[kb].models[0])];
    const double reach = sa.bound_radius + sb.bound_radius;
    const Vec3 dir = Vec3(u(rng) - 0.5, u(rng) - 0.5, 0.2 * (u(rng) - 0.5)).normalized();
    const Vec3 perp = Vec3(-dir.y(), dir.x(), 0).normalized();
    const double tc = 0.2 + 0.6 * u(rng);
    w.ents.vel[A] = dir * speed, w.ents.vel[B] = Vec3::Zero();
    const Mat3 ra = world::pose_rotation(w.ents.heading_deg[A], w.ents.pitch_deg[A], w.ents.roll_deg[A]);
    const Mat3 rb = world::pose_rotation(w.ents.heading_deg[B], w.ents.pitch_deg[B], w.ents.roll_deg[B]);
    const Vec3 cb(1000, 1000, 500), ca = cb + perp * (u(rng) * 0.8 * reach) + (1 - tc) * dt * w.ents.vel[A];
    w.ents.pos[A] = ca - ra * sa.sphere_centre;
    w.ents.pos[B] = cb - rb * sb.sphere_centre;
    det.set_dt(dt);
    collision::Contact k;
    const bool ours = det.test_pair(w, A, B, k);
    // FCL: advance from the start of the tick.
    auto poses = [&](double t, collision::Pose& pa, collision::Pose& pb) {
      pa.rot = ra, pa.pos = w.ents.pos[A] - w.ents.vel[A] * dt * (1 - t);
      pb.rot = rb, pb.pos = w.ents.pos[B];
    };
    double t = 0;
    bool fcl_hit = false;
    Vec3 mid;
    for (int it = 0; it < 400 && t <= 1; ++it) {
      collision::Pose pa, pb;
      poses(t, pa, pb);
      const double d = fcl_distance(m, w.kinds[ka].models[0], pa, w.kinds[kb].models[0], pb, &mid);
      if (d <= 1e-3) {
        fcl_hit = true;
        break;
      }
      t += (d - 5e-4) / (speed * dt);
    }
    if (fcl_hit && t == 0) continue;  // touching from the start: no first-contact time to compare
    ++compared;
    if (fcl_hit != ours) {
      ++disagree;
      continue;
    }
    if (!ours) continue;
    ++agree_hit;
    EXPECT_LT(std::abs(k.fraction - t) * speed * dt, 0.05) << "encounter " << n;
    EXPECT_LT((k.point - mid).norm(), 0.25) << "encounter " << n;
  }
  EXPECT_GT(agree_hit, 100);
  EXPECT_LE(disagree, compared / 100) << "more than 1% of the encounters disagree with FCL";
}

TEST(FclOracle, JetsAt2000MpsTouchAtOurTimeOfImpact) {
  Models m;
  auto& w = m.w;
  const double dt = 1.0, closing = 2000;
  // End-of-tick positions: they started 1 km apart, nose to nose, and crossed in the tick.
  const int a = test::add_vehicle(w, "a", "f16", 1500, 1000, 90, closing / 2);
  const int b = test::add_vehicle(w, "b", "f16", 500, 1000, 270, closing / 2);
  for (int e : {a, b}) w.ents.pos[e].z() = 1000;
  collision::Detector det(collision::Options{collision::Method::Continuous, collision::Tier::Auto, dt});
  collision::Contact k;
  ASSERT_TRUE(det.test_pair(w, a, b, k));
  const int mi = w.kinds[w.kinds.find("f16")].models[0];
  auto pose = [&](int e, double t) {
    collision::Pose p;
    p.rot = world::pose_rotation(w.ents.heading_deg[e], w.ents.pitch_deg[e], w.ents.roll_deg[e]);
    p.pos = w.ents.pos[e] - w.ents.vel[e] * dt * (1 - t);
    return p;
  };
  // At our time the meshes touch; 1 cm of closing earlier they are apart.
  EXPECT_LE(fcl_distance(m, mi, pose(a, k.fraction), mi, pose(b, k.fraction)), 1e-3);
  const double before = k.fraction - 0.01 / (closing * dt);
  EXPECT_GT(fcl_distance(m, mi, pose(a, before), mi, pose(b, before)), 0.0);
}
