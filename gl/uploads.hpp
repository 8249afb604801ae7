// Upload and vertex-format helpers shared by the passes: textures from images, buffers from
// vectors, vertex attributes. Needs a current GL context.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/objects.hpp"

namespace clothlab::vis {

// Anisotropic filtering (8x) on a GPU; 1 (trilinear only) on Mesa's llvmpipe.
float max_anisotropy();

// A mipmapped 2D texture of width x height RGBA8 pixels (row 0 first): sRGB and repeating
// (albedo) or linear (normal maps, masks). vis/textures/image_texture.hpp takes an Image.
Texture upload_rgba_texture(int width, int height, const std::uint8_t* rgba, bool srgb);

// Attribute `index` of `vao`: `components` floats from binding `binding`.
void float_attribute(GLuint vao, GLuint index, GLuint binding, int components);

// An immutable buffer holding `data` (at least one byte, so an empty vector is a valid buffer).
template <class T>
Buffer static_buffer(const std::vector<T>& data, GLbitfield flags = 0) {
  Buffer b = make_buffer();
  glNamedBufferStorage(b.get(),
                       static_cast<GLsizeiptr>(std::max<std::size_t>(1, data.size() * sizeof(T))),
                       data.empty() ? nullptr : data.data(), flags);
  return b;
}

// A buffer of `floats` floats (at least one) that glNamedBufferSubData updates.
Buffer dynamic_float_buffer(std::size_t floats);

}  // namespace clothlab::vis
