// Upload and vertex-format helpers shared by the passes: textures from images, buffers from
// vectors, vertex attributes. Needs a current GL context.
#pragma once

#include <cstddef>
#include <vector>

#include "vis/gl/objects.hpp"

namespace clothlab {
struct Image;
}  // namespace clothlab

namespace clothlab::vis {

// Anisotropic filtering (8x) on a GPU; 1 (trilinear only) on Mesa's llvmpipe.
float max_anisotropy();

// A mipmapped, repeating 2D texture of `image`: sRGB (albedo) or linear (normal maps, masks).
Texture upload_texture(const Image& image, bool srgb = true);

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
