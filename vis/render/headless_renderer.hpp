// Headless rendering in one object: an EGL context, an offscreen target and the same Renderer the
// window uses. Used by `clothlab render` and by the image tests.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/headless_context.hpp"
#include "gl/offscreen_target.hpp"
#include "vis/overlay/legends.hpp"
#include "vis/passes/field_pass.hpp"
#include "vis/render/diagnostics.hpp"
#include "vis/render/frame_request.hpp"
#include "vis/render/renderer.hpp"

namespace clothlab::vis {

class HeadlessOverlay;

class HeadlessRenderer {
 public:
  // Throws GlUnavailable (one clear line) without EGL / OpenGL 4.5, ShaderError on a bad shader.
  HeadlessRenderer(int width, int height);
  ~HeadlessRenderer();

  void set_cloth(const SolverState& solver) {
    renderer_.set_cloth(solver);
    diagnostics_.set_cloth();
  }
  // The scenery of the scene's [render] table (pole, meshes) and its [[colliders]]; after
  // set_cloth.
  void set_scene(const RenderSpec& spec, const Solver& solver,
                 const std::vector<ColliderSpec>& colliders = {}) {
    renderer_.set_scene(spec, solver, colliders);
  }
  // The fields draw() and probe() read for `view`: take the frame's snapshot with this request
  // (sim/fields/frame_fields.hpp; `probe` adds the probe's fields).
  FieldRequest request(const ViewSettings& view, bool probe = false) const {
    return frame_request(view, renderer_, probe);
  }
  // Uploads the snapshot (and what the view's diagnostics need) and draws the frame, with its
  // colour bars, into the multisampled target, without reading it back. `solver` is the one the
  // snapshot was taken of (its topology and pins).
  void draw(const SolverState& solver, const FrameFields& fields, const ViewSettings& view);
  // draw(), then the resolved image: RGBA rows, top first.
  std::vector<std::uint8_t> render(const SolverState& solver, const FrameFields& fields,
                                   const ViewSettings& view);

  // The fields under pixel (px, py), row 0 at the top, of the snapshot (taken for
  // request(view, true)) seen with `view`: draws the field pass (built on first use), reads the
  // one pixel and names the vertex of the triangle there nearest to the surface point. Nothing
  // where the pixel misses the cloth or lies outside the image.
  std::optional<ProbeSample> probe(const SolverState& solver, const FrameFields& fields,
                                   const ViewSettings& view, int px, int py);

  int width() const { return target_.width(); }
  int height() const { return target_.height(); }
  std::string gl_renderer() const { return context_.renderer(); }
  Renderer& renderer() { return renderer_; }  // e.g. to time its passes (benchmarks)
  const Renderer& renderer() const { return renderer_; }
  // The light as the last render() placed it (its shadow-map matrices).
  const LightRig& light() const { return renderer_.light(); }
  // The colour-by range and the arrows of the last render().
  const Diagnostics& diagnostics() const { return diagnostics_; }
  // The colour bars drawn into the last render() (ViewSettings::legends), right-most first.
  const std::vector<LegendBar>& legends() const { return legends_; }

 private:
  HeadlessContext context_;  // first: everything below needs the current context
  OffscreenTarget target_;
  Renderer renderer_;
  Diagnostics diagnostics_;
  std::unique_ptr<HeadlessOverlay> overlay_;  // only once a legend is drawn
  std::vector<LegendBar> legends_;
  std::unique_ptr<FieldPass> field_pass_;  // only once something probes
};

}  // namespace clothlab::vis
