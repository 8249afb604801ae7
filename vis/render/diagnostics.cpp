#include "vis/render/diagnostics.hpp"

#include "sim/solver.hpp"
#include "vis/render/arrow_pass.hpp"
#include "vis/render/renderer.hpp"
#include "vis/render/scalar_field.hpp"

namespace clothlab::vis {
namespace {

// Normal arrows are this fraction of the spacing between shown vertices long; the shaft radius
// is this fraction of the spacing.
constexpr float kNormalLength = 0.7f, kShaftRadius = 0.06f;

// The force field of `source` into `out`, 3 floats per vertex.
void copy_force_field(Solver& solver, ForceSource source, std::vector<float>& out) {
  solver.update_force_field(source);
  out.resize(3 * solver.vertex_count());
  for (std::size_t v = 0; v < solver.vertex_count(); ++v) {
    const Vec3d f = solver.force(static_cast<int>(v));
    for (int k = 0; k < 3; ++k) out[3 * v + k] = static_cast<float>(f[k]);
  }
}

}  // namespace

Diagnostics::Diagnostics() = default;
Diagnostics::~Diagnostics() = default;

void Diagnostics::set_cloth() {
  sampler_.reset();
  layout_request_ = -1;
  layout_ = {};
}

void Diagnostics::update(Solver& solver, const ViewSettings& view, Renderer& renderer) {
  color_range_.reset();
  force_range_.reset();
  force_arrows_.clear();
  normal_arrows_.clear();
  if (view.color.field == ScalarField::none || view.mode == DisplayMode::springs) {
    sampler_.reset();
    scalars_ = {};
  } else {
    if (!sampler_) sampler_ = std::make_unique<ScalarFieldSampler>(solver);
    sampler_->compute(solver, view.color.field, view.force_source, scalars_);
    color_range_ = choose_range(view.color.range, scalars_, view.color.fixed);
    renderer.set_scalars(scalars_, *color_range_);
  }

  const ArrowSettings& a = view.arrows;
  if (!a.force && !a.normals) {
    arrows_.reset();
    positions_ = {};
    vectors_ = {};
    return;
  }
  if (!arrows_) arrows_ = std::make_unique<ArrowPass>();
  if (layout_request_ != a.stride) {
    layout_ = vis::arrow_layout(solver, a.stride);
    layout_request_ = a.stride;
  }
  const std::size_t n = solver.vertex_count();
  positions_.resize(3 * n);
  vectors_.resize(3 * n);
  solver.copy_positions(positions_.data());
  const float spacing = layout_.spacing;
  if (a.force) {
    update_force_vectors(solver, view);
    build_force_arrows(layout_, positions_, vectors_, a.scale, a.length * spacing, *force_range_,
                       force_arrows_);
  }
  if (a.normals) {
    solver.copy_normals(vectors_.data());
    build_normal_arrows(layout_, positions_, vectors_, kNormalLength * spacing, view.camera.eye(),
                        normal_arrows_);
  }
}

// The arrows' vectors and range: the view's source, or the springs' force where the total is
// near zero and the view lets it (an automatic range only: a fixed one says nothing of it).
void Diagnostics::update_force_vectors(Solver& solver, const ViewSettings& view) {
  copy_force_field(solver, view.force_source, vectors_);
  force_range_ = arrow_range(solver, layout_, vectors_, view.color.range, view.color.fixed);
  shown_source_ = view.force_source;
  springs_at_rest_ = false;
  if (!view.springs_at_rest || view.force_source != ForceSource::total ||
      view.color.range == RangeMode::fixed)
    return;
  copy_force_field(solver, ForceSource::springs, spring_vectors_);
  const ScalarRange springs = arrow_range(solver, layout_, spring_vectors_, view.color.range, {});
  if (!total_near_zero(*force_range_, springs)) return;
  vectors_.swap(spring_vectors_);
  force_range_ = springs;
  shown_source_ = ForceSource::springs;
  springs_at_rest_ = true;
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
