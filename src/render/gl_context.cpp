#include "render/gl_context.hpp"

#include <GL/osmesa.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>
#include <vector>

#include "render/gl_api.hpp"

namespace npsnet::render {
namespace {

constexpr int kTagOsmesa = 1;
constexpr int kTagGlfw = 2;
int g_glfw_init_calls = 0;
int g_glfw_windows = 0;

void* osmesa_proc(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }
void* glfw_proc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

std::string gl_version_string() {
  const auto* v = reinterpret_cast<const char*>(gl::GetString(GL_VERSION));
  const auto* r = reinterpret_cast<const char*>(gl::GetString(GL_RENDERER));
  return std::string(v ? v : "?") + " on " + (r ? r : "?");
}

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext() {
    // Core profile, newest first. The context draws into FBOs; the OSMesa buffer itself is tiny.
    const int versions[][2] = {{4, 5}, {3, 3}};
    for (const auto& v : versions) {
      const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 0,
                             OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                             OSMESA_CONTEXT_MAJOR_VERSION, v[0], OSMESA_CONTEXT_MINOR_VERSION, v[1], 0};
      ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
      if (ctx_) break;
    }
    if (!ctx_) throw std::runtime_error("render: OSMesa could not create a GL 4.5 or 3.3 core-profile context");
    buf_.assign(kBufSide * kBufSide, 0);
    make_current();
    description = "OSMesa " + gl_version_string();
  }
  ~OsmesaContext() override {
    if (ctx_) OSMesaDestroyContext(ctx_);
  }
  void make_current() override {
    if (OSMesaGetCurrentContext() != ctx_ &&
        !OSMesaMakeCurrent(ctx_, buf_.data(), GL_UNSIGNED_BYTE, kBufSide, kBufSide))
      throw std::runtime_error("render: OSMesaMakeCurrent failed");
    gl::load(osmesa_proc, kTagOsmesa);
  }
  void present(unsigned, int, int) override {}
  bool is_window() const override { return false; }

 private:
  static constexpr int kBufSide = 4;
  OSMesaContext ctx_ = nullptr;
  std::vector<uint32_t> buf_;
};

class GlfwContext final : public GlContext {
 public:
  GlfwContext(int w, int h, const std::string& title) {
    ++g_glfw_init_calls;
    if (!glfwInit()) {
      const char* why = nullptr;
      glfwGetError(&why);
      throw std::runtime_error(std::string("render: GLFW cannot start (is there a display? DISPLAY unset?): ") +
                               (why ? why : "unknown error"));
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    win_ = glfwCreateWindow(w, h, title.c_str(), nullptr, nullptr);
    if (!win_) {
      const char* why = nullptr;
      glfwGetError(&why);
      if (g_glfw_windows == 0) glfwTerminate();
      throw std::runtime_error(std::string("render: GLFW cannot open a GL 3.3 core window: ") +
                               (why ? why : "unknown error"));
    }
    ++g_glfw_windows;
    make_current();
    glfwSwapInterval(0);
    description = "GLFW " + gl_version_string();
  }
  ~GlfwContext() override {
    glfwDestroyWindow(win_);
    if (--g_glfw_windows == 0) glfwTerminate();
  }
  void make_current() override {
    if (glfwGetCurrentContext() != win_) glfwMakeContextCurrent(win_);
    gl::load(glfw_proc, kTagGlfw);
  }
  void present(unsigned fbo, int w, int h) override {
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(win_, &fw, &fh);
    gl::BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    gl::BlitFramebuffer(0, 0, w, h, 0, 0, fw, fh, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    gl::BindFramebuffer(GL_FRAMEBUFFER, fbo);
    glfwSwapBuffers(win_);
    glfwPollEvents();
  }
  bool is_window() const override { return true; }
  bool should_close() const override { return glfwWindowShouldClose(win_); }
  void* native_window() const override { return win_; }
  void wait_events(double timeout_s) override {
    if (timeout_s > 0) glfwWaitEventsTimeout(timeout_s);
    else glfwPollEvents();
  }

 private:
  GLFWwindow* win_ = nullptr;
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context() { return std::make_unique<OsmesaContext>(); }
std::unique_ptr<GlContext> make_glfw_context(int w, int h, const std::string& title) {
  return std::make_unique<GlfwContext>(w, h, title);
}
int glfw_init_calls() { return g_glfw_init_calls; }

}  // namespace npsnet::render
