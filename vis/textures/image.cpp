#include "vis/textures/image.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "sim/core/temp_files.hpp"

namespace clothlab {

Image::Image(int w, int h) : width(w), height(h) {
  if (w <= 0 || h <= 0) {
    throw std::invalid_argument("Image: size must be positive, got " + std::to_string(w) + "x" +
                                std::to_string(h));
  }
  rgba.assign(std::size_t(w) * std::size_t(h) * 4, 0);
}

void Image::set_rgb(int x, int y, float r, float g, float b) {
  const auto to_byte = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  std::uint8_t* p = at(x, y);
  p[0] = to_byte(r);
  p[1] = to_byte(g);
  p[2] = to_byte(b);
  p[3] = 255;
}

void write_png(const Image& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4) {
    throw std::runtime_error("write_png: invalid image for '" + path + "'");
  }
  const std::string tmp = path + ".tmp";
  const TempFileGuard guard(tmp);  // removed on SIGINT / SIGTERM too
  const int ok =
      stbi_write_png(tmp.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4);
  if (!ok) {
    std::remove(tmp.c_str());  // stb may leave a partial file when a write fails midway
    throw std::runtime_error("write_png: cannot write '" + path + "'");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("write_png: cannot rename '" + tmp + "' to '" + path + "'");
  }
}

Image read_png(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (!data) {
    const char* reason = stbi_failure_reason();
    throw std::runtime_error("read_png: cannot read '" + path + "'" +
                             (reason ? std::string(": ") + reason : std::string()));
  }
  Image image;
  image.width = w;
  image.height = h;
  image.rgba.assign(data, data + std::size_t(w) * std::size_t(h) * 4);
  stbi_image_free(data);
  return image;
}

}  // namespace clothlab
