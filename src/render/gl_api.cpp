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

void stream_to_buffer(unsigned vbo, const void* data, size_t bytes, size_t& capacity) {
  BindBuffer(GL_ARRAY_BUFFER, vbo);
  if (bytes > capacity) {
    capacity = bytes > 2 * capacity ? bytes : 2 * capacity;
    BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity), nullptr, GL_STREAM_DRAW);
  }
  BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
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
