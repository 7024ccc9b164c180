#include "world/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "world/error.hpp"

namespace npsnet::world {

std::string read_text_file(const std::filesystem::path& file, const std::string& field) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), 0, field, std::string("cannot open file: ") + std::strerror(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError(file.string(), 0, field, "cannot read file");
  return std::move(ss).str();
}

bool file_exists(const std::filesystem::path& file) noexcept {
  std::error_code ec;
  return std::filesystem::exists(file, ec) && !ec;
}

}  // namespace npsnet::world
