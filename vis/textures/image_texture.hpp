// An Image as a GL texture: the GL layer (gl/uploads.hpp) takes raw pixels and knows no Image.
#pragma once

#include "gl/uploads.hpp"
#include "vis/textures/image.hpp"

namespace clothlab::vis {

// A mipmapped texture of `image`: sRGB and repeating (albedo) or linear (normal maps, masks).
inline Texture upload_texture(const Image& image, bool srgb = true) {
  return upload_rgba_texture(image.width, image.height, image.rgba.data(), srgb);
}

}  // namespace clothlab::vis
