// Reading rendered images in the image tests: where a world point lands on screen, and what a
// pixel holds in linear light (the renderer encodes sRGB once, at the end).
#pragma once

#include <cmath>
#include <cstddef>
#include <glm/glm.hpp>

#include "vis/render/view_settings.hpp"

namespace clothlab::testing {

// sRGB value in [0, 1] -> linear (IEC 61966-2-1).
inline double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
inline double srgb_byte_to_linear(int byte) {
  return srgb_to_linear(byte / 255.0);
}

// Screen position of world point p seen by `camera` in a w x h image: pixels, origin at the
// top-left corner, not rounded (the pixel is its floor).
inline glm::vec2 screen_position(const vis::OrbitCamera& camera, int w, int h, glm::vec3 p) {
  const glm::vec4 c = vis::view_projection(camera, w, h) * glm::vec4(p, 1.0f);
  return {(c.x / c.w * 0.5f + 0.5f) * float(w), (0.5f - c.y / c.w * 0.5f) * float(h)};
}

// Index of the first of the 4 bytes of the pixel holding p in RGBA rows (top row first).
inline std::size_t pixel_index(const vis::OrbitCamera& camera, int w, int h, glm::vec3 p) {
  const glm::vec2 s = screen_position(camera, w, h, p);
  const auto x = static_cast<std::size_t>(std::floor(s.x)),
             y = static_cast<std::size_t>(std::floor(s.y));
  return 4 * (y * static_cast<std::size_t>(w) + x);
}

}  // namespace clothlab::testing
