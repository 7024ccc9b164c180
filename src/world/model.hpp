// Model polygons, shared by collision L3 and the renderer. OBJ files (tinyobjloader) in metres,
// z up, +y forward (the heading direction), origin at the centre of the model's ground contact.
// Faces keep their vertex order and are not triangulated (Haines' test runs on the polygon);
// each face carries its material's diffuse colour (Kd from the .mtl, grey without one).
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/math.hpp"

namespace npsnet::world {

struct Face {
  uint32_t first = 0;  // into Model::face_vertices
  uint32_t count = 0;  // >= 3
  Vec3f normal{0, 0, 1};  // from the first three vertices (as the thesis computes the plane)
  Vec3f color{0.6f, 0.6f, 0.6f};
};

struct Model {
  std::string file;
  std::vector<Vec3f> vertices;
  std::vector<uint32_t> face_vertices;  // indices into vertices, face by face
  std::vector<Face> faces;
  Vec3f bbox_min{0, 0, 0}, bbox_max{0, 0, 0};
  Vec3f centre{0, 0, 0};   // bounding-box centre: the bounding sphere's centre in model space
  float true_radius = 0;   // farthest vertex from centre
};

// Throws InputError naming the file (and line for a bad face) on a missing or broken OBJ.
Model load_obj(const std::filesystem::path& file);
// The same from `text`, the contents of `file` (its folder holds the .mtl files it names).
Model load_obj_text(std::string_view text, const std::filesystem::path& file);

// All models, loaded once, referred to by index.
class ModelLibrary {
 public:
  // Loads `file` once; returns its index.
  int load(const std::filesystem::path& file);
  const Model& operator[](int i) const { return models_[static_cast<size_t>(i)]; }
  int size() const { return static_cast<int>(models_.size()); }

 private:
  std::vector<Model> models_;
  std::vector<std::string> paths_;
};

}  // namespace npsnet::world
