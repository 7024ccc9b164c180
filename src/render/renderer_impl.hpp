// The renderer's private parts (renderer.cpp, scene_draw.cpp): its GL objects and meshes
// (Renderer::Impl), the level-of-detail and look constants, and check_gl. Not for other rooms.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "render/effects.hpp"
#include "render/gl_context.hpp"
#include "render/model_meshes.hpp"
#include "render/overlay.hpp"
#include "render/renderer.hpp"
#include "render/shader.hpp"
#include "render/terrain_mesh.hpp"
#include "render/view.hpp"

namespace npsnet::render {
namespace impl {

inline constexpr int kTerrainChunkCells = 32;     // posts per chunk side - 1
inline constexpr int kBlockGridsquares = 4;       // fixed objects are culled in blocks of 4 x 4 gridsquares
inline constexpr double kTerrainLodK = 24.0;      // a chunk uses step s beyond s * spacing * this (m)
inline constexpr double kFullDetailRadii = 150.0; // full model within this many bounding radii (at 540 px)
inline constexpr double kSimpleRadii = 800.0;     // simplified model within this many radii; none beyond
inline constexpr double kEntityLodBoost = 3.0;    // vehicles keep detail farther than fixed objects
inline constexpr float kSkyHorizon[3] = {0.74f, 0.80f, 0.86f};
inline constexpr float kSkyZenith[3] = {0.33f, 0.53f, 0.82f};
inline constexpr int kMinOverlayW = 64, kMinOverlayH = 48;
inline constexpr double kWaterCellM = 200.0;      // water grid cell (haze is computed per vertex)
inline constexpr int kCraterSegments = 16;        // crater decal: segments around
inline constexpr float kGhostAlpha = 0.35f;       // opacity of a see-through vehicle (Camera::ghost_entity)

// Throws "render: <GL error> in <where>" when GL reports an error.
void check_gl(const char* where);

}  // namespace impl

struct Renderer::Impl {
  RenderOptions opt;
  const world::World* world = nullptr;
  std::unique_ptr<GlContext> ctx;
  unsigned fbo = 0, color_rb = 0, depth_rb = 0, empty_vao = 0;
  unsigned water_vao = 0, water_vbo = 0, particle_vao = 0, particle_vbo = 0;
  size_t particle_cap = 0;
  std::unique_ptr<Program> terrain_prog, object_prog, particle_prog, sky_prog;
  std::unique_ptr<TerrainMesh> terrain;
  std::unique_ptr<ModelMeshes> meshes;
  std::unique_ptr<Overlay> overlay;
  Effects effects;
  FrameStats stats;
  struct Crater {
    double t0;
    int first, count;  // vertices in crater_verts
  };
  std::vector<Crater> craters;
  std::vector<TerrainVertex> crater_verts;
  unsigned crater_vao = 0, crater_vbo = 0;
  bool have_water = false;
  int water_vertices = 0;
  float hmin = 0, hmax = 1;

  // fixed-object blocks over the world's grid: objects and bounds per block, radius per model
  int bcols = 0, brows = 0;
  std::vector<uint32_t> block_count;
  std::vector<Vec3> block_lo, block_hi;
  std::vector<float> model_radius;  // farthest vertex from the model origin, m
  std::vector<int> kind_max_lod_radius;

  void build_blocks();
  int model_for(int kind, int state) const;
  void draw_scene(const SceneView& v, const ViewMath& vm, const Camera& cam);
};

}  // namespace npsnet::render
