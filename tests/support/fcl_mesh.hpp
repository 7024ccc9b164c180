// FCL (the oracle of tests/oracle and bench/bench_accuracy) built from our collision shapes:
// the same triangles, so FCL and we answer about the same geometry. Tests and benchmarks only.
#pragma once
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>

#include <memory>
#include <vector>

#include "collision/collision.hpp"

namespace npsnet::test {

using FclMesh = fcl::BVHModel<fcl::OBBRSSd>;

inline std::shared_ptr<FclMesh> fcl_mesh(const collision::Shape& s) {
  auto m = std::make_shared<FclMesh>();
  std::vector<fcl::Vector3d> pts;
  std::vector<fcl::Triangle> tris;
  for (const auto& t : s.tris) {
    const size_t b = pts.size();
    for (const Vec3& v : t) pts.emplace_back(v.x(), v.y(), v.z());
    tris.emplace_back(b, b + 1, b + 2);
  }
  m->beginModel();
  m->addSubModel(pts, tris);
  m->endModel();
  return m;
}

}  // namespace npsnet::test
