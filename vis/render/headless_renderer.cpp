#include "vis/render/headless_renderer.hpp"

namespace clothlab::vis {

HeadlessRenderer::HeadlessRenderer(int width, int height) : target_(width, height) {}

std::vector<std::uint8_t> HeadlessRenderer::render(Solver& solver, const ViewSettings& view) {
  renderer_.update_cloth(solver);
  target_.bind();
  renderer_.draw(view, target_.width(), target_.height());
  return target_.read_rgba();
}

}  // namespace clothlab::vis
