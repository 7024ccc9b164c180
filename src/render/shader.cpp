#include "render/shader.hpp"

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "render/gl_api.hpp"

namespace npsnet::render {
namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ":0: shader: file not found or unreadable");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

unsigned compile(GLenum type, const std::filesystem::path& file) {
  const std::string src = read_text(file);
  const unsigned sh = gl::CreateShader(type);
  const char* p = src.c_str();
  const int len = static_cast<int>(src.size());
  gl::ShaderSource(sh, 1, &p, &len);
  gl::CompileShader(sh);
  int ok = 0;
  gl::GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    int n = 0;
    gl::GetShaderiv(sh, GL_INFO_LOG_LENGTH, &n);
    std::string log(static_cast<size_t>(std::max(n, 1)), '\0');
    gl::GetShaderInfoLog(sh, n, nullptr, log.data());
    gl::DeleteShader(sh);
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    throw std::runtime_error(file.string() + ":" + std::to_string(glsl_log_line(log)) +
                             ": shader: GLSL compile error: " + log);
  }
  return sh;
}

}  // namespace

int glsl_log_line(const std::string& log) {
  static const std::regex mesa(R"((?:^|\n)\s*\d+:(\d+)\(\d+\))");
  static const std::regex other(R"((?:^|\n)\s*(?:ERROR:\s*)?\d+[:(](\d+)\)?\s*:)");
  std::smatch m;
  if (std::regex_search(log, m, mesa)) return std::stoi(m[1]);
  if (std::regex_search(log, m, other)) return std::stoi(m[1]);
  return 0;
}

Program::Program(const std::filesystem::path& dir, const std::string& name) {
  const auto vf = dir / (name + ".vert");
  const auto ff = dir / (name + ".frag");
  const unsigned vs = compile(GL_VERTEX_SHADER, vf);
  unsigned fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, ff);
  } catch (...) {
    gl::DeleteShader(vs);
    throw;
  }
  id_ = gl::CreateProgram();
  gl::AttachShader(id_, vs);
  gl::AttachShader(id_, fs);
  gl::LinkProgram(id_);
  gl::DeleteShader(vs);
  gl::DeleteShader(fs);
  int ok = 0;
  gl::GetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    int n = 0;
    gl::GetProgramiv(id_, GL_INFO_LOG_LENGTH, &n);
    std::string log(static_cast<size_t>(std::max(n, 1)), '\0');
    gl::GetProgramInfoLog(id_, n, nullptr, log.data());
    gl::DeleteProgram(id_);
    id_ = 0;
    throw std::runtime_error(vf.string() + " + " + ff.string() + ":0: shader: GLSL link error: " + log);
  }
}

Program::~Program() {
  if (id_ && gl::DeleteProgram) gl::DeleteProgram(id_);
}

Program& Program::operator=(Program&& o) noexcept {
  if (this != &o) {
    if (id_) gl::DeleteProgram(id_);
    id_ = o.id_;
    o.id_ = 0;
  }
  return *this;
}

void Program::use() const { gl::UseProgram(id_); }
int Program::loc(const char* uniform) const { return gl::GetUniformLocation(id_, uniform); }

}  // namespace npsnet::render
