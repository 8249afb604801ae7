// RGBA8 images for the procedural textures, and PNG input through stb (Debian libstb) and output
// through libpng (Debian libpng, which lets each write choose its compression).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace clothlab {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // 4 bytes per pixel, row-major, row 0 = top

  Image() = default;
  // A width x height image, all bytes zero. Throws std::invalid_argument unless both are > 0.
  Image(int w, int h);

  // First of the 4 bytes of pixel (x, y); no bounds check beyond the vector's own.
  std::uint8_t* at(int x, int y) { return rgba.data() + 4 * (std::size_t(y) * width + x); }
  const std::uint8_t* at(int x, int y) const {
    return rgba.data() + 4 * (std::size_t(y) * width + x);
  }
  // Stores a colour given in [0, 1] per channel (clamped, rounded); alpha is opaque.
  void set_rgb(int x, int y, float r, float g, float b);
};

// How hard a PNG write compresses: `fast` for working files (rendered frames, screenshots: zlib
// level 1 and the Sub filter, 5x faster than stb_image_write's default on a 1280x720 frame, and
// smaller), `small` for files kept in the repository (goldens: level 9, every filter tried).
enum class PngCompression { fast, small };

// Writes `path + ".tmp"` and renames it to `path`, so the file is either complete or absent.
// Throws std::runtime_error naming the path on any failure (nothing is left behind).
void write_png(const Image& image, const std::string& path,
               PngCompression compression = PngCompression::fast);

// Reads any image stb understands, converted to 4 channels. Throws std::runtime_error naming
// the path when the file is missing or not a readable image.
Image read_png(const std::string& path);

// Stateless 32-bit integer hash ("lowbias32", Chris Wellons, "Prospecting for Hash Functions",
// 2018): the seeded per-thread and per-tile variations of the textures come from it, so the
// same seed gives the same bytes on every run and platform.
constexpr std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// Hash of (seed, a, b, c) mapped to [0, 1).
constexpr float hash_unit(std::uint32_t seed, std::uint32_t a, std::uint32_t b = 0,
                          std::uint32_t c = 0) {
  const std::uint32_t h = hash32(seed ^ hash32(a ^ hash32(b ^ hash32(c + 0x9e3779b9U))));
  return float(h >> 8) * (1.0f / 16777216.0f);
}

}  // namespace clothlab
