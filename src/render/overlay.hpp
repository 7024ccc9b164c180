// 2D overlay drawn in GL after the 3D scene: rectangles, bitmap-font text (font.hpp), the terrain
// map inset (a texture coloured like the 3D terrain, with hill shading, patched when a crater
// changes the ground) and lines/triangles for the map's view triangle. Pixel coordinates,
// top-left origin. Frame protocol: begin(), any number of calls, end() draws it all.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "render/shader.hpp"
#include "world/terrain.hpp"

namespace npsnet::render {

struct Rgba {
  float r, g, b, a;
};

// Terrain colour (the 3D terrain's palette): height h (m), normal's up component, map range.
Vec3f terrain_color(double h, double up, double hmin, double hmax, double water_level);

class Overlay {
 public:
  Overlay(const std::filesystem::path& shader_dir, const world::Terrain& t, double water_level);
  ~Overlay();
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  void update_map(const world::Terrain& t, const world::PostRect& r);

  void begin(int width, int height);
  void rect(float x, float y, float w, float h, Rgba c);
  // Text at (x, y) = top-left of the first glyph; `scale` pixels per font pixel. Returns its width.
  float text(float x, float y, float scale, const std::string& s, Rgba c);
  void map(float x, float y, float w, float h);
  void line(float x0, float y0, float x1, float y1, Rgba c);
  void triangle(float x0, float y0, float x1, float y1, float x2, float y2, Rgba c);
  void end();

 private:
  struct Quad {
    float x, y, w, h, u0, v0, u1, v1, r, g, b, a, mode;
  };
  struct Vert {
    float x, y, r, g, b, a;
  };
  void map_texels(const world::Terrain& t, int x0, int y0, int x1, int y1);

  Program quad_prog_, line_prog_;
  unsigned font_tex_ = 0, map_tex_ = 0;
  unsigned quad_vao_ = 0, quad_vbo_ = 0, line_vao_ = 0, line_vbo_ = 0;
  size_t quad_cap_ = 0, line_cap_ = 0;
  std::vector<Quad> quads_;
  std::vector<Vert> tris_, lines_;
  std::vector<uint8_t> map_rgba_;
  int map_w_ = 1, map_h_ = 1;
  double hmin_ = 0, hmax_ = 1, water_ = -1e9;
  int width_ = 1, height_ = 1;
};

}  // namespace npsnet::render
