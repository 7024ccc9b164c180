// A GL core-profile context to draw in: OSMesa off-screen (llvmpipe in system memory, no display
// needed, GLFW never touched) or a GLFW window. Either way the renderer draws into its own
// framebuffer object of the frame size; a window context then blits it to the window and swaps.
#pragma once
#include <memory>
#include <string>

namespace npsnet::render {

class GlContext {
 public:
  virtual ~GlContext() = default;
  virtual void make_current() = 0;      // also loads the GL function table for this context kind
  virtual void present(unsigned fbo, int w, int h) = 0;  // window: blit + swap; off-screen: nothing
  virtual bool is_window() const = 0;
  virtual bool should_close() const { return false; }
  virtual void* native_window() const { return nullptr; }  // GLFWwindow* of a window context
  virtual void wait_events(double /*timeout_s*/) {}          // window: handle input until then
  std::string description;              // "OSMesa GL 4.5 (Core Profile) Mesa ... llvmpipe"
};

// Throws std::runtime_error when no context can be made (with what was tried).
std::unique_ptr<GlContext> make_osmesa_context();
// Throws std::runtime_error when GLFW cannot start or open a window (e.g. no display).
std::unique_ptr<GlContext> make_glfw_context(int width, int height, const std::string& title);

// How many times this process called glfwInit (tests check a headless run never does).
int glfw_init_calls();

}  // namespace npsnet::render
