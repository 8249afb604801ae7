// The scientific views drawn over the cloth, shared by the window and headless rendering: the
// colour-by scalar (ViewSettings::color) and the force and normal arrows (ViewSettings::arrows).
// Each frame update() builds only what the view shows, from the frame's field snapshot
// (sim/fields/frame_fields.hpp, filled as frame_request() asks): no scalar and no arrow buffer
// exists while everything is off (docs/design.md: no field export unless something displays,
// probes or traces it).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "vis/render/arrow_field.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab {
class SolverState;
struct FrameFields;
}  // namespace clothlab

namespace clothlab::vis {

class ArrowPass;
class Renderer;

class Diagnostics {
 public:
  Diagnostics();
  ~Diagnostics();
  Diagnostics(const Diagnostics&) = delete;
  Diagnostics& operator=(const Diagnostics&) = delete;

  // Forgets what depends on the cloth's topology; call with Renderer::set_cloth.
  void set_cloth();
  // Builds the scalar and the arrows `view` asks for from `fields` (taken for a request that
  // includes frame_request(view)) and hands the scalar to `renderer` (before renderer.draw).
  // Needs a current GL context only when arrows are on.
  void update(const SolverState& solver, const FrameFields& fields, const ViewSettings& view,
              Renderer& renderer);
  // Draws the arrows over the cloth: right after renderer.draw(), into the same framebuffer.
  void draw(const ViewSettings& view, const Renderer& renderer);

  // What the last update() showed, for legends and tests.
  const std::optional<ScalarRange>& color_range() const { return color_range_; }
  const std::optional<ScalarRange>& force_range() const { return force_range_; }
  // The source the force arrows showed: the view's, or the springs where the total was near
  // zero (ScientificViews::springs_at_rest).
  ForceSource shown_force_source() const { return shown_source_; }
  bool showing_springs_at_rest() const { return springs_at_rest_; }
  const std::vector<ArrowInstance>& force_arrows() const { return force_arrows_; }
  const std::vector<ArrowInstance>& normal_arrows() const { return normal_arrows_; }
  const ArrowLayout& arrow_layout() const { return layout_; }
  // True while any diagnostic state (scalars, arrow pass) is held.
  bool active() const { return !scalars_.empty() || arrows_; }

 private:
  std::unique_ptr<ArrowPass> arrows_;  // while arrows are shown
  ArrowLayout layout_;
  int layout_request_ = -1;  // the stride setting layout_ was built for (-1: none)
  // The force arrows' vectors: the view's source, or the springs' where the total is near zero.
  const std::vector<float>& choose_force_vectors(const SolverState& solver,
                                                 const FrameFields& fields,
                                                 const ViewSettings& view);

  std::vector<float> scalars_;
  std::vector<ArrowInstance> force_arrows_, normal_arrows_;
  std::optional<ScalarRange> color_range_, force_range_;
  ForceSource shown_source_ = ForceSource::total;
  bool springs_at_rest_ = false;
};

}  // namespace clothlab::vis
