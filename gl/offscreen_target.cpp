#include "gl/offscreen_target.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace clothlab::vis {

OffscreenTarget::OffscreenTarget(int width, int height, int samples)
    : width_(width),
      height_(height),
      samples_(samples),
      msaa_fbo_(make_framebuffer()),
      resolve_fbo_(make_framebuffer()),
      msaa_color_(make_renderbuffer()),
      msaa_depth_(make_renderbuffer()),
      resolve_color_(make_renderbuffer()) {
  // 0 samples: plain single-sampled storage (1 would still be a multisample buffer).
  const int stored = samples > 1 ? samples : 0;
  glNamedRenderbufferStorageMultisample(msaa_color_.get(), stored, GL_SRGB8_ALPHA8, width, height);
  glNamedRenderbufferStorageMultisample(msaa_depth_.get(), stored, GL_DEPTH_COMPONENT32F, width,
                                        height);
  glNamedFramebufferRenderbuffer(msaa_fbo_.get(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                 msaa_color_.get());
  glNamedFramebufferRenderbuffer(msaa_fbo_.get(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                 msaa_depth_.get());
  glNamedRenderbufferStorage(resolve_color_.get(), GL_SRGB8_ALPHA8, width, height);
  glNamedFramebufferRenderbuffer(resolve_fbo_.get(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                 resolve_color_.get());
  for (GLuint fbo : {msaa_fbo_.get(), resolve_fbo_.get()}) {
    const GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("offscreen framebuffer incomplete (status " +
                               std::to_string(status) + ")");
  }
  glObjectLabel(GL_FRAMEBUFFER, msaa_fbo_.get(), -1, "offscreen msaa");
  rows_.resize(static_cast<std::size_t>(width) * height * 4);
}

void OffscreenTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_.get());
  glViewport(0, 0, width_, height_);
}

GLuint OffscreenTarget::resolved_source(bool same_size) const {
  if (samples_ <= 1 || same_size) return msaa_fbo_.get();
  // A multisampled blit cannot scale: resolve at the target's own size first.
  glBlitNamedFramebuffer(msaa_fbo_.get(), resolve_fbo_.get(), 0, 0, width_, height_, 0, 0, width_,
                         height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  return resolve_fbo_.get();
}

void OffscreenTarget::blit(GLuint source, GLuint framebuffer, int width, int height) const {
  const bool same = width == width_ && height == height_;
  glBlitNamedFramebuffer(source, framebuffer, 0, 0, width_, height_, 0, 0, width, height,
                         GL_COLOR_BUFFER_BIT, same ? GL_NEAREST : GL_LINEAR);
}

void OffscreenTarget::resolve_into(GLuint framebuffer, int width, int height) const {
  blit(resolved_source(width == width_ && height == height_), framebuffer, width, height);
}

// The whole blit each time, scissored to one of the four strips around the rectangle, so every
// pixel drawn gets exactly the value the unscissored blit gives it.
void OffscreenTarget::resolve_around(GLuint framebuffer, int width, int height, int x, int y, int w,
                                     int h) const {
  x = std::clamp(x, 0, width);
  y = std::clamp(y, 0, height);
  w = std::clamp(w, 0, width - x);
  h = std::clamp(h, 0, height - y);
  if (w == 0 || h == 0) return resolve_into(framebuffer, width, height);
  const GLuint source = resolved_source(width == width_ && height == height_);
  const int strips[4][4] = {{0, 0, x, height},                  // left of it
                            {x + w, 0, width - x - w, height},  // right of it
                            {x, 0, w, y},                       // below it
                            {x, y + h, w, height - y - h}};     // above it
  glEnable(GL_SCISSOR_TEST);
  for (const auto& s : strips) {
    if (s[2] <= 0 || s[3] <= 0) continue;
    glScissor(s[0], s[1], s[2], s[3]);
    blit(source, framebuffer, width, height);
  }
  glDisable(GL_SCISSOR_TEST);
}

std::vector<std::uint8_t> OffscreenTarget::read_rgba() {
  if (samples_ > 1)
    glBlitNamedFramebuffer(msaa_fbo_.get(), resolve_fbo_.get(), 0, 0, width_, height_, 0, 0, width_,
                           height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, samples_ > 1 ? resolve_fbo_.get() : msaa_fbo_.get());
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rows_.data());
  // GL's row 0 is the bottom; images have row 0 at the top.
  std::vector<std::uint8_t> image(rows_.size());
  const std::size_t stride = static_cast<std::size_t>(width_) * 4;
  for (int y = 0; y < height_; ++y)
    std::memcpy(image.data() + static_cast<std::size_t>(y) * stride,
                rows_.data() + static_cast<std::size_t>(height_ - 1 - y) * stride, stride);
  return image;
}

}  // namespace clothlab::vis
