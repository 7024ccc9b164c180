// The Renderer (renderer.hpp): its GL context, framebuffer, shaders and meshes made and freed,
// terrain and crater updates, a frame rendered (the scene: scene_draw.cpp) and read back.
#include "render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/constants.hpp"
#include "render/gl_api.hpp"
#include "render/hud_map.hpp"
#include "render/renderer_impl.hpp"

namespace npsnet::render {
using namespace impl;

void impl::check_gl(const char* where) {
  const GLenum e = gl::GetError();
  if (e != GL_NO_ERROR) throw std::runtime_error(std::string("render: ") + gl::error_name(e) + " in " + where);
}

int Renderer::Impl::model_for(int kind, int state) const {
  if (kind < 0 || kind >= world->kinds.size()) return -1;
  const auto& models = world->kinds[kind].models;
  if (models.empty()) return -1;
  return models[static_cast<size_t>(std::clamp(state, 0, static_cast<int>(models.size()) - 1))];
}

void Renderer::Impl::build_blocks() {
  // Blocks of kBlockGridsquares x kBlockGridsquares gridsquares of the world's one fixed-object
  // grid (world/fixed_grid.hpp): an object belongs to the block of its home gridsquare; only the
  // block's count and bounds are kept here.
  const auto& f = world->fixed;
  const auto& g = world->grid;
  if (g.size() != f.size()) throw std::runtime_error("render: the fixed objects are not indexed (World::index_fixed)");
  const int cols = std::max(1, g.cols()), rows = std::max(1, g.rows());
  bcols = (cols + kBlockGridsquares - 1) / kBlockGridsquares;
  brows = (rows + kBlockGridsquares - 1) / kBlockGridsquares;
  const size_t nb = static_cast<size_t>(bcols) * static_cast<size_t>(brows);
  block_count.assign(nb, 0);
  block_lo.assign(nb, Vec3(1e30, 1e30, 1e30));
  block_hi.assign(nb, Vec3(-1e30, -1e30, -1e30));
  for (size_t i = 0; i < f.size(); ++i) {
    const size_t b = static_cast<size_t>(g.row(f.pos[i].y()) / kBlockGridsquares) * static_cast<size_t>(bcols) +
                     static_cast<size_t>(g.col(f.pos[i].x()) / kBlockGridsquares);
    ++block_count[b];
    // the object's extent over all its states' models
    double r = 0, zlo = 0, zhi = 0;
    const int k = f.kind[i];
    if (k >= 0 && k < world->kinds.size())
      for (int m : world->kinds[k].models) {
        r = std::max<double>(r, model_radius[static_cast<size_t>(m)]);
        zlo = std::min<double>(zlo, world->models[m].bbox_min.z());
        zhi = std::max<double>(zhi, world->models[m].bbox_max.z());
      }
    block_lo[b] = block_lo[b].cwiseMin(f.pos[i] - Vec3(r, r, -zlo));
    block_hi[b] = block_hi[b].cwiseMax(f.pos[i] + Vec3(r, r, zhi));
  }
}

Renderer::Renderer(const RenderOptions& opt, const world::World& world) : p_(std::make_unique<Impl>()) {
  Impl& p = *p_;
  p.opt = opt;
  p.world = &world;
  if (opt.width < 1 || opt.height < 1)
    throw std::runtime_error("render: frame size " + std::to_string(opt.width) + "x" + std::to_string(opt.height) +
                             " must be at least 1x1");
  if (world.terrain.cols() < 2 || world.terrain.rows() < 2)
    throw std::runtime_error("render: the world has no terrain (needs at least 2 x 2 posts)");
  p.ctx = opt.window ? make_glfw_context(opt.width, opt.height, "NPSNET") : make_osmesa_context();
  p.ctx->make_current();

  GLint max_rb = 0, max_vp[2] = {0, 0};
  gl::GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_rb);
  gl::GetIntegerv(GL_MAX_VIEWPORT_DIMS, max_vp);
  const int lim = std::min({max_rb, max_vp[0], max_vp[1]});
  if (opt.width > lim || opt.height > lim)
    throw std::runtime_error("render: frame size " + std::to_string(opt.width) + "x" + std::to_string(opt.height) +
                             " exceeds this GL's limit of " + std::to_string(lim) + " px a side");
  gl::GenFramebuffers(1, &p.fbo);
  gl::BindFramebuffer(GL_FRAMEBUFFER, p.fbo);
  gl::GenRenderbuffers(1, &p.color_rb);
  gl::BindRenderbuffer(GL_RENDERBUFFER, p.color_rb);
  gl::RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, opt.width, opt.height);
  gl::FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, p.color_rb);
  gl::GenRenderbuffers(1, &p.depth_rb);
  gl::BindRenderbuffer(GL_RENDERBUFFER, p.depth_rb);
  gl::RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, opt.width, opt.height);
  gl::FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, p.depth_rb);
  if (gl::CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("render: cannot make a " + std::to_string(opt.width) + "x" + std::to_string(opt.height) +
                             " framebuffer");

  const auto dir = opt.shader_dir.empty() ? std::filesystem::path("shaders") : opt.shader_dir;
  p.terrain_prog = std::make_unique<Program>(dir, "terrain");
  p.object_prog = std::make_unique<Program>(dir, "object");
  p.particle_prog = std::make_unique<Program>(dir, "particle");
  p.sky_prog = std::make_unique<Program>(dir, "sky");
  p.overlay = std::make_unique<Overlay>(dir, world.terrain, world.water_level_m);

  p.terrain = std::make_unique<TerrainMesh>(world.terrain, kTerrainChunkCells);
  p.hmin = p.terrain->min_z();
  p.hmax = p.terrain->max_z();
  p.meshes = std::make_unique<ModelMeshes>(world.models);
  p.model_radius.resize(static_cast<size_t>(world.models.size()));
  for (int m = 0; m < world.models.size(); ++m) {
    float r = 0;
    for (const auto& v : world.models[m].vertices) r = std::max(r, v.norm());
    p.model_radius[static_cast<size_t>(m)] = r;
  }
  p.build_blocks();

  gl::GenVertexArrays(1, &p.empty_vao);
  // water: a grid over the posts below the water level (fine enough for per-vertex haze)
  p.have_water = world.water_level_m > p.hmin;
  {
    const auto& t = world.terrain;
    int i0 = t.cols(), i1 = -1, j0 = t.rows(), j1 = -1;
    for (int j = 0; j < t.rows(); ++j)
      for (int i = 0; i < t.cols(); ++i)
        if (t.post(i, j) < world.water_level_m) i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
    std::vector<TerrainVertex> grid;
    if (p.have_water && i1 >= i0) {
      const double s = t.spacing_m();
      const double x0 = std::max(0, i0 - 1) * s, x1 = std::min(t.cols() - 1, i1 + 1) * s;
      const double y0 = std::max(0, j0 - 1) * s, y1 = std::min(t.rows() - 1, j1 + 1) * s;
      const int nx = std::clamp(static_cast<int>((x1 - x0) / kWaterCellM) + 1, 1, 256);
      const int ny = std::clamp(static_cast<int>((y1 - y0) / kWaterCellM) + 1, 1, 256);
      const auto z = static_cast<float>(world.water_level_m);
      const auto vtx = [&](int a, int b) {
        return TerrainVertex{static_cast<float>(x0 + (x1 - x0) * a / nx), static_cast<float>(y0 + (y1 - y0) * b / ny), z,
                             0, 0, 1, 0};
      };
      for (int b = 0; b < ny; ++b)
        for (int a = 0; a < nx; ++a)
          for (const auto& [da, db] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}) grid.push_back(vtx(a + da, b + db));
    }
    p.have_water = !grid.empty();
    p.water_vertices = static_cast<int>(grid.size());
    gl::GenVertexArrays(1, &p.water_vao);
    gl::BindVertexArray(p.water_vao);
    gl::GenBuffers(1, &p.water_vbo);
    gl::BindBuffer(GL_ARRAY_BUFFER, p.water_vbo);
    gl::BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(std::max<size_t>(1, grid.size()) * sizeof(TerrainVertex)),
                   grid.empty() ? nullptr : grid.data(), GL_STATIC_DRAW);
    terrain_vertex_layout();
  }
  gl::GenVertexArrays(1, &p.crater_vao);
  gl::BindVertexArray(p.crater_vao);
  gl::GenBuffers(1, &p.crater_vbo);
  gl::BindBuffer(GL_ARRAY_BUFFER, p.crater_vbo);
  terrain_vertex_layout();
  gl::GenVertexArrays(1, &p.particle_vao);
  gl::BindVertexArray(p.particle_vao);
  gl::GenBuffers(1, &p.particle_vbo);
  gl::BindBuffer(GL_ARRAY_BUFFER, p.particle_vbo);
  for (int a = 0; a < 2; ++a) {
    gl::EnableVertexAttribArray(static_cast<GLuint>(a));
    gl::VertexAttribPointer(static_cast<GLuint>(a), 4, GL_FLOAT, GL_FALSE, sizeof(Particle),
                            reinterpret_cast<void*>(static_cast<size_t>(a) * 4 * sizeof(float)));
    gl::VertexAttribDivisor(static_cast<GLuint>(a), 1);
  }
  gl::BindVertexArray(0);
  check_gl("Renderer setup");
}

Renderer::~Renderer() {
  if (!p_ || !p_->ctx) return;
  Impl& p = *p_;
  p.ctx->make_current();
  p.terrain.reset();
  p.meshes.reset();
  p.overlay.reset();
  p.terrain_prog.reset();
  p.object_prog.reset();
  p.particle_prog.reset();
  p.sky_prog.reset();
  gl::DeleteBuffers(1, &p.water_vbo);
  gl::DeleteBuffers(1, &p.crater_vbo);
  gl::DeleteVertexArrays(1, &p.crater_vao);
  gl::DeleteBuffers(1, &p.particle_vbo);
  gl::DeleteVertexArrays(1, &p.water_vao);
  gl::DeleteVertexArrays(1, &p.particle_vao);
  gl::DeleteVertexArrays(1, &p.empty_vao);
  gl::DeleteRenderbuffers(1, &p.color_rb);
  gl::DeleteRenderbuffers(1, &p.depth_rb);
  gl::DeleteFramebuffers(1, &p.fbo);
}

void Renderer::terrain_changed(const world::PostRect& r) {
  Impl& p = *p_;
  if (r.empty()) return;
  p.ctx->make_current();
  p.terrain->rebuild(p.world->terrain, r);
  p.hmin = std::min(p.hmin, p.terrain->min_z());
  p.overlay->update_map(p.world->terrain, r);
}

void Renderer::add_explosion(const Vec3& at, double t, float scale) { p_->effects.add_explosion(at, t, scale); }
void Renderer::add_fire(const Vec3& at, double t, double seconds) { p_->effects.add_fire(at, t, seconds); }

void Renderer::add_crater(const Vec3& at, double radius_m, double t) {
  Impl& p = *p_;
  if (!at.allFinite() || !std::isfinite(t) || !(radius_m > 0) || radius_m > 1e4) return;
  p.ctx->make_current();
  // rings: centre, 0.5 r, r, 1.6 r; scorch 1 -> 0 so the outer ring meets the terrain's own colour
  const double rings[4] = {0.0, 0.5, 1.0, 1.6};
  const float scorch[4] = {1.0f, 0.95f, 0.55f, 0.0f};
  const auto& t_ = p.world->terrain;
  const auto vtx = [&](int ring, int k) {
    const double a = 2 * kPi * k / kCraterSegments, rr = radius_m * rings[ring];
    const double x = at.x() + rr * std::cos(a), y = at.y() + rr * std::sin(a);
    const Vec3 n = t_.normal(x, y);
    return TerrainVertex{static_cast<float>(x), static_cast<float>(y), static_cast<float>(t_.height(x, y) + 0.05),
                         static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z()), scorch[ring]};
  };
  const int first = static_cast<int>(p.crater_verts.size());
  for (int ring = 0; ring < 3; ++ring)
    for (int k = 0; k < kCraterSegments; ++k) {
      const TerrainVertex a0 = vtx(ring, k), a1 = vtx(ring, k + 1), b0 = vtx(ring + 1, k), b1 = vtx(ring + 1, k + 1);
      p.crater_verts.insert(p.crater_verts.end(), {a0, b0, b1, a0, b1, a1});
    }
  p.craters.push_back({t, first, static_cast<int>(p.crater_verts.size()) - first});
  gl::BindBuffer(GL_ARRAY_BUFFER, p.crater_vbo);
  gl::BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(p.crater_verts.size() * sizeof(TerrainVertex)),
                 p.crater_verts.data(), GL_STATIC_DRAW);
}

void Renderer::render(const SceneView& view, const Camera& cam, const Hud& hud, bool map_inset) {
  Impl& p = *p_;
  if (view.world && view.world != p.world)
    throw std::runtime_error("render: SceneView.world is not the world this Renderer was built for");
  p.ctx->make_current();
  gl::BindFramebuffer(GL_FRAMEBUFFER, p.fbo);
  gl::Viewport(0, 0, p.opt.width, p.opt.height);
  p.stats = {};
  const ViewMath vm = make_view(cam.eye, cam.target, cam.fov_y_deg, p.opt.width, p.opt.height, cam.up);
  gl::ClearColor(kSkyHorizon[0], kSkyHorizon[1], kSkyHorizon[2], 1);
  gl::Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (cam.eye.allFinite() && cam.target.allFinite()) p.draw_scene(view, vm, cam);
  if ((map_inset || hud.show) && p.opt.width >= kMinOverlayW && p.opt.height >= kMinOverlayH)
    draw_hud_and_map(*p.overlay, *p.world, view, vm, hud, map_inset,
                     p.opt.fog ? 2.0 * p.opt.visibility_m : 0.15 * std::max(p.world->terrain.width_m(), p.world->terrain.depth_m()));
  gl::Finish();
  check_gl("render");
  p.ctx->present(p.fbo, p.opt.width, p.opt.height);
}

std::vector<uint8_t> Renderer::pixels() const {
  const Impl& p = *p_;
  p.ctx->make_current();
  const auto w = static_cast<size_t>(p.opt.width), h = static_cast<size_t>(p.opt.height);
  std::vector<uint8_t> raw(w * h * 4), out(w * h * 4);
  gl::BindFramebuffer(GL_FRAMEBUFFER, p.fbo);
  gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl::ReadPixels(0, 0, p.opt.width, p.opt.height, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
  for (size_t y = 0; y < h; ++y)
    std::copy_n(&raw[(h - 1 - y) * w * 4], w * 4, &out[y * w * 4]);
  return out;
}

int Renderer::width() const { return p_->opt.width; }
int Renderer::height() const { return p_->opt.height; }
const FrameStats& Renderer::stats() const { return p_->stats; }
const std::string& Renderer::gl_description() const { return p_->ctx->description; }
bool Renderer::window_should_close() const { return p_->ctx->should_close(); }
void* Renderer::native_window() const { return p_->ctx->native_window(); }
void Renderer::wait_events(double timeout_s) { p_->ctx->wait_events(timeout_s); }
const TerrainMesh& Renderer::terrain_mesh() const { return *p_->terrain; }

}  // namespace npsnet::render
