// Terrain mesh from the heightfield, in square chunks of `chunk_cells` cells. Each chunk holds its
// full-resolution posts (x, y, z world metres, unit normal, scorch 0..1) plus a skirt hanging from
// its edges that hides the cracks between chunks drawn at different levels of detail. A chunk is
// drawn with every step-th post (step 1, 2, 4, ...) by distance, and culled against the view
// frustum by its bounding box. A crater changes a PostRect: rebuild() recomputes only the posts
// in that rectangle (grown by one for the normals) and uploads only the changed rows.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "render/view.hpp"
#include "world/terrain.hpp"

namespace npsnet::render {

struct TerrainVertex {
  float x, y, z;
  float nx, ny, nz;
  float scorch;  // 0 = untouched, 1 = blackened (crater floor)
};
// Declares TerrainVertex's attributes (0 position, 1 normal, 2 scorch) on the bound VAO and
// ARRAY_BUFFER; shared by the terrain, water and crater meshes.
void terrain_vertex_layout();

struct TerrainDrawStats {
  int chunks_drawn = 0, chunks_culled = 0;
  int64_t triangles = 0;
};

class TerrainMesh {
 public:
  TerrainMesh(const world::Terrain& t, int chunk_cells);
  ~TerrainMesh();
  TerrainMesh(const TerrainMesh&) = delete;
  TerrainMesh& operator=(const TerrainMesh&) = delete;

  // Rebuild the posts of `r` (and their neighbours' normals); returns the vertices rewritten.
  int rebuild(const world::Terrain& t, const world::PostRect& r);
  // Draws visible chunks. `lod_k`: a chunk at distance d uses the largest step s (power of two,
  // <= chunk_cells) with d >= s * spacing * lod_k; lod_k <= 0 = always full resolution. Chunks
  // wholly farther than max_dist_m (where the haze has left nothing) are skipped.
  void draw(const ViewMath& v, double lod_k, double max_dist_m, TerrainDrawStats& stats) const;

  const std::vector<TerrainVertex>& vertices() const { return verts_; }
  std::vector<TerrainVertex> read_back() const;  // the GPU copy (tests)
  // Index of post (i, j)'s vertex in vertices().
  size_t vertex_of(int i, int j) const;
  int chunks_x() const { return cx_; }
  int chunks_y() const { return cy_; }
  float min_z() const { return zmin_; }
  float max_z() const { return zmax_; }
  int last_rebuilt_chunks() const { return last_chunks_; }

 private:
  struct Chunk {
    int i0, j0, nx, ny;   // first post, posts per side
    uint32_t base;        // first vertex
    float zmin, zmax, skirt;
  };
  struct IndexRange {
    size_t offset;  // bytes into the index buffer
    int count;
  };
  void fill_post(const world::Terrain& t, const Chunk& c, int i, int j, float scorch);
  void fill_skirts(const Chunk& c);
  void chunk_bounds(Chunk& c) const;
  const IndexRange& indices_for(int nx, int ny, int step) const;

  int cells_ = 32, cols_ = 0, rows_ = 0, cx_ = 0, cy_ = 0;
  double spacing_ = 1;
  float zmin_ = 0, zmax_ = 0;
  std::vector<Chunk> chunks_;
  std::vector<TerrainVertex> verts_;
  std::map<std::array<int, 3>, IndexRange> ranges_;
  unsigned vao_ = 0, vbo_ = 0, ibo_ = 0;
  int last_chunks_ = 0;
};

}  // namespace npsnet::render
