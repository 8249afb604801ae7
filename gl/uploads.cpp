#include "gl/uploads.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace clothlab::vis {

// On Mesa's llvmpipe (the CPU rasteriser of CI and headless renders) trilinear only: its
// anisotropic sampler can spend minutes on one frame (the drop_sphere scene at 1280x720: 0.3 s
// frames, then one of 210 s with the time in the JIT-compiled fragment code, and 0.29 s with
// anisotropy off), and on a CPU it is the dearest sampling anyway.
float max_anisotropy() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer && std::strstr(renderer, "llvmpipe") ? 1.0f : 8.0f;
}

Texture upload_rgba_texture(int width, int height, const std::uint8_t* rgba, bool srgb) {
  Texture t = make_texture(GL_TEXTURE_2D);
  const int levels = 1 + static_cast<int>(std::log2(std::max(width, height)));
  glTextureStorage2D(t.get(), levels, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, width, height);
  glTextureSubImage2D(t.get(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glGenerateTextureMipmap(t.get());
  glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  if (srgb) {
    glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  }
  glTextureParameterf(t.get(), GL_TEXTURE_MAX_ANISOTROPY, max_anisotropy());
  return t;
}

Texture srgb_table_texture(const std::uint8_t* rgb, const std::string& label) {
  Texture t = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(t.get(), 1, GL_SRGB8, 256, 1);
  // One row of tightly packed 3-byte texels: the unpack alignment, which only spaces rows, does
  // not matter.
  glTextureSubImage2D(t.get(), 0, 0, 0, 256, 1, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glObjectLabel(GL_TEXTURE, t.get(), -1, label.c_str());
  return t;
}

void float_attribute(GLuint vao, GLuint index, GLuint binding, int components, std::size_t offset) {
  glEnableVertexArrayAttrib(vao, index);
  glVertexArrayAttribFormat(vao, index, components, GL_FLOAT, GL_FALSE,
                            static_cast<GLuint>(offset));
  glVertexArrayAttribBinding(vao, index, binding);
}

void vertex_buffer(GLuint vao, GLuint binding, GLuint buffer, std::size_t offset,
                   std::size_t stride) {
  glVertexArrayVertexBuffer(vao, binding, buffer, static_cast<GLintptr>(offset),
                            static_cast<GLsizei>(stride));
}

void element_buffer(GLuint vao, GLuint buffer) {
  glVertexArrayElementBuffer(vao, buffer);
}

Buffer dynamic_float_buffer(std::size_t floats) {
  return dynamic_buffer(std::max<std::size_t>(1, floats) * sizeof(float));
}

Buffer dynamic_buffer(std::size_t bytes) {
  Buffer b = make_buffer();
  glNamedBufferStorage(b.get(), static_cast<GLsizeiptr>(std::max<std::size_t>(1, bytes)), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  return b;
}

void update_buffer(GLuint buffer, const void* data, std::size_t bytes, std::size_t offset) {
  glNamedBufferSubData(buffer, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void bind_uniform_buffer(GLuint index, GLuint buffer) {
  glBindBufferBase(GL_UNIFORM_BUFFER, index, buffer);
}

}  // namespace clothlab::vis
