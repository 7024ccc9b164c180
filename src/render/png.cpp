// PNG output (stb_image_write from libstb-dev; its implementation lives in this file only).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <system_error>

#include "render/renderer.hpp"

namespace npsnet::render {

bool Renderer::write_png(const std::filesystem::path& file) const {
  const std::vector<uint8_t> px = pixels();
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  return stbi_write_png(file.string().c_str(), width(), height(), 4, px.data(), width() * 4) != 0;
}

}  // namespace npsnet::render
