// Each tile is a flat stone with its own seeded tone and tint, a faint mottling from periodic
// value noise, a slightly darkened bevel towards its edges, and a grout line around it. All
// noise lattices wrap at the texture edge, so the texture repeats without seams.
#include "vis/textures/floor_texture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace clothlab {
namespace {

using Rgb = std::array<float, 3>;

constexpr Rgb kLightStone{0.74f, 0.73f, 0.70f};
constexpr Rgb kDarkStone{0.44f, 0.44f, 0.45f};
constexpr Rgb kGrout{0.24f, 0.23f, 0.22f};
constexpr float kGroutHalfWidth = 0.025f;    // per side, as a fraction of a tile
constexpr float kMinGroutHalfPixels = 0.6f;  // so small textures still show a grout line
constexpr float kBevelWidth = 0.06f;         // darkening ramp inside the grout, fraction of a tile
constexpr std::uint32_t kToneTag = 1, kTintTag = 2, kNoiseTag = 3;

float clamped_smoothstep(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

int wrap(int i, int period) {
  return ((i % period) + period) % period;
}

// Value noise (Perlin, "An Image Synthesizer", SIGGRAPH 1985, with values rather than
// gradients at the lattice): hashed values on a `period` x `period` lattice that wraps, blended
// with smoothstep. u, v are in lattice cells, in [0, period). Result in [0, 1).
float periodic_value_noise(float u, float v, int period, std::uint32_t seed) {
  const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
  const float tu = clamped_smoothstep(u - float(i0)), tv = clamped_smoothstep(v - float(j0));
  const auto at = [&](int i, int j) {
    return hash_unit(seed, kNoiseTag, std::uint32_t(wrap(i, period)),
                     std::uint32_t(wrap(j, period)) + std::uint32_t(period) * 7919U);
  };
  const float top = at(i0, j0) + (at(i0 + 1, j0) - at(i0, j0)) * tu;
  const float bottom = at(i0, j0 + 1) + (at(i0 + 1, j0 + 1) - at(i0, j0 + 1)) * tu;
  return top + (bottom - top) * tv;
}

// Two octaves of mottling in [-1, 1); the lattices (8 and 32 cells across the texture) are
// multiples of the tile count so each wraps at the texture edge.
float mottling(float u, float v, std::uint32_t seed) {
  const float coarse = periodic_value_noise(u * 8.0f, v * 8.0f, 8, seed);
  const float fine = periodic_value_noise(u * 32.0f, v * 32.0f, 32, seed);
  return 2.0f * (0.7f * coarse + 0.3f * fine) - 1.0f;
}

Rgb tile_colour(int tx, int ty, std::uint32_t seed) {
  const Rgb base = (tx + ty) % 2 == 0 ? kLightStone : kDarkStone;
  const auto id = std::uint32_t(ty * kFloorTiles + tx);
  const float tone = 0.93f + 0.14f * hash_unit(seed, kToneTag, id);   // +-7 % per tile
  const float warm = 0.02f * (hash_unit(seed, kTintTag, id) - 0.5f);  // slight warm/cool tint
  return {base[0] * tone + warm, base[1] * tone, base[2] * tone - warm};
}

}  // namespace

Image make_floor_texture(int size, std::uint32_t seed) {
  if (size < 1) throw std::invalid_argument("make_floor_texture: size " + std::to_string(size));
  Image image(size, size);
  // Grout straddles every tile edge, the texture's own included, so tiled copies meet in the
  // middle of a grout line; at least ~1 pixel per side keeps the line at small sizes.
  const float tile_pixels = float(size) / kFloorTiles;
  const float grout = std::max(kGroutHalfWidth, kMinGroutHalfPixels / tile_pixels);
  for (int y = 0; y < size; ++y) {
    const float v = (float(y) + 0.5f) / float(size);  // texture coordinate in [0, 1)
    const float tv = v * kFloorTiles;
    const int ty = static_cast<int>(tv);
    const float fy = tv - float(ty);
    for (int x = 0; x < size; ++x) {
      const float u = (float(x) + 0.5f) / float(size);
      const float tu = u * kFloorTiles;
      const int tx = static_cast<int>(tu);
      const float fx = tu - float(tx);

      // Distance to the nearest tile edge, in tiles; grout within `grout` of it.
      const float edge = std::min(std::min(fx, 1.0f - fx), std::min(fy, 1.0f - fy));
      const float m = mottling(u, v, seed);
      Rgb c;
      if (edge < grout) {
        const float g = 1.0f + 0.08f * m;
        c = {kGrout[0] * g, kGrout[1] * g, kGrout[2] * g};
      } else {
        const Rgb stone = tile_colour(tx, ty, seed);
        const float bevel = 0.85f + 0.15f * clamped_smoothstep((edge - grout) / kBevelWidth);
        const float light = bevel * (1.0f + 0.10f * m);
        c = {stone[0] * light, stone[1] * light, stone[2] * light};
      }
      image.set_rgb(x, y, c[0], c[1], c[2]);
    }
  }
  return image;
}

}  // namespace clothlab
