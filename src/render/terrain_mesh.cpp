#include "render/terrain_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/gl_api.hpp"

namespace npsnet::render {
namespace {

constexpr double kScorchMaxSpacingM = 4.0;

// Sample positions 0, s, 2s, ... and always the last post.
void samples(int n, int step, std::vector<int>& out) {
  out.clear();
  for (int k = 0; k < n - 1; k += step) out.push_back(k);
  out.push_back(n - 1);
}

}  // namespace

TerrainMesh::TerrainMesh(const world::Terrain& t, int chunk_cells) {
  cols_ = t.cols();
  rows_ = t.rows();
  if (cols_ < 2 || rows_ < 2) throw std::runtime_error("render: terrain needs at least 2 x 2 posts");
  spacing_ = t.spacing_m();
  cells_ = std::max(1, std::min({chunk_cells, cols_ - 1, rows_ - 1}));
  cx_ = (cols_ - 1 + cells_ - 1) / cells_;
  cy_ = (rows_ - 1 + cells_ - 1) / cells_;
  uint32_t base = 0;
  for (int b = 0; b < cy_; ++b)
    for (int a = 0; a < cx_; ++a) {
      Chunk c{};
      c.i0 = a * cells_;
      c.j0 = b * cells_;
      c.nx = std::min(cells_, cols_ - 1 - c.i0) + 1;
      c.ny = std::min(cells_, rows_ - 1 - c.j0) + 1;
      c.base = base;
      base += static_cast<uint32_t>(c.nx * c.ny + 2 * c.nx + 2 * c.ny);
      chunks_.push_back(c);
    }
  verts_.resize(base);
  for (auto& c : chunks_) {
    for (int j = 0; j < c.ny; ++j)
      for (int i = 0; i < c.nx; ++i) fill_post(t, c, c.i0 + i, c.j0 + j, 0.0f);
    chunk_bounds(c);
    fill_skirts(c);
  }
  zmin_ = chunks_[0].zmin;
  zmax_ = chunks_[0].zmax;
  for (const auto& c : chunks_) {
    zmin_ = std::min(zmin_, c.zmin);
    zmax_ = std::max(zmax_, c.zmax);
  }

  // Index patterns, shared by every chunk of the same size and step.
  std::vector<uint32_t> idx;
  std::vector<int> sx, sy;
  for (const auto& c : chunks_)
    for (int step = 1; step <= cells_; step *= 2) {
      const std::array<int, 3> key{c.nx, c.ny, step};
      if (ranges_.count(key)) continue;
      const size_t first = idx.size();
      samples(c.nx, step, sx);
      samples(c.ny, step, sy);
      const auto g = [&](int i, int j) { return static_cast<uint32_t>(j * c.nx + i); };
      for (size_t b = 0; b + 1 < sy.size(); ++b)
        for (size_t a = 0; a + 1 < sx.size(); ++a) {
          const uint32_t v00 = g(sx[a], sy[b]), v10 = g(sx[a + 1], sy[b]);
          const uint32_t v01 = g(sx[a], sy[b + 1]), v11 = g(sx[a + 1], sy[b + 1]);
          idx.insert(idx.end(), {v00, v10, v11, v00, v11, v01});
        }
      // skirts: south (j = 0), north, west (i = 0), east
      const uint32_t sb = static_cast<uint32_t>(c.nx * c.ny);
      const uint32_t south = sb, north = sb + c.nx, west = sb + 2 * c.nx, east = west + c.ny;
      for (size_t a = 0; a + 1 < sx.size(); ++a) {
        const int i0 = sx[a], i1 = sx[a + 1];
        idx.insert(idx.end(), {g(i0, 0), south + i0, south + i1, g(i0, 0), south + i1, g(i1, 0)});
        idx.insert(idx.end(), {g(i1, c.ny - 1), north + i1, north + i0, g(i1, c.ny - 1), north + i0,
                               g(i0, c.ny - 1)});
      }
      for (size_t b = 0; b + 1 < sy.size(); ++b) {
        const int j0 = sy[b], j1 = sy[b + 1];
        idx.insert(idx.end(), {g(0, j1), west + j1, west + j0, g(0, j1), west + j0, g(0, j0)});
        idx.insert(idx.end(), {g(c.nx - 1, j0), east + j0, east + j1, g(c.nx - 1, j0), east + j1,
                               g(c.nx - 1, j1)});
      }
      ranges_[key] = {first * sizeof(uint32_t), static_cast<int>(idx.size() - first)};
    }

  gl::GenVertexArrays(1, &vao_);
  gl::BindVertexArray(vao_);
  gl::GenBuffers(1, &vbo_);
  gl::BindBuffer(GL_ARRAY_BUFFER, vbo_);
  gl::BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(verts_.size() * sizeof(TerrainVertex)), verts_.data(),
                 GL_DYNAMIC_DRAW);
  gl::GenBuffers(1, &ibo_);
  gl::BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
  gl::BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(idx.size() * sizeof(uint32_t)), idx.data(),
                 GL_STATIC_DRAW);
  terrain_vertex_layout();
  gl::BindVertexArray(0);
}

void terrain_vertex_layout() {
  const auto stride = static_cast<GLsizei>(sizeof(TerrainVertex));
  gl::EnableVertexAttribArray(0);
  gl::VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(0));
  gl::EnableVertexAttribArray(1);
  gl::VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(3 * sizeof(float)));
  gl::EnableVertexAttribArray(2);
  gl::VertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(6 * sizeof(float)));
}

TerrainMesh::~TerrainMesh() {
  if (!gl::DeleteBuffers) return;
  gl::DeleteBuffers(1, &vbo_);
  gl::DeleteBuffers(1, &ibo_);
  gl::DeleteVertexArrays(1, &vao_);
}

size_t TerrainMesh::vertex_of(int i, int j) const {
  const int a = std::min(i / cells_, cx_ - 1), b = std::min(j / cells_, cy_ - 1);
  const Chunk& c = chunks_[static_cast<size_t>(b * cx_ + a)];
  return c.base + static_cast<size_t>((j - c.j0) * c.nx + (i - c.i0));
}

void TerrainMesh::fill_post(const world::Terrain& t, const Chunk& c, int i, int j, float scorch) {
  const auto h = [&](int a, int b) {
    return static_cast<double>(t.post(std::clamp(a, 0, cols_ - 1), std::clamp(b, 0, rows_ - 1)));
  };
  const double dx = (h(i + 1, j) - h(i - 1, j)) / (2 * spacing_);
  const double dy = (h(i, j + 1) - h(i, j - 1)) / (2 * spacing_);
  Vec3 n(-dx, -dy, 1.0);
  n.normalize();
  TerrainVertex& v = verts_[c.base + static_cast<size_t>((j - c.j0) * c.nx + (i - c.i0))];
  v = {static_cast<float>(i * spacing_), static_cast<float>(j * spacing_), t.post(i, j),
       static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z()), scorch};
}

void TerrainMesh::chunk_bounds(Chunk& c) const {
  c.zmin = 1e30f;
  c.zmax = -1e30f;
  for (int k = 0; k < c.nx * c.ny; ++k) {
    c.zmin = std::min(c.zmin, verts_[c.base + k].z);
    c.zmax = std::max(c.zmax, verts_[c.base + k].z);
  }
  // deep enough to cover the largest height error of a coarser neighbour, never less than 1 m
  c.skirt = std::max(1.0f, 0.5f * (c.zmax - c.zmin) + static_cast<float>(0.05 * spacing_));
}

void TerrainMesh::fill_skirts(const Chunk& c) {
  const uint32_t sb = c.base + static_cast<uint32_t>(c.nx * c.ny);
  const auto drop = [&](uint32_t dst, int i, int j) {
    TerrainVertex v = verts_[c.base + static_cast<size_t>(j * c.nx + i)];
    v.z -= c.skirt;
    verts_[dst] = v;
  };
  for (int i = 0; i < c.nx; ++i) {
    drop(sb + i, i, 0);
    drop(sb + c.nx + i, i, c.ny - 1);
  }
  for (int j = 0; j < c.ny; ++j) {
    drop(sb + 2 * c.nx + j, 0, j);
    drop(sb + 2 * c.nx + c.ny + j, c.nx - 1, j);
  }
}

int TerrainMesh::rebuild(const world::Terrain& t, const world::PostRect& r) {
  last_chunks_ = 0;
  if (r.empty()) return 0;
  if (t.cols() != cols_ || t.rows() != rows_)
    throw std::runtime_error("render: terrain_changed: the terrain's size changed; build a new Renderer");
  // normals of the neighbours depend on the changed posts
  const int i0 = std::max(0, r.i0 - 1), i1 = std::min(cols_ - 1, r.i1 + 1);
  const int j0 = std::max(0, r.j0 - 1), j1 = std::min(rows_ - 1, r.j1 + 1);
  if (i0 > i1 || j0 > j1) return 0;
  int rewritten = 0;
  gl::BindBuffer(GL_ARRAY_BUFFER, vbo_);
  // posts on a chunk border belong to both chunks
  const int a0 = std::max(0, (i0 - 1) / cells_), a1 = std::min(cx_ - 1, i1 / cells_);
  const int b0 = std::max(0, (j0 - 1) / cells_), b1 = std::min(cy_ - 1, j1 / cells_);
  for (int b = b0; b <= b1; ++b)
    for (int a = a0; a <= a1; ++a) {
      Chunk& c = chunks_[static_cast<size_t>(b * cx_ + a)];
      const int ci0 = std::max(i0, c.i0), ci1 = std::min(i1, c.i0 + c.nx - 1);
      const int cj0 = std::max(j0, c.j0), cj1 = std::min(j1, c.j0 + c.ny - 1);
      if (ci0 > ci1 || cj0 > cj1) continue;
      ++last_chunks_;
      for (int j = cj0; j <= cj1; ++j)
        for (int i = ci0; i <= ci1; ++i) {
          const TerrainVertex& old = verts_[c.base + static_cast<size_t>((j - c.j0) * c.nx + (i - c.i0))];
          const float dz = old.z - t.post(i, j);  // > 0 where the ground went down
          // blacken lowered posts only where posts are close enough to draw a crater's shape;
          // on coarser terrain the renderer's crater decals show it (Renderer::add_crater)
          const float scorch = spacing_ <= kScorchMaxSpacingM
                                   ? std::clamp(old.scorch + std::max(0.0f, dz) * 0.6f, 0.0f, 1.0f)
                                   : old.scorch;
          fill_post(t, c, i, j, scorch);
          ++rewritten;
        }
      chunk_bounds(c);
      fill_skirts(c);
      zmin_ = std::min(zmin_, c.zmin);
      // upload the changed rows of the grid, then the chunk's skirts
      const size_t first = c.base + static_cast<size_t>((cj0 - c.j0) * c.nx);
      const size_t count = static_cast<size_t>((cj1 - cj0 + 1) * c.nx);
      gl::BufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(first * sizeof(TerrainVertex)),
                        static_cast<GLsizeiptr>(count * sizeof(TerrainVertex)), &verts_[first]);
      const size_t sfirst = c.base + static_cast<size_t>(c.nx * c.ny);
      const size_t scount = static_cast<size_t>(2 * c.nx + 2 * c.ny);
      gl::BufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(sfirst * sizeof(TerrainVertex)),
                        static_cast<GLsizeiptr>(scount * sizeof(TerrainVertex)), &verts_[sfirst]);
    }
  return rewritten;
}

const TerrainMesh::IndexRange& TerrainMesh::indices_for(int nx, int ny, int step) const {
  return ranges_.at({nx, ny, step});
}

void TerrainMesh::draw(const ViewMath& v, double lod_k, double max_dist_m, TerrainDrawStats& stats) const {
  gl::BindVertexArray(vao_);
  for (const auto& c : chunks_) {
    const Vec3 lo(c.i0 * spacing_, c.j0 * spacing_, c.zmin - c.skirt);
    const Vec3 hi((c.i0 + c.nx - 1) * spacing_, (c.j0 + c.ny - 1) * spacing_, c.zmax);
    if (!v.box_visible(lo, hi)) {
      ++stats.chunks_culled;
      continue;
    }
    const Vec3 near = v.eye.cwiseMax(lo).cwiseMin(hi);
    const double d = (near - v.eye).norm();
    if (d > max_dist_m) {
      ++stats.chunks_culled;
      continue;
    }
    int step = 1;
    if (lod_k > 0) {
      while (step * 2 <= cells_ && d >= step * 2 * spacing_ * lod_k) step *= 2;
    }
    const IndexRange& r = indices_for(c.nx, c.ny, step);
    gl::DrawElementsBaseVertex(GL_TRIANGLES, r.count, GL_UNSIGNED_INT, reinterpret_cast<void*>(r.offset),
                               static_cast<GLint>(c.base));
    ++stats.chunks_drawn;
    stats.triangles += r.count / 3;
  }
  gl::BindVertexArray(0);
}

std::vector<TerrainVertex> TerrainMesh::read_back() const {
  std::vector<TerrainVertex> out(verts_.size());
  gl::BindBuffer(GL_ARRAY_BUFFER, vbo_);
  gl::GetBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(out.size() * sizeof(TerrainVertex)), out.data());
  return out;
}

}  // namespace npsnet::render
