#include "vis/render/diagnostics.hpp"

#include <algorithm>

#include "sim/fields/frame_fields.hpp"
#include "vis/passes/arrow_pass.hpp"
#include "vis/render/frame_request.hpp"
#include "vis/render/renderer.hpp"
#include "vis/render/scalar_field.hpp"

namespace clothlab::vis {
namespace {

// Normal arrows are this fraction of the spacing between shown vertices long; the shaft radius
// is this fraction of the spacing.
constexpr float kNormalLength = 0.7f, kShaftRadius = 0.06f;

// The automatic ranges that start at zero: the contact gap from touching to out of reach, the
// distance from the reference (`scalars`, in mm) from none to the largest.
std::optional<ScalarRange> own_range(const ViewSettings& view, const FrameFields& fields,
                                     const std::vector<float>& scalars) {
  if (view.color.range == RangeMode::fixed) return std::nullopt;
  if (view.color.field == ScalarField::contact) return ScalarRange{0.0, fields.contact_range};
  if (view.color.field != ScalarField::error) return std::nullopt;
  const float largest = scalars.empty() ? 0.0f : *std::max_element(scalars.begin(), scalars.end());
  return ScalarRange{0.0, std::max(double(largest), 1e-3)};
}

}  // namespace

Diagnostics::Diagnostics() = default;
Diagnostics::~Diagnostics() = default;

void Diagnostics::set_cloth() {
  layout_request_ = -1;
  layout_ = {};
}

void Diagnostics::update(const SolverState& solver, const FrameFields& fields,
                         const ViewSettings& view, Renderer& renderer) {
  color_range_.reset();
  force_range_.reset();
  force_arrows_.clear();
  normal_arrows_.clear();
  if (view.color.field == ScalarField::none || view.mode == DisplayMode::springs) {
    scalars_ = {};
  } else {
    scalar_values(fields, view.color.field, view.force_source, scalars_);
    color_range_ = own_range(view, fields, scalars_);
    if (!color_range_) color_range_ = choose_range(view.color.range, scalars_, view.color.fixed);
    renderer.set_scalars(scalars_, *color_range_);
  }

  const ArrowSettings& a = view.arrows;
  if (!a.force && !a.normals) {
    arrows_.reset();
    return;
  }
  if (!arrows_) arrows_ = std::make_unique<ArrowPass>();
  if (layout_request_ != a.stride) {
    layout_ = vis::arrow_layout(solver, a.stride);
    layout_request_ = a.stride;
  }
  const float spacing = layout_.spacing;
  if (a.force) {
    const std::vector<float>& vectors = choose_force_vectors(solver, fields, view);
    build_force_arrows(layout_, fields.positions, vectors, a.scale, a.length * spacing,
                       *force_range_, force_arrows_);
  }
  if (a.normals) {
    require_field(fields.normals, 3 * fields.vertices, "normals");
    build_normal_arrows(layout_, fields.positions, fields.normals, kNormalLength * spacing,
                        view.camera.eye(), normal_arrows_);
  }
}

// The arrows' vectors and range: the view's source, or the springs' force where the total is
// near zero and the view lets it (an automatic range only: a fixed one says nothing of it).
const std::vector<float>& Diagnostics::choose_force_vectors(const SolverState& solver,
                                                            const FrameFields& fields,
                                                            const ViewSettings& view) {
  const std::vector<float>& chosen = fields.force(view.force_source);
  require_field(chosen, 3 * fields.vertices, "the force arrows' force");
  force_range_ = arrow_range(solver, layout_, chosen, view.color.range, view.color.fixed);
  shown_source_ = view.force_source;
  springs_at_rest_ = false;
  if (!springs_may_replace_total(view)) return chosen;
  const std::vector<float>& springs_force = fields.force(ForceSource::springs);
  require_field(springs_force, 3 * fields.vertices, "the springs' force");
  const ScalarRange springs = arrow_range(solver, layout_, springs_force, view.color.range, {});
  if (!total_near_zero(*force_range_, springs)) return chosen;
  force_range_ = springs;
  shown_source_ = ForceSource::springs;
  springs_at_rest_ = true;
  return springs_force;
}
void Diagnostics::draw(const ViewSettings& view, const Renderer& renderer) {
  if (!arrows_) return;
  const float radius = kShaftRadius * layout_.spacing;
  if (!force_arrows_.empty())
    arrows_->draw(force_arrows_, ArrowColoring::colormap, radius,
                  renderer.colormap_texture(view.color.map));
  if (!normal_arrows_.empty())
    arrows_->draw(normal_arrows_, ArrowColoring::direction, radius,
                  renderer.colormap_texture(view.color.map));
}

}  // namespace clothlab::vis
