// PNG output (stb_image_write from libstb-dev; its implementation lives in this file only).
// The PNG is encoded in memory, written to a temporary name in the same folder and renamed
// onto `file`, so a process killed at any moment leaves either no file or a whole PNG.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <system_error>

#include "render/renderer.hpp"

namespace npsnet::render {

namespace {
// Writes all of `data` to `file` (created or truncated); "" or the reason it failed.
std::string write_all(const std::filesystem::path& file, const unsigned char* data, size_t n) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return std::strerror(errno);
  std::string err;
  for (size_t done = 0; done < n && err.empty();) {
    const ssize_t w = ::write(fd, data + done, n - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) err = w < 0 ? std::strerror(errno) : "short write";
    else done += static_cast<size_t>(w);
  }
  if (::close(fd) != 0 && err.empty()) err = std::strerror(errno);
  return err;
}
}  // namespace

bool Renderer::write_png(const std::filesystem::path& file, std::string* why) const {
  auto fail = [&](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  const std::vector<uint8_t> px = pixels();
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  int len = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> png(
      stbi_write_png_to_mem(px.data(), width() * 4, width(), height(), 4, &len), std::free);
  if (!png || len <= 0) return fail("cannot encode the PNG");
  std::filesystem::path tmp = file;
  tmp += ".tmp-" + std::to_string(::getpid());
  if (std::string e = write_all(tmp, png.get(), static_cast<size_t>(len)); !e.empty()) {
    std::filesystem::remove(tmp, ec);
    return fail(e);
  }
  if (std::rename(tmp.c_str(), file.c_str()) != 0) {
    const std::string e = std::strerror(errno);
    std::filesystem::remove(tmp, ec);
    return fail(e);
  }
  return true;
}

}  // namespace npsnet::render
