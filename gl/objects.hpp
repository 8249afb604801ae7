// Move-only RAII owners of GL objects (docs/style.md: "GL objects are move-only RAII types under
// gl/"). Each wraps one name and deletes it with the matching glDelete* call.
#pragma once

#include <utility>

#include "gl/gl.hpp"

namespace clothlab::vis {

template <void (*Delete)(GLuint)>
class GlName {
 public:
  GlName() = default;
  explicit GlName(GLuint name) : name_(name) {}
  GlName(GlName&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  GlName& operator=(GlName&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;
  ~GlName() { reset(); }

  GLuint get() const { return name_; }
  explicit operator bool() const { return name_ != 0; }
  void reset() {
    if (name_) Delete(name_);
    name_ = 0;
  }

 private:
  GLuint name_ = 0;
};

namespace detail {
inline void delete_buffer(GLuint n) {
  glDeleteBuffers(1, &n);
}
inline void delete_vertex_array(GLuint n) {
  glDeleteVertexArrays(1, &n);
}
inline void delete_texture(GLuint n) {
  glDeleteTextures(1, &n);
}
inline void delete_framebuffer(GLuint n) {
  glDeleteFramebuffers(1, &n);
}
inline void delete_renderbuffer(GLuint n) {
  glDeleteRenderbuffers(1, &n);
}
inline void delete_program(GLuint n) {
  glDeleteProgram(n);
}
inline void delete_shader(GLuint n) {
  glDeleteShader(n);
}
inline void delete_sampler(GLuint n) {
  glDeleteSamplers(1, &n);
}
inline void delete_transform_feedback(GLuint n) {
  glDeleteTransformFeedbacks(1, &n);
}
}  // namespace detail

using Buffer = GlName<detail::delete_buffer>;
using VertexArray = GlName<detail::delete_vertex_array>;
using Texture = GlName<detail::delete_texture>;
using Framebuffer = GlName<detail::delete_framebuffer>;
using Renderbuffer = GlName<detail::delete_renderbuffer>;
using Program = GlName<detail::delete_program>;
using Shader = GlName<detail::delete_shader>;
using Sampler = GlName<detail::delete_sampler>;
using TransformFeedback = GlName<detail::delete_transform_feedback>;

// Creation helpers (direct state access, GL 4.5): one name from glCreate*(args..., 1, &name).
template <class Name, class Create, class... Args>
Name create_one(Create create, Args... args) {
  GLuint n = 0;
  create(args..., 1, &n);
  return Name(n);
}
inline Buffer make_buffer() {
  return create_one<Buffer>(glCreateBuffers);
}
inline VertexArray make_vertex_array() {
  return create_one<VertexArray>(glCreateVertexArrays);
}
inline Texture make_texture(GLenum target) {
  return create_one<Texture>(glCreateTextures, target);
}
inline Framebuffer make_framebuffer() {
  return create_one<Framebuffer>(glCreateFramebuffers);
}
inline Renderbuffer make_renderbuffer() {
  return create_one<Renderbuffer>(glCreateRenderbuffers);
}
inline Sampler make_sampler() {
  return create_one<Sampler>(glCreateSamplers);
}
inline TransformFeedback make_transform_feedback() {
  return create_one<TransformFeedback>(glCreateTransformFeedbacks);
}

}  // namespace clothlab::vis
