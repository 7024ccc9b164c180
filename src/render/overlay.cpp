#include "render/overlay.hpp"

#include <algorithm>
#include <cmath>

#include "render/font.hpp"
#include "render/gl_api.hpp"

namespace npsnet::render {
namespace {

constexpr int kMapMaxTexels = 512;

double smooth(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}
Vec3f mix(const Vec3f& a, const Vec3f& b, double t) { return a + (b - a) * static_cast<float>(t); }

}  // namespace

Vec3f terrain_color(double h, double up, double hmin, double hmax, double water_level) {
  // keep in step with shaders/terrain.frag
  const double span = std::max(hmax - hmin, 1.0);
  const double t = std::clamp((h - hmin) / span, 0.0, 1.0);
  Vec3f c = mix(Vec3f(0.40f, 0.50f, 0.24f), Vec3f(0.55f, 0.53f, 0.33f), smooth(0.15, 0.45, t));
  c = mix(c, Vec3f(0.52f, 0.45f, 0.36f), smooth(0.5, 0.8, t));
  c = mix(c, Vec3f(0.80f, 0.79f, 0.77f), smooth(0.88, 0.97, t));
  c = mix(Vec3f(0.46f, 0.43f, 0.40f), c, smooth(0.72, 0.88, up));
  c = mix(Vec3f(0.76f, 0.70f, 0.52f), c, smooth(0.5, 3.0, h - water_level));
  return c;
}

Overlay::Overlay(const std::filesystem::path& shader_dir, const world::Terrain& t, double water_level)
    : quad_prog_(shader_dir, "overlay"), line_prog_(shader_dir, "lines2d") {
  water_ = water_level;
  hmin_ = 1e30;
  hmax_ = -1e30;
  for (float h : t.posts()) {
    hmin_ = std::min<double>(hmin_, h);
    hmax_ = std::max<double>(hmax_, h);
  }
  // font atlas
  const auto atlas = font::atlas();
  gl::GenTextures(1, &font_tex_);
  gl::BindTexture(GL_TEXTURE_2D, font_tex_);
  gl::PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl::TexImage2D(GL_TEXTURE_2D, 0, GL_R8, font::kAtlasW, font::kAtlasH, 0, GL_RED, GL_UNSIGNED_BYTE, atlas.data());
  gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  // map: row 0 = north edge (top of the inset)
  map_w_ = std::min(kMapMaxTexels, std::max(2, t.cols()));
  map_h_ = std::min(kMapMaxTexels, std::max(2, t.rows()));
  map_rgba_.assign(static_cast<size_t>(map_w_ * map_h_ * 4), 255);
  map_texels(t, 0, 0, map_w_ - 1, map_h_ - 1);
  gl::GenTextures(1, &map_tex_);
  gl::BindTexture(GL_TEXTURE_2D, map_tex_);
  gl::PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl::TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, map_w_, map_h_, 0, GL_RGBA, GL_UNSIGNED_BYTE, map_rgba_.data());
  gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

  gl::GenVertexArrays(1, &quad_vao_);
  gl::BindVertexArray(quad_vao_);
  gl::GenBuffers(1, &quad_vbo_);
  gl::BindBuffer(GL_ARRAY_BUFFER, quad_vbo_);
  const auto qs = static_cast<GLsizei>(sizeof(Quad));
  const int sizes[4] = {4, 4, 4, 1};
  for (int a = 0; a < 4; ++a) {
    gl::EnableVertexAttribArray(static_cast<GLuint>(a));
    gl::VertexAttribPointer(static_cast<GLuint>(a), sizes[a], GL_FLOAT, GL_FALSE, qs,
                            reinterpret_cast<void*>(static_cast<size_t>(a) * 4 * sizeof(float)));
    gl::VertexAttribDivisor(static_cast<GLuint>(a), 1);
  }
  gl::GenVertexArrays(1, &line_vao_);
  gl::BindVertexArray(line_vao_);
  gl::GenBuffers(1, &line_vbo_);
  gl::BindBuffer(GL_ARRAY_BUFFER, line_vbo_);
  const auto ls = static_cast<GLsizei>(sizeof(Vert));
  gl::EnableVertexAttribArray(0);
  gl::VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, ls, reinterpret_cast<void*>(0));
  gl::EnableVertexAttribArray(1);
  gl::VertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, ls, reinterpret_cast<void*>(2 * sizeof(float)));
  gl::BindVertexArray(0);
}

Overlay::~Overlay() {
  if (!gl::DeleteBuffers) return;
  gl::DeleteTextures(1, &font_tex_);
  gl::DeleteTextures(1, &map_tex_);
  gl::DeleteBuffers(1, &quad_vbo_);
  gl::DeleteBuffers(1, &line_vbo_);
  gl::DeleteVertexArrays(1, &quad_vao_);
  gl::DeleteVertexArrays(1, &line_vao_);
}

void Overlay::map_texels(const world::Terrain& t, int x0, int y0, int x1, int y1) {
  const double W = t.width_m(), D = t.depth_m();
  const Vec3 sun = Vec3(0.5, -0.5, 0.7).normalized();
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double wx = (x + 0.5) / map_w_ * W, wy = (1.0 - (y + 0.5) / map_h_) * D;
      const double h = t.height(wx, wy);
      const Vec3 n = t.normal(wx, wy);
      Vec3f c;
      if (h < water_) {
        c = Vec3f(0.16f, 0.32f, 0.50f);
      } else {
        // hill shading exaggerated so a 50 km map still shows its relief
        Vec3 ne(n.x() * 4, n.y() * 4, n.z());
        ne.normalize();
        const double shade = 0.55 + 0.6 * std::max(0.0, ne.dot(sun));
        c = terrain_color(h, n.z(), hmin_, hmax_, water_) * static_cast<float>(shade);
      }
      uint8_t* p = &map_rgba_[static_cast<size_t>((y * map_w_ + x) * 4)];
      for (int k = 0; k < 3; ++k) p[k] = static_cast<uint8_t>(std::clamp(c[k] * 255.0f, 0.0f, 255.0f));
      p[3] = 255;
    }
}

void Overlay::update_map(const world::Terrain& t, const world::PostRect& r) {
  if (r.empty()) return;
  const double W = t.width_m(), D = t.depth_m(), s = t.spacing_m();
  const auto tx = [&](double wx) { return std::clamp(static_cast<int>(wx / W * map_w_), 0, map_w_ - 1); };
  const auto ty = [&](double wy) { return std::clamp(static_cast<int>((1.0 - wy / D) * map_h_), 0, map_h_ - 1); };
  const int x0 = tx((r.i0 - 1) * s), x1 = tx((r.i1 + 1) * s);
  const int y0 = ty((r.j1 + 1) * s), y1 = ty((r.j0 - 1) * s);
  map_texels(t, x0, y0, x1, y1);
  gl::BindTexture(GL_TEXTURE_2D, map_tex_);
  gl::PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl::PixelStorei(GL_UNPACK_ROW_LENGTH, map_w_);
  gl::TexSubImage2D(GL_TEXTURE_2D, 0, x0, y0, x1 - x0 + 1, y1 - y0 + 1, GL_RGBA, GL_UNSIGNED_BYTE,
                    &map_rgba_[static_cast<size_t>((y0 * map_w_ + x0) * 4)]);
  gl::PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

void Overlay::begin(int width, int height) {
  width_ = width;
  height_ = height;
  quads_.clear();
  tris_.clear();
  lines_.clear();
}

void Overlay::rect(float x, float y, float w, float h, Rgba c) {
  quads_.push_back({x, y, w, h, 0, 0, 0, 0, c.r, c.g, c.b, c.a, 0});
}

float Overlay::text(float x, float y, float scale, const std::string& s, Rgba c) {
  float cx = x;
  for (char ch : s) {
    auto code = static_cast<unsigned char>(ch);
    if (code < 32 || code > 127) code = 127;
    const int cell = code - 32;
    const float u0 = static_cast<float>((cell % font::kAtlasCols) * font::kCellW) / font::kAtlasW;
    const float v0 = static_cast<float>((cell / font::kAtlasCols) * font::kCellH) / font::kAtlasH;
    const float u1 = u0 + static_cast<float>(font::kGlyphW) / font::kAtlasW;
    const float v1 = v0 + static_cast<float>(font::kGlyphH) / font::kAtlasH;
    if (code != ' ')
      quads_.push_back({cx, y, font::kGlyphW * scale, font::kGlyphH * scale, u0, v0, u1, v1, c.r, c.g, c.b, c.a, 1});
    cx += font::kCellW * scale;
  }
  return cx - x;
}

void Overlay::map(float x, float y, float w, float h) {
  quads_.push_back({x, y, w, h, 0, 0, 1, 1, 1, 1, 1, 1, 2});
}

void Overlay::line(float x0, float y0, float x1, float y1, Rgba c) {
  lines_.push_back({x0, y0, c.r, c.g, c.b, c.a});
  lines_.push_back({x1, y1, c.r, c.g, c.b, c.a});
}

void Overlay::triangle(float x0, float y0, float x1, float y1, float x2, float y2, Rgba c) {
  for (const auto& [x, y] : {std::pair{x0, y0}, std::pair{x1, y1}, std::pair{x2, y2}})
    tris_.push_back({x, y, c.r, c.g, c.b, c.a});
}

void Overlay::end() {
  gl::Disable(GL_DEPTH_TEST);
  gl::Disable(GL_CULL_FACE);
  gl::Enable(GL_BLEND);
  gl::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const auto upload = [](unsigned vbo, size_t& cap, const void* data, size_t bytes) {
    gl::stream_to_buffer(vbo, data, bytes, cap);
  };
  // quads in submission order (panels, map, text), then triangles and lines on top of the map
  if (!quads_.empty()) {
    quad_prog_.use();
    gl::Uniform2f(quad_prog_.loc("u_screen"), static_cast<float>(width_), static_cast<float>(height_));
    gl::Uniform1i(quad_prog_.loc("u_font"), 0);
    gl::Uniform1i(quad_prog_.loc("u_map"), 1);
    gl::ActiveTexture(GL_TEXTURE0);
    gl::BindTexture(GL_TEXTURE_2D, font_tex_);
    gl::ActiveTexture(GL_TEXTURE1);
    gl::BindTexture(GL_TEXTURE_2D, map_tex_);
    gl::ActiveTexture(GL_TEXTURE0);
    gl::BindVertexArray(quad_vao_);
    upload(quad_vbo_, quad_cap_, quads_.data(), quads_.size() * sizeof(Quad));
    gl::DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(quads_.size()));
  }
  if (!tris_.empty() || !lines_.empty()) {
    line_prog_.use();
    gl::Uniform2f(line_prog_.loc("u_screen"), static_cast<float>(width_), static_cast<float>(height_));
    gl::BindVertexArray(line_vao_);
    std::vector<Vert>& all = tris_;
    const size_t ntri = tris_.size();
    all.insert(all.end(), lines_.begin(), lines_.end());
    upload(line_vbo_, line_cap_, all.data(), all.size() * sizeof(Vert));
    if (ntri) gl::DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(ntri));
    if (!lines_.empty()) gl::DrawArrays(GL_LINES, static_cast<GLint>(ntri), static_cast<GLsizei>(lines_.size()));
  }
  gl::BindVertexArray(0);
  gl::Disable(GL_BLEND);
  gl::Enable(GL_DEPTH_TEST);
}

}  // namespace npsnet::render
