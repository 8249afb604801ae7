// Upload and vertex-format helpers shared by the passes: textures from images, buffers from
// vectors, vertex attributes. Needs a current GL context.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "gl/objects.hpp"

namespace clothlab::vis {

// Anisotropic filtering (8x) on a GPU; 1 (trilinear only) on Mesa's llvmpipe.
float max_anisotropy();

// A mipmapped 2D texture of width x height RGBA8 pixels (row 0 first): sRGB and repeating
// (albedo) or linear (normal maps, masks). vis/textures/image_texture.hpp takes an Image.
Texture upload_rgba_texture(int width, int height, const std::uint8_t* rgba, bool srgb);

// A 256 x 1 sRGB texture of 256 RGB8 texels (a colour map's table): linear filtering, clamped,
// labelled `label` for GL debuggers.
Texture srgb_table_texture(const std::uint8_t* rgb, const std::string& label);

// Attribute `index` of `vao`: `components` floats from binding `binding`, `offset` bytes into
// each element.
void float_attribute(GLuint vao, GLuint index, GLuint binding, int components,
                     std::size_t offset = 0);
// Binding `binding` of `vao` reads `buffer` from byte `offset` in elements of `stride` bytes.
void vertex_buffer(GLuint vao, GLuint binding, GLuint buffer, std::size_t offset,
                   std::size_t stride);
// `vao`'s index buffer.
void element_buffer(GLuint vao, GLuint buffer);
// Where 32-bit index `first` of the bound index buffer starts, as glDrawElements takes it.
inline const void* element_offset(std::size_t first) {
  return reinterpret_cast<const void*>(first * sizeof(std::uint32_t));
}

// An immutable buffer holding `data` (at least one byte, so an empty vector is a valid buffer).
template <class T>
Buffer static_buffer(const std::vector<T>& data, GLbitfield flags = 0) {
  Buffer b = make_buffer();
  glNamedBufferStorage(b.get(),
                       static_cast<GLsizeiptr>(std::max<std::size_t>(1, data.size() * sizeof(T))),
                       data.empty() ? nullptr : data.data(), flags);
  return b;
}

// A buffer of `floats` floats (at least one) that update_buffer() fills.
Buffer dynamic_float_buffer(std::size_t floats);
// A buffer of `bytes` bytes (at least one) that update_buffer() fills.
Buffer dynamic_buffer(std::size_t bytes);
// Writes `bytes` bytes of `data` into a dynamic buffer at byte `offset`.
void update_buffer(GLuint buffer, const void* data, std::size_t bytes, std::size_t offset = 0);
template <class T>
void update_buffer(GLuint buffer, const std::vector<T>& data) {
  update_buffer(buffer, data.data(), data.size() * sizeof(T));
}
// Binds `buffer` to uniform block binding `index`.
void bind_uniform_buffer(GLuint index, GLuint buffer);

}  // namespace clothlab::vis
