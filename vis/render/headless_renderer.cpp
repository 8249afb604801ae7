#include "vis/render/headless_renderer.hpp"

#include "vis/overlay/headless_overlay.hpp"
#include "vis/overlay/legends.hpp"
#include "vis/render/render_quality.hpp"

namespace clothlab::vis {

HeadlessRenderer::HeadlessRenderer(int width, int height) : target_(width, height) {}
HeadlessRenderer::~HeadlessRenderer() = default;

void HeadlessRenderer::draw(const SolverState& solver, const FrameFields& fields,
                            const ViewSettings& view) {
  const int samples = msaa_samples(renderer_.quality(view), view.mode);
  if (samples != target_.samples()) target_ = OffscreenTarget(width(), height(), samples);
  renderer_.update_cloth(fields);
  diagnostics_.update(solver, fields, view, renderer_);
  target_.bind();
  renderer_.draw(view, target_.width(), target_.height());
  if (PassTimer* timer = renderer_.pass_timer()) timer->begin(Pass::overlay);
  diagnostics_.draw(view, renderer_);
  legends_.clear();
  const std::optional<ScalarRange>& strain = renderer_.strain_range();
  if (view.legends && (diagnostics_.color_range() || diagnostics_.force_range() || strain)) {
    if (!overlay_) overlay_ = std::make_unique<HeadlessOverlay>();
    const ImVec2 size(static_cast<float>(width()), static_cast<float>(height()));
    overlay_->draw(width(), height(), [&](ImDrawList* draw) {
      legends_ = draw_legends(draw, ImVec2(0.0f, 0.0f), size, view, diagnostics_, strain);
    });
  }
  if (PassTimer* timer = renderer_.pass_timer()) timer->end();
}

std::vector<std::uint8_t> HeadlessRenderer::render(const SolverState& solver,
                                                   const FrameFields& fields,
                                                   const ViewSettings& view) {
  draw(solver, fields, view);
  return target_.read_rgba();
}

std::optional<ProbeSample> HeadlessRenderer::probe(const SolverState& solver,
                                                   const FrameFields& fields,
                                                   const ViewSettings& view, int px, int py) {
  if (px < 0 || py < 0 || px >= width() || py >= height()) return std::nullopt;
  if (!field_pass_) field_pass_ = std::make_unique<FieldPass>(width(), height());
  renderer_.update_cloth(fields);
  return probe_fields(solver, fields, renderer_, *field_pass_,
                      view_projection(view.camera, width(), height()), px, py);
}

}  // namespace clothlab::vis
