#include "vis/textures/image.hpp"

#include <png.h>
#include <stb/stb_image.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
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

namespace {

// libpng reports errors by longjmp to png_jmpbuf: everything that must be released is set up
// before that point and released on both paths.
bool encode_png(std::FILE* file, const Image& image, PngCompression compression) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  const bool fast = compression == PngCompression::fast;
  png_set_compression_level(png, fast ? 1 : 9);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, fast ? PNG_FILTER_SUB : PNG_ALL_FILTERS);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB_ALPHA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) png_write_row(png, image.at(0, y));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void write_png(const Image& image, const std::string& path, PngCompression compression) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4) {
    throw std::runtime_error("write_png: invalid image for '" + path + "'");
  }
  const std::string tmp = path + ".tmp";
  const TempFileGuard guard(tmp);  // removed on SIGINT / SIGTERM too
  errno = 0;
  std::FILE* file = std::fopen(tmp.c_str(), "wb");
  bool ok = file && encode_png(file, image, compression);
  if (file) ok = std::fclose(file) == 0 && ok;
  if (!ok) {
    const int why = errno;     // ENOSPC on a full disk
    std::remove(tmp.c_str());  // a write that failed midway leaves a partial file
    throw std::runtime_error("write_png: cannot write '" + path + "'" +
                             (why ? std::string(": ") + std::strerror(why) : std::string()));
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
