#include "render/model_meshes.hpp"

#include <algorithm>
#include <stdexcept>

#include "render/gl_api.hpp"

namespace npsnet::render {
namespace {

void push_tri(std::vector<ModelVertex>& out, const Vec3f& a, const Vec3f& b, const Vec3f& c, const Vec3f& col) {
  Vec3f n = (b - a).cross(c - a);
  const float len = n.norm();
  if (!(len > 1e-12f)) return;
  n /= len;
  for (const Vec3f* p : {&a, &b, &c})
    out.push_back({p->x(), p->y(), p->z(), n.x(), n.y(), n.z(), col.x(), col.y(), col.z()});
}

// Box [lo, hi] with outward counter-clockwise faces (no bottom: it stands on the ground).
void push_box(std::vector<ModelVertex>& out, const Vec3f& lo, const Vec3f& hi, const Vec3f& col) {
  const auto P = [&](int x, int y, int z) { return Vec3f(x ? hi.x() : lo.x(), y ? hi.y() : lo.y(), z ? hi.z() : lo.z()); };
  const auto quad = [&](const Vec3f& a, const Vec3f& b, const Vec3f& c, const Vec3f& d) {
    push_tri(out, a, b, c, col);
    push_tri(out, a, c, d, col);
  };
  quad(P(0, 0, 0), P(0, 0, 1), P(0, 1, 1), P(0, 1, 0));  // -x
  quad(P(1, 0, 0), P(1, 1, 0), P(1, 1, 1), P(1, 0, 1));  // +x
  quad(P(0, 0, 0), P(1, 0, 0), P(1, 0, 1), P(0, 0, 1));  // -y
  quad(P(0, 1, 0), P(0, 1, 1), P(1, 1, 1), P(1, 1, 0));  // +y
  quad(P(0, 0, 1), P(1, 0, 1), P(1, 1, 1), P(0, 1, 1));  // +z
}

void simplified(const world::Model& m, std::vector<ModelVertex>& out) {
  const float zlo = m.bbox_min.z(), zhi = m.bbox_max.z(), zmid = 0.5f * (zlo + zhi);
  for (int band = 0; band < 2; ++band) {
    Vec3f lo(1e30f, 1e30f, band ? zmid : zlo), hi(-1e30f, -1e30f, band ? zhi : zmid);
    Vec3f col(0, 0, 0);
    float area = 0;
    for (const auto& f : m.faces) {
      Vec3f c(0, 0, 0);
      for (uint32_t k = 0; k < f.count; ++k) c += m.vertices[m.face_vertices[f.first + k]];
      c /= static_cast<float>(f.count);
      if ((c.z() >= zmid) != (band == 1)) continue;
      float a = 0;
      const Vec3f& v0 = m.vertices[m.face_vertices[f.first]];
      for (uint32_t k = 1; k + 1 < f.count; ++k)
        a += 0.5f * (m.vertices[m.face_vertices[f.first + k]] - v0)
                        .cross(m.vertices[m.face_vertices[f.first + k + 1]] - v0)
                        .norm();
      col += f.color * a;
      area += a;
      for (uint32_t k = 0; k < f.count; ++k) {
        const Vec3f& v = m.vertices[m.face_vertices[f.first + k]];
        lo = lo.cwiseMin(Vec3f(v.x(), v.y(), lo.z()));
        hi = hi.cwiseMax(Vec3f(v.x(), v.y(), hi.z()));
      }
    }
    if (area <= 0 || !(hi.x() > lo.x()) || !(hi.y() > lo.y()) || !(hi.z() > lo.z())) continue;
    // shrink horizontally: a box's silhouette is larger than a rounded model's
    const Vec3f mid = 0.5f * (lo + hi);
    lo.x() = mid.x() + 0.8f * (lo.x() - mid.x());
    hi.x() = mid.x() + 0.8f * (hi.x() - mid.x());
    lo.y() = mid.y() + 0.8f * (lo.y() - mid.y());
    hi.y() = mid.y() + 0.8f * (hi.y() - mid.y());
    push_box(out, lo, hi, col / area);
  }
}

}  // namespace

ModelMeshes::ModelMeshes(const world::ModelLibrary& lib) {
  std::vector<ModelVertex> verts;
  for (int mi = 0; mi < lib.size(); ++mi) {
    const world::Model& m = lib[mi];
    Range full{static_cast<int>(verts.size()), 0};
    for (const auto& f : m.faces) {
      if (f.count < 3) continue;
      const Vec3f& a = m.vertices[m.face_vertices[f.first]];
      for (uint32_t k = 1; k + 1 < f.count; ++k)
        push_tri(verts, a, m.vertices[m.face_vertices[f.first + k]], m.vertices[m.face_vertices[f.first + k + 1]],
                 f.color);
    }
    full.count = static_cast<int>(verts.size()) - full.first;
    if (full.count == 0) throw std::runtime_error(m.file + ":0: model: no drawable faces");
    Range simple{static_cast<int>(verts.size()), 0};
    simplified(m, verts);
    simple.count = static_cast<int>(verts.size()) - simple.first;
    if (simple.count == 0) simple = full;
    ranges_.push_back(full);
    ranges_.push_back(simple);
  }
  buckets_.resize(ranges_.size());
  gl::GenVertexArrays(1, &vao_);
  gl::BindVertexArray(vao_);
  gl::GenBuffers(1, &vbo_);
  gl::BindBuffer(GL_ARRAY_BUFFER, vbo_);
  gl::BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(std::max<size_t>(1, verts.size()) * sizeof(ModelVertex)),
                 verts.data(), GL_STATIC_DRAW);
  const auto stride = static_cast<GLsizei>(sizeof(ModelVertex));
  for (int a = 0; a < 3; ++a) {
    gl::EnableVertexAttribArray(static_cast<GLuint>(a));
    gl::VertexAttribPointer(static_cast<GLuint>(a), 3, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<void*>(static_cast<size_t>(a) * 3 * sizeof(float)));
  }
  gl::GenBuffers(1, &inst_vbo_);
  gl::BindBuffer(GL_ARRAY_BUFFER, inst_vbo_);
  for (int a = 3; a < 5; ++a) {
    gl::EnableVertexAttribArray(static_cast<GLuint>(a));
    gl::VertexAttribDivisor(static_cast<GLuint>(a), 1);
  }
  gl::BindVertexArray(0);
}

ModelMeshes::~ModelMeshes() {
  if (!gl::DeleteBuffers) return;
  gl::DeleteBuffers(1, &vbo_);
  gl::DeleteBuffers(1, &inst_vbo_);
  gl::DeleteVertexArrays(1, &vao_);
}

void ModelMeshes::clear() {
  for (auto& b : buckets_) b.clear();
}

void ModelMeshes::add(int model, bool simple, const Instance& inst) {
  if (model < 0 || static_cast<size_t>(2 * model + 1) >= buckets_.size()) return;
  buckets_[static_cast<size_t>(2 * model + (simple ? 1 : 0))].push_back(inst);
}

void ModelMeshes::draw(ObjectDrawStats& stats) {
  staging_.clear();
  for (const auto& b : buckets_) staging_.insert(staging_.end(), b.begin(), b.end());
  if (staging_.empty()) return;
  gl::BindVertexArray(vao_);
  gl::stream_to_buffer(inst_vbo_, staging_.data(), staging_.size() * sizeof(Instance), inst_capacity_);
  size_t at = 0;
  const auto stride = static_cast<GLsizei>(sizeof(Instance));
  for (size_t k = 0; k < buckets_.size(); ++k) {
    const size_t n = buckets_[k].size();
    if (n == 0) continue;
    // point the instance attributes at this bucket's slice (works on GL 3.3: no base-instance)
    gl::VertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(at * sizeof(Instance)));
    gl::VertexAttribPointer(4, 4, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<void*>(at * sizeof(Instance) + 4 * sizeof(float)));
    const Range& r = ranges_[k];
    gl::DrawArraysInstanced(GL_TRIANGLES, r.first, r.count, static_cast<GLsizei>(n));
    (k % 2 ? stats.instances_simple : stats.instances_full) += static_cast<int64_t>(n);
    stats.triangles += static_cast<int64_t>(n) * (r.count / 3);
    at += n;
  }
  gl::BindVertexArray(0);
}

}  // namespace npsnet::render
