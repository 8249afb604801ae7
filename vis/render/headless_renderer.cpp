#include "vis/render/headless_renderer.hpp"

#include "sim/solver.hpp"

namespace clothlab::vis {

HeadlessRenderer::HeadlessRenderer(int width, int height) : target_(width, height) {}

std::vector<std::uint8_t> HeadlessRenderer::render(Solver& solver, const ViewSettings& view) {
  renderer_.update_cloth(solver);
  diagnostics_.update(solver, view, renderer_);
  target_.bind();
  renderer_.draw(view, target_.width(), target_.height());
  diagnostics_.draw(view, renderer_);
  return target_.read_rgba();
}

std::optional<ProbeSample> HeadlessRenderer::probe(Solver& solver, const ViewSettings& view, int px,
                                                   int py) {
  if (px < 0 || py < 0 || px >= width() || py >= height()) return std::nullopt;
  if (!fields_) fields_ = std::make_unique<FieldPass>(width(), height());
  renderer_.update_cloth(solver);
  return probe_fields(solver, renderer_, *fields_, view_projection(view.camera, width(), height()),
                      px, py);
}

}  // namespace clothlab::vis
