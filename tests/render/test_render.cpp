// Renderer tests, headless (OSMesa; no display needed). A small flat world with the bundled kinds
// and models, fixed cameras, and checks on the pixels that come back.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#define STB_IMAGE_IMPLEMENTATION  // the decoder, for this test only
#include <stb/stb_image.h>

#include <cstdlib>
#include <functional>
#include <fstream>
#include <string>

#include "support/dirs.hpp"
#include "render/font.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "render/shader.hpp"
#include "render/terrain_mesh.hpp"
#include "render/view.hpp"
#include "support/scratch.hpp"
#include "world/error.hpp"

using namespace npsnet;
namespace fs = std::filesystem;

namespace {

const fs::path kSrc = npsnet::dirs::source();

// Flat ground at 50 m, 129 x 129 posts 2 m apart (256 m square), the bundled kinds and models;
// post(i, j), when given, sets each post's height instead (the terrain is built from them).
world::World flat_world(float height = 50.0f, const std::function<float(int, int)>& post = {}) {
  world::World w;
  const int n = 129;
  std::vector<float> h(static_cast<size_t>(n * n), height);
  if (post)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) h[static_cast<size_t>(j * n + i)] = post(i, j);
  w.terrain = world::Terrain(n, n, 2.0, std::move(h), geo::Geodetic{35.98, -121.25, 0.0});
  w.kinds = world::KindTable::load(kSrc / "models/kinds.toml", w.models);
  return w;
}

render::RenderOptions options(int w, int h) {
  render::RenderOptions o;
  o.width = w;
  o.height = h;
  o.shader_dir = kSrc / "shaders";
  o.fog = false;
  return o;
}

struct Rgb {
  int r, g, b;
};
Rgb at(const std::vector<uint8_t>& px, int width, int x, int y) {
  const size_t k = (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 4;
  return {px[k], px[k + 1], px[k + 2]};
}
// The tree's foliage (Kd 0.13 0.42 0.12 and 0.10 0.33 0.10), lit: green well above red and blue.
// The terrain's lowland colour (0.40 0.50 0.24) is not.
bool leafy(const Rgb& c) { return c.g > 40 && c.g > 2 * c.r && c.g > 2 * c.b; }
int count_leafy(const std::vector<uint8_t>& px, int w, int h) {
  int n = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) n += leafy(at(px, w, x, y));
  return n;
}

fs::path temp_dir(const std::string& name) { return npsnet::test::fresh_dir("render_" + name); }

}  // namespace

TEST(Render, TreeAtItsProjectedPlaceAndStumpAfterSwap) {
  world::World w = flat_world();
  const int tree = w.kinds.find("tree");
  ASSERT_GE(tree, 0);
  w.fixed.add("t1", tree, Vec3(128, 128, 50), 0.0f, 2.5f);
  w.index_fixed();
  render::Renderer r(options(320, 240), w);
  render::Camera cam{Vec3(128, 96, 56), Vec3(128, 128, 54), 50};
  render::SceneView v{&w, nullptr, nullptr, 0.0, -1};
  r.render(v, cam, {}, false);
  const auto px = r.pixels();
  ASSERT_EQ(px.size(), 320u * 240u * 4u);

  // the crown's middle (4.5 m up the 8 m tree) projects into foliage
  const render::ViewMath vm = render::make_view(cam.eye, cam.target, cam.fov_y_deg, 320, 240);
  double cx = 0, cy = 0;
  ASSERT_TRUE(render::project_to_pixel(vm, Vec3(128, 128, 54.5), cx, cy));
  int hits = 0;
  for (int dy = -3; dy <= 3; ++dy)
    for (int dx = -3; dx <= 3; ++dx) hits += leafy(at(px, 320, static_cast<int>(cx) + dx, static_cast<int>(cy) + dy));
  EXPECT_GE(hits, 40) << "of 49 pixels around the crown's projection (" << cx << ", " << cy << ")";
  // well to the side: terrain, not tree
  EXPECT_FALSE(leafy(at(px, 320, 10, 230)));
  EXPECT_FALSE(leafy(at(px, 320, 310, 230)));
  const int intact = count_leafy(px, 320, 240);
  EXPECT_GT(intact, 800);

  // the stump (state 2) has no foliage
  w.fixed.state[0] = static_cast<uint8_t>(w.kinds[tree].state_index("stump"));
  r.render(v, cam, {}, false);
  const int stump = count_leafy(r.pixels(), 320, 240);
  EXPECT_LT(stump, intact / 20) << "intact " << intact << " stump " << stump;

  // a past copy of the states (ring buffer) is drawn instead of the world's own
  std::vector<uint8_t> past{0};
  render::SceneView pv{&w, nullptr, &past, 0.0, -1};
  r.render(pv, cam, {}, false);
  EXPECT_EQ(count_leafy(r.pixels(), 320, 240), intact);
}

TEST(Render, EntityDrawnWithItsHeadingAndDamageState) {
  world::World w = flat_world();
  const int tank = w.kinds.find("m1a1");
  ASSERT_GE(tank, 0);
  w.ents.add("tank1", tank, Vec3(128, 128, 50), 0.0f, 4.0f);
  render::Renderer r(options(200, 200), w);
  // straight down from 40 m, screen up = north
  render::Camera cam{Vec3(128, 127.99, 90), Vec3(128, 128, 50), 30};
  render::SceneView v{&w, nullptr, nullptr, 0.0, -1};
  int mid_x = 0, mid_y = 0;  // centre of the drawn box, px (the gun makes it lie forward of the hull)
  const auto extent = [&](int& wide, int& tall, int& dark) {
    r.render(v, cam, {}, false);
    const auto px = r.pixels();
    int x0 = 999, x1 = -1, y0 = 999, y1 = -1;
    dark = 0;
    for (int y = 0; y < 200; ++y)
      for (int x = 0; x < 200; ++x) {
        const Rgb c = at(px, 200, x, y);
        const bool ground = std::abs(c.r - at(px, 200, 2, 2).r) < 6 && std::abs(c.g - at(px, 200, 2, 2).g) < 6;
        if (ground) continue;
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        dark += c.r + c.g + c.b < 120;
      }
    wide = x1 - x0 + 1;
    tall = y1 - y0 + 1;
    mid_x = (x0 + x1) / 2;
    mid_y = (y0 + y1) / 2;
  };
  int wide = 0, tall = 0, dark0 = 0, dark1 = 0;
  extent(wide, tall, dark0);
  EXPECT_GT(tall, wide * 2) << "heading 0: the 9.8 m tank lies north-south (" << wide << " x " << tall << ")";
  EXPECT_LT(mid_y, 100 - 4) << "heading 0: the gun points north (up)";
  w.ents.heading_deg[0] = 90;
  extent(wide, tall, dark0);
  EXPECT_GT(wide, tall * 2) << "heading 90: east-west (" << wide << " x " << tall << ")";
  EXPECT_GT(mid_x, 100 + 4) << "heading 90: the gun points east (right)";
  w.ents.state[0] = 2;  // wreck: blackened
  extent(wide, tall, dark1);
  EXPECT_GT(dark1, dark0 + 200) << "dark pixels intact " << dark0 << ", wreck " << dark1;
}

TEST(Render, WrittenPngDecodesWithTheRightSize) {
  world::World w = flat_world();
  w.fixed.add("t1", w.kinds.find("tree"), Vec3(128, 128, 50), 0.0f, 2.5f);
  w.index_fixed();
  render::Renderer r(options(333, 211), w);
  r.render({&w, nullptr, nullptr, 0, -1}, {Vec3(128, 96, 56), Vec3(128, 128, 54), 50}, {}, true);
  const fs::path f = temp_dir("png") / "frame.png";
  ASSERT_TRUE(r.write_png(f));
  int x = 0, y = 0, n = 0;
  unsigned char* img = stbi_load(f.string().c_str(), &x, &y, &n, 4);
  ASSERT_NE(img, nullptr) << stbi_failure_reason();
  EXPECT_EQ(x, 333);
  EXPECT_EQ(y, 211);
  EXPECT_EQ(n, 4);
  // same pixels, same orientation (top row first) as pixels()
  const auto px = r.pixels();
  EXPECT_EQ(0, std::memcmp(img, px.data(), px.size()));
  // top of the frame is sky (blue above red), bottom is ground
  EXPECT_GT(img[2], img[0]);
  const size_t bottom = (static_cast<size_t>(210) * 333 + 166) * 4;
  EXPECT_GT(img[bottom + 1], img[bottom + 2]);
  stbi_image_free(img);
  if (const char* keep = std::getenv("NPSNET_KEEP_TEST_PNG")) fs::copy_file(f, fs::path(keep) / "test-frame.png",
                                                                           fs::copy_options::overwrite_existing);
  EXPECT_FALSE(r.write_png("/proc/no/such/dir/frame.png"));
}

TEST(Render, OneByOneAndLargestFrames) {
  world::World w = flat_world();
  for (int side : {1, 4096}) {
    render::Renderer r(options(side, side), w);
    r.render({&w, nullptr, nullptr, 0, -1}, {Vec3(128, 20, 80), Vec3(128, 200, 40), 50}, {}, true);
    const auto px = r.pixels();
    ASSERT_EQ(px.size(), static_cast<size_t>(side) * side * 4);
    if (side == 1) {
      EXPECT_EQ(px[3], 255);
    } else {
      const Rgb top = at(px, side, side / 2, 0), bottom = at(px, side, side / 2, side - 1);
      EXPECT_GT(top.b, top.r) << "sky at the top";
      EXPECT_GT(bottom.g, bottom.b) << "ground at the bottom";
    }
  }
  EXPECT_THROW(render::Renderer(options(0, 10), w), std::runtime_error);
}

TEST(Render, MissingOrBrokenShaderNamesFileAndLine) {
  world::World w = flat_world();
  const fs::path dir = temp_dir("shaders");
  for (const auto& e : fs::directory_iterator(kSrc / "shaders")) fs::copy_file(e.path(), dir / e.path().filename());
  fs::remove(dir / "object.frag");
  try {
    render::Renderer r(options(64, 64), w);  // the real shaders work
    auto o = options(64, 64);
    o.shader_dir = dir;
    render::Renderer bad(o, w);
    FAIL() << "a missing shader file was not reported";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "object.frag").string()), std::string::npos) << e.what();
  }
  // a compile error on line 7 of terrain.vert
  fs::copy_file(kSrc / "shaders/object.frag", dir / "object.frag");
  {
    std::ifstream in(kSrc / "shaders/terrain.vert");
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    ASSERT_GT(lines.size(), 8u);
    lines.insert(lines.begin() + 6, "this is not GLSL;");
    std::ofstream out(dir / "terrain.vert", std::ios::trunc);
    for (const auto& l : lines) out << l << "\n";
  }
  try {
    auto o = options(64, 64);
    o.shader_dir = dir;
    render::Renderer bad(o, w);
    FAIL() << "a shader compile error was not reported";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "terrain.vert").string() + ":7:"), std::string::npos) << e.what();
  }
}

TEST(Render, MissingModelFileIsAnErrorNamingIt) {
  const fs::path dir = temp_dir("models");
  fs::copy_file(kSrc / "models/materials.mtl", dir / "materials.mtl");
  fs::copy_file(kSrc / "models/tree.obj", dir / "tree.obj");
  std::ofstream(dir / "kinds.toml") << "[tree]\nmobility = \"fixed\"\nmass_kg = 1500.0\n"
                                       "states = [\"intact\", \"stump\"]\nmodels = [\"tree.obj\", \"no_such_stump.obj\"]\n"
                                       "dis_type = [5, 1, 0, 1, 1, 0, 0]\n";
  world::ModelLibrary lib;
  try {
    world::KindTable::load(dir / "kinds.toml", lib);
    FAIL() << "a missing model file was not reported";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_stump.obj"), std::string::npos) << e.what();
  }
}

TEST(Render, HeadlessNeverInitialisesGlfw) {
  const char* d = std::getenv("DISPLAY");
  const std::string saved = d ? d : "";
  ::unsetenv("DISPLAY");
  ::unsetenv("WAYLAND_DISPLAY");
  {
    world::World w = flat_world();
    render::Renderer r(options(64, 48), w);
    r.render({&w, nullptr, nullptr, 0, -1}, {Vec3(128, 20, 80), Vec3(128, 200, 40), 50}, {}, true);
    EXPECT_NE(r.gl_description().find("OSMesa"), std::string::npos) << r.gl_description();
  }
  if (render::glfw_init_calls() == 0) {
    glfwGetCurrentContext();  // GLFW's own state: reports "not initialized" if nothing started it
    EXPECT_EQ(glfwGetError(nullptr), GLFW_NOT_INITIALIZED);
  }
  EXPECT_EQ(render::glfw_init_calls(), 0);
  if (!saved.empty()) ::setenv("DISPLAY", saved.c_str(), 1);
}

TEST(Render, WindowUnderADisplay) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY (run under xvfb-run -a to test the GLFW window)";
  world::World w = flat_world();
  auto o = options(160, 120);
  o.window = true;
  render::Renderer r(o, w);
  EXPECT_NE(r.gl_description().find("GLFW"), std::string::npos);
  r.render({&w, nullptr, nullptr, 0, -1}, {Vec3(128, 20, 80), Vec3(128, 200, 40), 50}, {}, true);
  const auto px = r.pixels();
  ASSERT_EQ(px.size(), 160u * 120u * 4u);
  EXPECT_GT(at(px, 160, 80, 0).b, at(px, 160, 80, 0).r);
  EXPECT_EQ(render::glfw_init_calls(), 1);
}

TEST(Render, CraterRebuildsOnlyItsPatch) {
  world::World w = flat_world();
  render::Renderer r(options(64, 64), w);
  const render::TerrainMesh& mesh = r.terrain_mesh();
  const auto before = mesh.vertices();
  const world::PostRect pr = w.terrain.crater(100.0, 60.0, 6.0, 2.0);
  ASSERT_FALSE(pr.empty());
  r.terrain_changed(pr);
  const auto after = mesh.vertices();
  ASSERT_EQ(before.size(), after.size());
  int changed = 0;
  for (int j = 0; j < w.terrain.rows(); ++j)
    for (int i = 0; i < w.terrain.cols(); ++i) {
      const size_t k = mesh.vertex_of(i, j);
      const bool moved = before[k].z != after[k].z || before[k].nx != after[k].nx || before[k].ny != after[k].ny;
      if (!moved) continue;
      ++changed;
      EXPECT_TRUE(i >= pr.i0 - 1 && i <= pr.i1 + 1 && j >= pr.j0 - 1 && j <= pr.j1 + 1)
          << "post (" << i << ", " << j << ") changed outside the crater's rectangle";
      EXPECT_FLOAT_EQ(after[k].z, w.terrain.post(i, j));
    }
  EXPECT_GT(changed, 10);
  EXPECT_LE(r.terrain_mesh().last_rebuilt_chunks(), 4);
  // the GPU copy has the change
  const auto gpu = mesh.read_back();
  ASSERT_EQ(gpu.size(), after.size());
  EXPECT_EQ(0, std::memcmp(gpu.data(), after.data(), gpu.size() * sizeof(render::TerrainVertex)));
  // and equals a mesh built from scratch (positions and normals)
  render::TerrainMesh fresh(w.terrain, 32);
  ASSERT_EQ(fresh.vertices().size(), after.size());
  for (size_t k = 0; k < after.size(); ++k) {
    ASSERT_FLOAT_EQ(fresh.vertices()[k].z, after[k].z) << k;
    ASSERT_FLOAT_EQ(fresh.vertices()[k].nx, after[k].nx) << k;
  }
}

TEST(Render, ExplosionShowsAfterItsStartOnly) {
  world::World w = flat_world();
  render::Renderer r(options(200, 150), w);
  const Vec3 at_pt(128, 128, 50);
  r.add_explosion(at_pt, 10.0, 1.0f);
  render::Camera cam{Vec3(128, 80, 60), Vec3(128, 128, 53), 50};
  const auto fiery = [&](double t) {
    r.render({&w, nullptr, nullptr, t, -1}, cam, {}, false);
    const auto px = r.pixels();
    int n = 0;
    for (int y = 0; y < 150; ++y)
      for (int x = 0; x < 200; ++x) {
        const Rgb c = at(px, 200, x, y);
        n += c.r > 200 && c.g > 60 && c.b < 0.6 * c.r;  // orange-yellow fire
      }
    return n;
  };
  EXPECT_EQ(fiery(9.0), 0) << "before the explosion";
  EXPECT_GT(fiery(10.5), 300) << "fireball";
  EXPECT_EQ(fiery(25.0), 0) << "long over";
}

TEST(Render, LookAtPairSeesBoth) {
  world::World w = flat_world();
  const Vec3 a(100, 100, 50), b(140, 120, 50);
  const render::Camera c = render::look_at_pair(w, a, b);
  EXPECT_GT(c.eye.z(), 55.0);
  const render::ViewMath vm = render::make_view(c.eye, c.target, c.fov_y_deg, 960, 540);
  for (const Vec3& p : {a, b}) {
    double x = 0, y = 0;
    ASSERT_TRUE(render::project_to_pixel(vm, p, x, y));
    EXPECT_GT(x, 0);
    EXPECT_LT(x, 960);
    EXPECT_GT(y, 0);
    EXPECT_LT(y, 540);
  }
}

TEST(Render, GlslLogLineAndFont) {
  EXPECT_EQ(render::glsl_log_line("0:12(5): error: syntax error"), 12);
  EXPECT_EQ(render::glsl_log_line("ERROR: 0:33: 'x' : undeclared"), 33);
  EXPECT_EQ(render::glsl_log_line("no line here"), 0);
  const uint8_t* a = render::font::glyph('A');
  const uint8_t* box = render::font::glyph('\x01');
  EXPECT_NE(0, std::memcmp(a, box, 7));
  EXPECT_EQ(0, std::memcmp(render::font::glyph('a'), a, 7));
  const auto atlas = render::font::atlas();
  EXPECT_EQ(atlas.size(), static_cast<size_t>(render::font::kAtlasW * render::font::kAtlasH));
}

TEST(Render, WaterDrawnAtItsLevel) {
  // a pond: posts in the middle 40 x 40 are 5 m below the ground and 3 m below the water level
  world::World w = flat_world(50.0f, [](int i, int j) { return i >= 44 && i < 84 && j >= 44 && j < 84 ? 45.0f : 50.0f; });
  w.water_level_m = 48.0;
  auto o = options(120, 90);
  render::Renderer r(o, w);
  // straight down onto the pond, then onto dry ground
  const auto colour_below = [&](double x, double y) {
    r.render({&w, nullptr, nullptr, 0, -1}, {Vec3(x, y - 0.01, 120), Vec3(x, y, 50), 20}, {}, false);
    return at(r.pixels(), 120, 60, 45);
  };
  const Rgb pond = colour_below(128, 128), dry = colour_below(30, 30);
  EXPECT_GT(pond.b, pond.r + 40) << "water is blue: " << pond.r << " " << pond.g << " " << pond.b;
  EXPECT_GT(dry.g, dry.b) << "ground is not";
}

TEST(Render, CraterDecalFromItsTimeOn) {
  world::World w = flat_world();
  render::Renderer r(options(160, 120), w);
  r.add_crater(Vec3(128, 128, 50), 6.0, 5.0);
  render::Camera cam{Vec3(128, 100, 70), Vec3(128, 128, 50), 40};
  const render::ViewMath vm = render::make_view(cam.eye, cam.target, cam.fov_y_deg, 160, 120);
  double cx = 0, cy = 0;
  ASSERT_TRUE(render::project_to_pixel(vm, Vec3(128, 128, 50), cx, cy));
  const auto centre = [&](double t) {
    r.render({&w, nullptr, nullptr, t, -1}, cam, {}, false);
    return at(r.pixels(), 160, static_cast<int>(cx), static_cast<int>(cy));
  };
  const Rgb before = centre(4.0), after = centre(6.0);
  EXPECT_GT(before.r + before.g + before.b, 200) << "ground before the crater";
  EXPECT_LT(after.r + after.g + after.b, 100) << "scorched crater floor after it";
}

TEST(Render, CullingAndDistanceLod) {
  world::World w;
  const int n = 401;  // 10 km square, 25 m posts
  w.terrain = world::Terrain(n, n, 25.0, std::vector<float>(static_cast<size_t>(n * n), 10.0f),
                             geo::Geodetic{35.98, -121.25, 0.0});
  w.kinds = world::KindTable::load(kSrc / "models/kinds.toml", w.models);
  const int tree = w.kinds.find("tree");
  // camera at (5000, 1000) looking north
  w.fixed.add("near", tree, Vec3(5000, 1060, 10), 0.0f, 2.5f);    // 60 m ahead: full model
  w.fixed.add("far", tree, Vec3(5000, 3500, 10), 0.0f, 2.5f);     // 2.5 km: simplified
  w.fixed.add("beyond", tree, Vec3(5000, 9900, 10), 0.0f, 2.5f);  // 8.9 km: not drawn
  w.fixed.add("behind", tree, Vec3(5000, 600, 10), 0.0f, 2.5f);   // behind the camera: culled
  w.index_fixed();
  render::Renderer r(options(320, 240), w);
  r.render({&w, nullptr, nullptr, 0, -1}, {Vec3(5000, 1000, 14), Vec3(5000, 2000, 14), 50}, {}, false);
  const auto& st = r.stats();
  EXPECT_EQ(st.objects_full, 1);
  EXPECT_EQ(st.objects_simple, 1);
  EXPECT_GT(st.blocks_culled, 0);
  EXPECT_GT(st.terrain_chunks_culled, 0);
  // terrain far away is drawn coarser: fewer triangles than the full-resolution visible chunks
  EXPECT_LT(st.terrain_triangles, static_cast<int64_t>(st.terrain_chunks_drawn) * 32 * 32 * 2);
  // looking south instead, the tree behind is the near one
  r.render({&w, nullptr, nullptr, 0, -1}, {Vec3(5000, 1000, 14), Vec3(5000, 0, 14), 50}, {}, false);
  EXPECT_EQ(r.stats().objects_full, 1);
  EXPECT_EQ(r.stats().objects_simple, 0);
}

TEST(Models, EveryKindAndStateHasAValidModel) {
  world::ModelLibrary lib;
  const world::KindTable kinds = world::KindTable::load(kSrc / "models/kinds.toml", lib);
  for (int k = 0; k < kinds.size(); ++k) {
    ASSERT_EQ(kinds[k].models.size(), kinds[k].states.size()) << kinds[k].name;
    for (int m : kinds[k].models) {
      const world::Model& mod = lib[m];
      EXPECT_GE(mod.faces.size(), 20u) << mod.file;
      EXPECT_LE(mod.faces.size(), 300u) << mod.file;
      // no degenerate face; outward counter-clockwise winding: the enclosed volume is positive
      double vol = 0;
      for (const auto& f : mod.faces) {
        EXPECT_GT(f.normal.norm(), 0.5f) << mod.file << ": degenerate face";
        const Vec3f& a = mod.vertices[mod.face_vertices[f.first]];
        for (uint32_t i = 1; i + 1 < f.count; ++i)
          vol += a.dot(mod.vertices[mod.face_vertices[f.first + i]].cross(mod.vertices[mod.face_vertices[f.first + i + 1]])) / 6.0;
      }
      EXPECT_GT(vol, 0.0) << mod.file;
    }
  }
  // sizes the brief asks for (metres): tree ~8 m tall, tank 9.8 long, ship 30 long
  const auto extent = [&](const std::string& kind) {
    const world::Model& m = lib[kinds[kinds.find(kind)].models[0]];
    return Vec3f(m.bbox_max - m.bbox_min);
  };
  EXPECT_NEAR(extent("tree").z(), 8.0f, 0.5f);
  EXPECT_NEAR(extent("m1a1").y(), 9.8f, 0.2f);
  EXPECT_NEAR(extent("m1a1").x(), 3.7f, 0.2f);
  EXPECT_NEAR(extent("patrol_ship").y(), 30.0f, 0.5f);
  EXPECT_NEAR(extent("f16").y(), 15.0f, 0.5f);
  EXPECT_NEAR(extent("f16").x(), 10.0f, 0.3f);
  EXPECT_NEAR(extent("watertower").z(), 30.0f, 1.0f);
}
