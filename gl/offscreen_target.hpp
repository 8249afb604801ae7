// A framebuffer to render into without a window: colour and depth, multisampled (samples > 1)
// and resolved into a plain RGBA8 framebuffer that is read back to memory, or single-sampled
// (samples 1) and read back directly.
#pragma once

#include <cstdint>
#include <vector>

#include "gl/objects.hpp"

namespace clothlab::vis {

class OffscreenTarget {
 public:
  OffscreenTarget(int width, int height, int samples = 4);

  // Binds the framebuffer drawn into and sets the viewport.
  void bind() const;
  GLuint framebuffer() const { return msaa_fbo_.get(); }
  // Resolves and reads the image: RGBA8, row 0 at the top.
  std::vector<std::uint8_t> read_rgba();
  // Resolves (or copies) the image into `framebuffer` (a window's: 0) of the same size.
  void resolve_into(GLuint framebuffer) const { resolve_into(framebuffer, width_, height_); }
  // The same into `framebuffer` of another size: resolved first where multisampled, then scaled
  // with linear filtering (the window's scene drawn at fewer pixels, render_quality.hpp).
  void resolve_into(GLuint framebuffer, int width, int height) const;
  // The same, leaving the destination's pixels [x, x + w) x [y, y + h) (from the bottom left)
  // as they are: what an opaque panel covers is never filtered (a CPU rasteriser pays for every
  // pixel it scales up).
  void resolve_around(GLuint framebuffer, int width, int height, int x, int y, int w, int h) const;
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

 private:
  int width_, height_, samples_;
  Framebuffer msaa_fbo_, resolve_fbo_;
  Renderbuffer msaa_color_, msaa_depth_, resolve_color_;
  std::vector<std::uint8_t> rows_;
  // The framebuffer the final (scaling) blit reads: the resolved copy where multisampled.
  GLuint resolved_source(bool same_size) const;
  // `source` (this target's size) into framebuffer's [0, width) x [0, height): copied at the same
  // size, else scaled with linear filtering.
  void blit(GLuint source, GLuint framebuffer, int width, int height) const;
};

}  // namespace clothlab::vis
