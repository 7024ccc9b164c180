// Input errors carry a place: FILE:LINE: field: message (the `npsnet check` format).
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

namespace npsnet::world {

struct Problem {
  std::string file;
  int line = 0;  // 0 when the problem is about the file as a whole
  std::string field;
  std::string message;
  std::string str() const {
    return file + ":" + std::to_string(line) + ": " + field + ": " + message;
  }
};

// Thrown by loaders; holds every problem found (a loader collects, then throws once).
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<Problem> problems)
      : std::runtime_error(join(problems)), problems_(std::move(problems)) {}
  InputError(std::string file, int line, std::string field, std::string message)
      : InputError(std::vector<Problem>{{std::move(file), line, std::move(field), std::move(message)}}) {}
  const std::vector<Problem>& problems() const { return problems_; }

 private:
  static std::string join(const std::vector<Problem>& ps) {
    std::string s;
    for (const auto& p : ps) {  // appends: GCC 12 warns (falsely) on "literal" + std::string
      if (!s.empty()) s += '\n';
      s += p.str();
    }
    return s;
  }
  std::vector<Problem> problems_;
};

}  // namespace npsnet::world
