// The frame-level GL state the renderer and the applications set between passes: which
// framebuffer is drawn into, fixed-function switches, clears, reading pixels back, waiting for
// the GPU. Passes keep their own draw calls (vis/passes/); code elsewhere goes through these
// (docs/design.md, "Layout": raw GL calls stay in gl/, the passes and the GPU step).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gl/gl.hpp"

namespace clothlab::vis {

// The framebuffer bound for drawing now (0: the window's).
GLuint bound_draw_framebuffer();
// Binds `framebuffer` for drawing and reading and sets the viewport to width x height.
void bind_target(GLuint framebuffer, int width, int height);
// Clears the bound target's colour attachment 0 to rgba, and its depth to 1 and stencil to 0.
void clear_target(const float rgba[4]);

// Sets the bound target's depth to `depth` inside the rectangle (pixels, origin bottom-left) and
// leaves the rest: a depth of 0 there makes the depth test reject every fragment drawn over it
// before it is shaded.
void clear_depth_in(int x, int y, int width, int height, float depth);

// Leaves no vertex array bound (the next pass binds its own).
void unbind_vertex_array();

// Turns a capability (GL_DEPTH_TEST, GL_FRAMEBUFFER_SRGB, ...) on or off.
void set_capability(GLenum capability, bool on);
// Sets a capability for a scope and restores its previous setting on leaving it.
class ScopedCapability {
 public:
  ScopedCapability(GLenum capability, bool on);
  ~ScopedCapability();
  ScopedCapability(const ScopedCapability&) = delete;
  ScopedCapability& operator=(const ScopedCapability&) = delete;

 private:
  GLenum capability_;
  bool was_on_;
};

// The GL renderer's name (GL_RENDERER), e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
std::string gl_renderer_name();
// Waits until the GPU has finished every command issued so far (benchmarks count its work).
void finish_gpu_work();
// The window's back buffer, width x height RGBA rows with row 0 at the top, alpha set to 255.
std::vector<std::uint8_t> read_window_rgba(int width, int height);
// Debug builds: the driver reports every error where it happens (synchronous output), so a
// debugger's backtrace points at the offending call; messages go to stderr after `prefix`.
void enable_debug_output(const char* prefix);

}  // namespace clothlab::vis
