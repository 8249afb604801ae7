#include "gl/draw_state.hpp"

#include <cstdio>
#include <cstring>

namespace clothlab::vis {
namespace {

// Notifications are too chatty to print.
void GLAD_API_PTR print_gl_message(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                                   const GLchar* message, const void* prefix) {
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
  std::fprintf(stderr, "%s: GL %s: %s\n", static_cast<const char*>(prefix),
               type == GL_DEBUG_TYPE_ERROR ? "error" : "warning", message);
}

}  // namespace

GLuint bound_draw_framebuffer() {
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  return static_cast<GLuint>(target);
}

void bind_target(GLuint framebuffer, int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
}

void clear_target(const float rgba[4]) {
  glClearBufferfv(GL_COLOR, 0, rgba);
  glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
}

void clear_depth_in(int x, int y, int width, int height, float depth) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, y, width, height);
  glClearBufferfi(GL_DEPTH_STENCIL, 0, depth, 0);
  glDisable(GL_SCISSOR_TEST);
}

void unbind_vertex_array() {
  glBindVertexArray(0);
}

void set_capability(GLenum capability, bool on) {
  if (on)
    glEnable(capability);
  else
    glDisable(capability);
}

ScopedCapability::ScopedCapability(GLenum capability, bool on)
    : capability_(capability), was_on_(glIsEnabled(capability) == GL_TRUE) {
  set_capability(capability, on);
}

ScopedCapability::~ScopedCapability() {
  set_capability(capability_, was_on_);
}

std::string gl_renderer_name() {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name ? name : "";
}

void finish_gpu_work() {
  glFinish();
}

std::vector<std::uint8_t> read_window_rgba(int width, int height) {
  const std::size_t row = 4 * static_cast<std::size_t>(width);
  std::vector<std::uint8_t> rows(row * static_cast<std::size_t>(height));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  // GL's row 0 is the bottom; images have row 0 at the top.
  std::vector<std::uint8_t> image(rows.size());
  for (int y = 0; y < height; ++y)
    std::memcpy(image.data() + static_cast<std::size_t>(y) * row,
                rows.data() + static_cast<std::size_t>(height - 1 - y) * row, row);
  for (std::size_t i = 3; i < image.size(); i += 4) image[i] = 255;
  return image;
}

void enable_debug_output(const char* prefix) {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(print_gl_message, prefix);
}

}  // namespace clothlab::vis
