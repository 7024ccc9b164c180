// The node's renderer: draws a World as seen from a Camera into an off-screen frame (OSMesa GL
// core profile on llvmpipe; no display needed and GLFW never touched) or, with
// RenderOptions::window, into a GLFW window as well. Shaders are read at run time from
// RenderOptions::shader_dir. Units: metres, local frame (x east, y north, z up); angles in degrees;
// scenario time t in seconds. Frame sizes 1 x 1 up to 4096 x 4096 (and more where GL allows).
//
// Drawn each frame: sky; terrain (chunked mesh, frustum-culled, distance LOD; a crater reported
// through terrain_changed rebuilds only its patch); water at world.water_level_m; fixed objects
// instanced per (kind, state) model, culled per block of gridsquares, full model near, two-box
// simplified model farther, skipped beyond; entities with the model of their current damage
// state and their heading/pitch/roll; particle explosions, fire and smoke; optional haze; the
// HUD of the driven vehicle and a 2D map inset of the whole terrain (entity dots + the driven
// vehicle's view triangle), both drawn in GL with a bitmap font made in code.
// Threading: a Renderer and its GL context belong to the thread that made it (the tick's); it
// reads the World (or a past copy of its entities) only between ticks, never during one.
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/math.hpp"
#include "world/world.hpp"

namespace npsnet::render {

class TerrainMesh;

struct RenderOptions {
  int width = 960, height = 540;        // frame size, px
  bool window = false;                  // also show the frames in a GLFW window
  std::filesystem::path shader_dir;     // holds terrain.vert/.frag, object.*, particle.*, sky.*, overlay.*, lines2d.*
  bool fog = true;                      // haze
  double visibility_m = 10000;          // haze: at this distance 37 % of an object's colour remains
  double lod_scale = 1.0;               // > 1 keeps full detail farther away
};

struct Camera {
  Vec3 eye{0, 0, 0}, target{0, 1, 0};
  double fov_y_deg = 50;  // vertical field of view
  Vec3 up{0, 0, 1};       // the frame's up is this made square to the line of sight (roll)
  int hide_entity = -1;   // an entity not drawn: the vehicle the eye sits in (driver camera)
  int ghost_entity = -1;  // an entity drawn see-through (its nearest faces, 35 % opaque): a
                          // vehicle standing on what the frame is about
};

struct Hud {
  bool show = false;
  double speed_kmh = 0, heading_deg = 0, pitch_deg = 0, roll_deg = 0;
  int rounds = 0;
  double fuel_l = 0;
  std::string label;   // e.g. "TANK1 M1A1"
  std::string camera;  // the camera mode shown ("driver", "chase", "orbit", "map", "outside"); "" = none
};

// What to draw. ents / fixed_state may be a past copy (a ring buffer of world states) or the
// world's own arrays; null = the world's own. fixed_state[i] is the damage state of fixed object i.
struct SceneView {
  const world::World* world = nullptr;
  const world::Entities* ents = nullptr;
  const std::vector<uint8_t>* fixed_state = nullptr;
  double t = 0;      // scenario time of this state, s (drives the particle effects)
  int driven = -1;   // entity index of the driven vehicle (HUD, white map dot, view triangle)
};

struct FrameStats {
  int terrain_chunks_drawn = 0, terrain_chunks_culled = 0;
  int64_t terrain_triangles = 0;
  int blocks_visible = 0, blocks_culled = 0;
  int64_t objects_full = 0, objects_simple = 0, object_triangles = 0;
  int particles = 0;
};

class Renderer {
 public:
  // Throws std::runtime_error with a message (no GL context, frame too large, missing or broken
  // shader file named with its line, a model without faces).
  explicit Renderer(const RenderOptions& opt, const world::World& world);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The heightfield changed inside `r` (a crater): rebuild that patch of the mesh and the map.
  void terrain_changed(const world::PostRect& r);
  // Effects start at scenario time t; an explosion of scale 1 is a tank round (fireball ~8 m).
  void add_explosion(const Vec3& at, double t, float scale);
  void add_fire(const Vec3& at, double t, double seconds);
  // A crater of `radius_m` at `at` from scenario time t on: a scorched disc laid on the terrain
  // (on coarse terrain a crater moves few posts, so the lowered mesh alone hardly shows it).
  void add_crater(const Vec3& at, double radius_m, double t);

  void render(const SceneView& view, const Camera& cam, const Hud& hud, bool map_inset = true);
  // PNG of the last frame (rows flipped: GL is bottom-up), written to a temporary name and
  // renamed onto `file` (never a partial PNG). False (nothing written; the reason in *why) on failure.
  bool write_png(const std::filesystem::path& file, std::string* why = nullptr) const;
  std::vector<uint8_t> pixels() const;  // RGBA, width * height * 4, top row first

  int width() const;
  int height() const;
  const FrameStats& stats() const;
  const std::string& gl_description() const;  // context kind, GL version, renderer
  bool window_should_close() const;           // the user closed the window
  void* native_window() const;                // the GLFWwindow* with RenderOptions::window, else null
  void wait_events(double timeout_s);         // window: handle input events for up to timeout_s
  const TerrainMesh& terrain_mesh() const;    // for tests

 private:
  struct Impl;
  std::unique_ptr<Impl> p_;
};

// A camera placed to see both points (an imminent/result snapshot): to the side of the pair,
// above it and above the terrain, with a clear line of sight where the terrain allows.
Camera look_at_pair(const world::World& w, const Vec3& a, const Vec3& b);
// The view from a vehicle: eye `eye_height_m` above its ground contact, looking along its heading
// (compass degrees) and pitch (nose up, degrees).
Camera vehicle_eye(const Vec3& pos, double heading_deg, double pitch_deg, double eye_height_m);

}  // namespace npsnet::render
