// Every model of the world's ModelLibrary on the GPU, drawn instanced. Faces (convex polygons,
// counter-clockwise from outside) are fanned into triangles with flat normals and their
// material's colour. Each model also gets a simplified form for distant instances: two stacked
// boxes (lower and upper half of the model's height) coloured with the area-weighted mean colour
// of the faces in that half.
#pragma once
#include <cstdint>
#include <vector>

#include "world/model.hpp"

namespace npsnet::render {

struct ModelVertex {
  float px, py, pz, nx, ny, nz, r, g, b;
};

struct Instance {  // matches object.vert
  float x, y, z, heading_rad;
  float pitch_rad, roll_rad, scale, pad;
};

struct ObjectDrawStats {
  int64_t instances_full = 0, instances_simple = 0, triangles = 0;
};

class ModelMeshes {
 public:
  explicit ModelMeshes(const world::ModelLibrary& lib);
  ~ModelMeshes();
  ModelMeshes(const ModelMeshes&) = delete;
  ModelMeshes& operator=(const ModelMeshes&) = delete;

  // Frame protocol: clear(), add() per visible instance, draw() once (needs the object program bound).
  void clear();
  void add(int model, bool simple, const Instance& inst);
  void draw(ObjectDrawStats& stats);

  int model_count() const { return static_cast<int>(ranges_.size() / 2); }
  int triangles(int model, bool simple) const { return ranges_[static_cast<size_t>(2 * model + simple)].count / 3; }

 private:
  struct Range {
    int first = 0, count = 0;
  };
  std::vector<Range> ranges_;                   // [2 * model + simple]
  std::vector<std::vector<Instance>> buckets_;  // same index
  std::vector<Instance> staging_;
  unsigned vao_ = 0, vbo_ = 0, inst_vbo_ = 0;
  size_t inst_capacity_ = 0;
};

}  // namespace npsnet::render
