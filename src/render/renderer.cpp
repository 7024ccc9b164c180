#include "render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/constants.hpp"
#include "render/effects.hpp"
#include "render/gl_api.hpp"
#include "render/gl_context.hpp"
#include "render/hud_map.hpp"
#include "render/model_meshes.hpp"
#include "render/overlay.hpp"
#include "render/shader.hpp"
#include "render/terrain_mesh.hpp"
#include "render/view.hpp"

namespace npsnet::render {
namespace {

constexpr int kTerrainChunkCells = 32;     // posts per chunk side - 1
constexpr int kBlockGridsquares = 4;       // fixed objects are culled in blocks of 4 x 4 gridsquares
constexpr double kTerrainLodK = 24.0;      // a chunk uses step s beyond s * spacing * this (m)
constexpr double kFullDetailRadii = 150.0; // full model within this many bounding radii (at 540 px)
constexpr double kSimpleRadii = 800.0;     // simplified model within this many radii; none beyond
constexpr double kEntityLodBoost = 3.0;    // vehicles keep detail farther than fixed objects
constexpr float kSkyHorizon[3] = {0.74f, 0.80f, 0.86f};
constexpr float kSkyZenith[3] = {0.33f, 0.53f, 0.82f};
constexpr int kMinOverlayW = 64, kMinOverlayH = 48;
constexpr double kWaterCellM = 200.0;      // water grid cell (haze is computed per vertex)
constexpr int kCraterSegments = 16;        // crater decal: segments around
constexpr float kGhostAlpha = 0.35f;       // opacity of a see-through vehicle (Camera::ghost_entity)

void check_gl(const char* where) {
  const GLenum e = gl::GetError();
  if (e != GL_NO_ERROR) throw std::runtime_error(std::string("render: ") + gl::error_name(e) + " in " + where);
}

}  // namespace

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

void Renderer::Impl::draw_scene(const SceneView& v, const ViewMath& vm, const Camera& cam) {
  const world::World& w = *world;
  const float fog_density = opt.fog && opt.visibility_m > 0 ? static_cast<float>(1.0 / opt.visibility_m) : 0.0f;
  // beyond this the haze leaves < 1 % of a colour: nothing there is drawn
  const double max_dist = fog_density > 0 ? 2.15 * opt.visibility_m : static_cast<double>(kFarM);
  const Vec3f sun = Vec3f(0.45f, -0.50f, 0.74f).normalized();
  const Vec3f eyef = vm.eye.cast<float>();
  const auto common = [&](const Program& pr) {
    pr.use();
    gl::UniformMatrix4fv(pr.loc("u_vp"), 1, GL_FALSE, vm.vp.data());
    gl::Uniform3f(pr.loc("u_eye"), eyef.x(), eyef.y(), eyef.z());
    gl::Uniform3f(pr.loc("u_sun"), sun.x(), sun.y(), sun.z());
    gl::Uniform1f(pr.loc("u_fog_density"), fog_density);
    gl::Uniform3f(pr.loc("u_fog_color"), kSkyHorizon[0], kSkyHorizon[1], kSkyHorizon[2]);
  };

  gl::Enable(GL_DEPTH_TEST);
  gl::DepthFunc(GL_LEQUAL);
  gl::DepthMask(GL_TRUE);

  // terrain
  common(*terrain_prog);
  gl::Uniform2f(terrain_prog->loc("u_hrange"), hmin, hmax);
  gl::Uniform1f(terrain_prog->loc("u_water_level"), static_cast<float>(std::clamp(w.water_level_m, -1e6, 1e6)));
  gl::Uniform1i(terrain_prog->loc("u_water"), 0);
  gl::Disable(GL_CULL_FACE);  // skirts face both ways
  TerrainDrawStats ts;
  terrain->draw(vm, kTerrainLodK / std::max(0.1, opt.lod_scale), max_dist, ts);
  stats.terrain_chunks_drawn = ts.chunks_drawn;
  stats.terrain_chunks_culled = ts.chunks_culled;
  stats.terrain_triangles = ts.triangles;
  // crater decals that exist at this scenario time, pulled towards the eye so they win over the ground
  bool any_crater = false;
  for (const auto& c : craters) any_crater |= c.t0 <= v.t;
  if (any_crater) {
    gl::Enable(GL_POLYGON_OFFSET_FILL);
    gl::PolygonOffset(-2.0f, -4.0f);
    gl::BindVertexArray(crater_vao);
    for (const auto& c : craters)
      if (c.t0 <= v.t) gl::DrawArrays(GL_TRIANGLES, c.first, c.count);
    gl::Disable(GL_POLYGON_OFFSET_FILL);
  }

  // objects: fixed ones by block, then entities
  meshes->clear();
  const double px_scale = static_cast<double>(vm.height) / 540.0 * std::max(0.1, opt.lod_scale);
  const double full_k = kFullDetailRadii * px_scale, simple_k = kSimpleRadii * px_scale;
  const auto& fs = (v.fixed_state && v.fixed_state->size() == w.fixed.size()) ? *v.fixed_state : w.fixed.state;
  const auto& f = w.fixed;
  const double reach = std::min(max_dist, simple_k * 40.0);  // no fixed object is 40 m in radius
  const auto& g = w.grid;
  const bool indexed = g.cols() > 0 && !f.id.empty();
  const int a0 = indexed ? g.col(vm.eye.x() - reach) / kBlockGridsquares : 0;
  const int a1 = indexed ? g.col(vm.eye.x() + reach) / kBlockGridsquares : -1;
  const int b0 = indexed ? g.row(vm.eye.y() - reach) / kBlockGridsquares : 0;
  const int b1 = indexed ? g.row(vm.eye.y() + reach) / kBlockGridsquares : -1;
  int bv = 0, bc = 0;
  for (int b = b0; b <= b1; ++b)
    for (int a = a0; a <= a1; ++a) {
      const size_t blk = static_cast<size_t>(b) * static_cast<size_t>(bcols) + static_cast<size_t>(a);
      if (block_count[blk] == 0) continue;
      const Vec3 near = vm.eye.cwiseMax(block_lo[blk]).cwiseMin(block_hi[blk]);
      if ((near - vm.eye).norm() > reach || !vm.box_visible(block_lo[blk], block_hi[blk])) {
        ++bc;
        continue;
      }
      ++bv;
      const auto draw = [&](int i) {
        const int m = model_for(f.kind[i], fs[i]);
        if (m < 0) return;
        const float r = model_radius[static_cast<size_t>(m)];
        const double d = (f.pos[i] - vm.eye).norm();
        if (d > simple_k * r || d > max_dist + r || !vm.sphere_visible(f.pos[i], r)) return;
        meshes->add(m, d > full_k * r,
                    {static_cast<float>(f.pos[i].x()), static_cast<float>(f.pos[i].y()),
                     static_cast<float>(f.pos[i].z()), static_cast<float>(deg2rad(f.heading_deg[i])), 0, 0, 1, 0});
      };
      const int j1 = std::min(g.rows(), (b + 1) * kBlockGridsquares), i1 = std::min(g.cols(), (a + 1) * kBlockGridsquares);
      for (int j = b * kBlockGridsquares; j < j1; ++j)
        for (int i = a * kBlockGridsquares; i < i1; ++i) g.for_each_home(j * g.cols() + i, draw);
    }
  stats.blocks_visible = bv;
  stats.blocks_culled = bc;
  const world::Entities& e = v.ents ? *v.ents : w.ents;
  const auto entity_instance = [&](size_t i) {
    return Instance{static_cast<float>(e.pos[i].x()), static_cast<float>(e.pos[i].y()), static_cast<float>(e.pos[i].z()),
                    static_cast<float>(deg2rad(e.heading_deg[i])), static_cast<float>(deg2rad(e.pitch_deg[i])),
                    static_cast<float>(deg2rad(e.roll_deg[i])), 1, 0};
  };
  int ghost_model = -1;
  for (size_t i = 0; i < e.size(); ++i) {
    if ((i < e.active.size() && !e.active[i]) || static_cast<int>(i) == cam.hide_entity) continue;
    const int m = model_for(e.kind[i], e.state[i]);
    if (m < 0 || !e.pos[i].allFinite()) continue;
    if (static_cast<int>(i) == cam.ghost_entity) {
      ghost_model = m;
      continue;
    }
    const float r = model_radius[static_cast<size_t>(m)];
    const double d = (e.pos[i] - vm.eye).norm();
    if (d > simple_k * kEntityLodBoost * r || d > max_dist + r || !vm.sphere_visible(e.pos[i], r)) continue;
    meshes->add(m, d > full_k * kEntityLodBoost * r, entity_instance(i));
  }
  common(*object_prog);
  gl::Uniform1f(object_prog->loc("u_alpha"), 1.0f);
  gl::Enable(GL_CULL_FACE);
  gl::CullFace(GL_BACK);
  gl::FrontFace(GL_CCW);
  ObjectDrawStats os;
  meshes->draw(os);
  stats.objects_full = os.instances_full;
  stats.objects_simple = os.instances_simple;
  stats.object_triangles = os.triangles;
  gl::Disable(GL_CULL_FACE);

  // sky: where nothing opaque was drawn (depth still 1)
  gl::DepthMask(GL_FALSE);
  sky_prog->use();
  const Mat4f inv = vm.vp.inverse();
  gl::UniformMatrix4fv(sky_prog->loc("u_inv_vp"), 1, GL_FALSE, inv.data());
  gl::Uniform3f(sky_prog->loc("u_horizon"), kSkyHorizon[0], kSkyHorizon[1], kSkyHorizon[2]);
  gl::Uniform3f(sky_prog->loc("u_zenith"), kSkyZenith[0], kSkyZenith[1], kSkyZenith[2]);
  gl::BindVertexArray(empty_vao);
  gl::DrawArrays(GL_TRIANGLES, 0, 3);
  gl::DepthMask(GL_TRUE);

  // water
  gl::Enable(GL_BLEND);
  gl::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  if (have_water) {
    common(*terrain_prog);
    gl::Uniform1i(terrain_prog->loc("u_water"), 1);
    gl::BindVertexArray(water_vao);
    gl::DrawArrays(GL_TRIANGLES, 0, water_vertices);
  }

  // the see-through vehicle (Camera::ghost_entity): its nearest faces only (depth first), blended
  if (ghost_model >= 0) {
    meshes->clear();
    meshes->add(ghost_model, false, entity_instance(static_cast<size_t>(cam.ghost_entity)));
    common(*object_prog);
    gl::Enable(GL_CULL_FACE);
    gl::ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    ObjectDrawStats gs;
    meshes->draw(gs);
    gl::ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl::DepthMask(GL_FALSE);
    gl::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl::Uniform1f(object_prog->loc("u_alpha"), kGhostAlpha);
    meshes->draw(gs);
    gl::Uniform1f(object_prog->loc("u_alpha"), 1.0f);
    gl::DepthMask(GL_TRUE);
    gl::Disable(GL_CULL_FACE);
  }

  // particles: premultiplied alpha, no depth writes
  const auto& parts = effects.particles(v.t);
  stats.particles = static_cast<int>(parts.size());
  if (!parts.empty()) {
    gl::DepthMask(GL_FALSE);
    gl::BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    common(*particle_prog);
    gl::Uniform3f(particle_prog->loc("u_right"), vm.right.x(), vm.right.y(), vm.right.z());
    gl::Uniform3f(particle_prog->loc("u_up"), vm.up.x(), vm.up.y(), vm.up.z());
    gl::BindVertexArray(particle_vao);
    gl::BindBuffer(GL_ARRAY_BUFFER, particle_vbo);
    const size_t bytes = parts.size() * sizeof(Particle);
    if (bytes > particle_cap) {
      particle_cap = std::max(bytes, particle_cap * 2);
      gl::BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(particle_cap), nullptr, GL_STREAM_DRAW);
    }
    gl::BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), parts.data());
    gl::DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(parts.size()));
    gl::DepthMask(GL_TRUE);
  }
  gl::Disable(GL_BLEND);
  gl::BindVertexArray(0);
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

Camera look_at_pair(const world::World& w, const Vec3& a, const Vec3& b) {
  const Vec3 mid = 0.5 * (a + b);
  Vec2 dir(b.x() - a.x(), b.y() - a.y());
  const double sep = dir.norm();
  dir = sep > 1e-6 ? Vec2(dir / sep) : Vec2(0, 1);
  const Vec2 side(-dir.y(), dir.x());
  const double dist = std::max(30.0, 1.3 * sep + 20.0);
  Camera c;
  c.fov_y_deg = 50;
  c.target = mid + Vec3(0, 0, 1.5);
  Vec3 eye = mid + Vec3(side.x(), side.y(), 0) * (0.9 * dist) - Vec3(dir.x(), dir.y(), 0) * (0.3 * dist);
  eye.z() = std::max(mid.z(), w.terrain.height(eye.x(), eye.y())) + std::max(8.0, 0.35 * dist);
  // raise the eye until the terrain no longer hides the target (bounded)
  for (int tries = 0; tries < 20; ++tries) {
    bool blocked = false;
    for (int k = 1; k < 24 && !blocked; ++k) {
      const Vec3 q = eye + (c.target - eye) * (k / 24.0);
      blocked = w.terrain.height(q.x(), q.y()) > q.z() - 1.0;
    }
    if (!blocked) break;
    eye.z() += 0.15 * dist;
  }
  c.eye = eye;
  return c;
}

Camera vehicle_eye(const Vec3& pos, double heading_deg, double pitch_deg, double eye_height_m) {
  const Vec2 d = heading_to_dir(heading_deg);
  const double cp = std::cos(deg2rad(pitch_deg)), sp = std::sin(deg2rad(pitch_deg));
  Camera c;
  c.eye = pos + Vec3(0, 0, eye_height_m);
  c.target = c.eye + Vec3(d.x() * cp, d.y() * cp, sp) * 100.0;
  c.fov_y_deg = 50;
  return c;
}

}  // namespace npsnet::render
