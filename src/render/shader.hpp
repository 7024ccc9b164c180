// GLSL programs loaded at run time from a shader directory (<dir>/<name>.vert and .frag).
// A missing file is an error naming it; a compile error names the file and the line from the
// GLSL log ("shaders/terrain.frag:12: GLSL compile error: ..."); a link error names both files.
#pragma once
#include <filesystem>
#include <string>

namespace npsnet::render {

class Program {
 public:
  Program() = default;
  Program(const std::filesystem::path& dir, const std::string& name);  // throws std::runtime_error
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  Program(Program&& o) noexcept : id_(o.id_) { o.id_ = 0; }
  Program& operator=(Program&& o) noexcept;

  void use() const;
  int loc(const char* uniform) const;  // -1 when the uniform is absent or optimised away
  unsigned id() const { return id_; }

 private:
  unsigned id_ = 0;
};

// First line number found in a GLSL info log ("0:12(3): error" Mesa, "0(12) : error" others); 0 if none.
int glsl_log_line(const std::string& log);

}  // namespace npsnet::render
