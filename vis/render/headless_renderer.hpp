// Headless rendering in one object: an EGL context, an offscreen target and the same Renderer the
// window uses. Used by `clothlab render` and by the image tests.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "vis/gl/headless_context.hpp"
#include "vis/gl/offscreen_target.hpp"
#include "vis/render/renderer.hpp"

namespace clothlab::vis {

class HeadlessRenderer {
 public:
  // Throws GlUnavailable (one clear line) without EGL / OpenGL 4.5, ShaderError on a bad shader.
  HeadlessRenderer(int width, int height);

  void set_cloth(Solver& solver) { renderer_.set_cloth(solver); }
  // Uploads the solver's state, draws and reads back: RGBA rows, top first.
  std::vector<std::uint8_t> render(Solver& solver, const ViewSettings& view);

  int width() const { return target_.width(); }
  int height() const { return target_.height(); }
  std::string gl_renderer() const { return context_.renderer(); }

 private:
  HeadlessContext context_;  // first: everything below needs the current context
  OffscreenTarget target_;
  Renderer renderer_;
};

}  // namespace clothlab::vis
