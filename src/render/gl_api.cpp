#include "render/gl_api.hpp"

#include <stdexcept>

namespace npsnet::render::gl {

#define NPSNET_GL_DEFINE(T, name) T name = nullptr;
NPSNET_GL_FUNCS(NPSNET_GL_DEFINE)
#undef NPSNET_GL_DEFINE

namespace {
int g_loaded_tag = -1;
}

void load(ProcLoader loader, int tag) {
  if (tag == g_loaded_tag) return;
#define NPSNET_GL_LOAD(T, name)                                                          \
  name = reinterpret_cast<T>(loader("gl" #name));                                        \
  if (!name) {                                                                           \
    g_loaded_tag = -1;                                                                   \
    throw std::runtime_error("render: the GL context has no function gl" #name);         \
  }
  NPSNET_GL_FUNCS(NPSNET_GL_LOAD)
#undef NPSNET_GL_LOAD
  g_loaded_tag = tag;
}

std::string error_name(unsigned err) {
  switch (err) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "GL error " + std::to_string(err);
  }
}

}  // namespace npsnet::render::gl
