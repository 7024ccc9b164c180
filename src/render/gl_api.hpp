// The GL core-profile functions the renderer uses, as pointers loaded at run time from the
// current context's loader (OSMesaGetProcAddress or glfwGetProcAddress). Nothing in src/render
// calls a gl* symbol directly: libOSMesa and libGL both export them, and only the loader of the
// context in use returns the right ones.
#pragma once
#include <GL/glcorearb.h>

#include <cstddef>
#include <string>

// GL 1.1 entry points that Mesa's glcorearb.h declares without PFN typedefs.
using NpsPfnPolygonOffset = void(APIENTRYP)(GLfloat factor, GLfloat units);
using NpsPfnDrawArrays = void(APIENTRYP)(GLenum mode, GLint first, GLsizei count);
using NpsPfnGenTextures = void(APIENTRYP)(GLsizei n, GLuint* textures);
using NpsPfnDeleteTextures = void(APIENTRYP)(GLsizei n, const GLuint* textures);
using NpsPfnBindTexture = void(APIENTRYP)(GLenum target, GLuint texture);
using NpsPfnTexSubImage2D = void(APIENTRYP)(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width,
                                            GLsizei height, GLenum format, GLenum type, const void* pixels);

#define NPSNET_GL_FUNCS(X)                                              \
  X(PFNGLGETSTRINGPROC, GetString)                                      \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                                  \
  X(PFNGLGETERRORPROC, GetError)                                        \
  X(PFNGLVIEWPORTPROC, Viewport)                                        \
  X(PFNGLCLEARCOLORPROC, ClearColor)                                    \
  X(PFNGLCLEARPROC, Clear)                                              \
  X(PFNGLENABLEPROC, Enable)                                            \
  X(PFNGLDISABLEPROC, Disable)                                          \
  X(PFNGLDEPTHMASKPROC, DepthMask)                                      \
  X(PFNGLCOLORMASKPROC, ColorMask)                                      \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                                      \
  X(PFNGLBLENDFUNCPROC, BlendFunc)                                      \
  X(PFNGLCULLFACEPROC, CullFace)                                        \
  X(PFNGLFRONTFACEPROC, FrontFace)                                      \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                                  \
  X(PFNGLREADPIXELSPROC, ReadPixels)                                    \
  X(PFNGLFINISHPROC, Finish)                                            \
  X(PFNGLLINEWIDTHPROC, LineWidth)                                      \
  X(NpsPfnPolygonOffset, PolygonOffset)                              \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                    \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                              \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                                    \
  X(PFNGLBUFFERDATAPROC, BufferData)                                    \
  X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                              \
  X(PFNGLGETBUFFERSUBDATAPROC, GetBufferSubData)                        \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                          \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                    \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                          \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)          \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                  \
  X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor)                  \
  X(NpsPfnDrawArrays, DrawArrays)                                    \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)                  \
  X(PFNGLDRAWELEMENTSBASEVERTEXPROC, DrawElementsBaseVertex)            \
  X(PFNGLCREATESHADERPROC, CreateShader)                                \
  X(PFNGLDELETESHADERPROC, DeleteShader)                                \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                                \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                              \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                                  \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                        \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                              \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                              \
  X(PFNGLATTACHSHADERPROC, AttachShader)                                \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                                  \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                      \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                    \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                    \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                      \
  X(PFNGLUNIFORM1FPROC, Uniform1f)                                      \
  X(PFNGLUNIFORM2FPROC, Uniform2f)                                      \
  X(PFNGLUNIFORM3FPROC, Uniform3f)                                      \
  X(PFNGLUNIFORM4FPROC, Uniform4f)                                      \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                        \
  X(NpsPfnGenTextures, GenTextures)                                  \
  X(NpsPfnDeleteTextures, DeleteTextures)                            \
  X(NpsPfnBindTexture, BindTexture)                                  \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                              \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                    \
  X(NpsPfnTexSubImage2D, TexSubImage2D)                              \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                              \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                          \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                    \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                          \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)          \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)            \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                        \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                  \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                        \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                  \
  X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)

namespace npsnet::render::gl {

#define NPSNET_GL_DECLARE(T, name) extern T name;
NPSNET_GL_FUNCS(NPSNET_GL_DECLARE)
#undef NPSNET_GL_DECLARE

using ProcLoader = void* (*)(const char* name);

// Loads every pointer above through `loader` for the context kind `tag` (a no-op when that kind
// is already loaded). Throws std::runtime_error naming the first function the context lacks.
void load(ProcLoader loader, int tag);

// "GL_INVALID_OPERATION" etc. for messages.
std::string error_name(unsigned err);

// Binds `vbo` (GL_ARRAY_BUFFER) and writes `bytes` of `data` at its start; past `capacity`
// (bytes, updated) the buffer is first remade at twice that, or `bytes` if more (stream draw).
void stream_to_buffer(unsigned vbo, const void* data, size_t bytes, size_t& capacity);

}  // namespace npsnet::render::gl
