// Renderer::Impl::draw_scene: one frame of the world from a view (renderer_impl.hpp): terrain
// and crater decals, fixed objects by block and entities with their level of detail, sky, water,
// the see-through vehicle, particles.
#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "render/gl_api.hpp"
#include "render/renderer_impl.hpp"

namespace npsnet::render {
using namespace impl;

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
    gl::stream_to_buffer(particle_vbo, parts.data(), parts.size() * sizeof(Particle), particle_cap);
    gl::DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(parts.size()));
    gl::DepthMask(GL_TRUE);
  }
  gl::Disable(GL_BLEND);
  gl::BindVertexArray(0);
}

}  // namespace npsnet::render
