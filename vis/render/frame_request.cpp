#include "vis/render/frame_request.hpp"

#include <stdexcept>
#include <string>

#include "vis/render/renderer.hpp"

namespace clothlab::vis {
namespace {

void add_color_field(const ViewSettings& view, FieldRequest& r) {
  if (view.mode == DisplayMode::springs) return;  // mode 1 colours by strain alone
  switch (view.color.field) {
    case ScalarField::force:
      r.add_force(view.force_source);
      return;
    case ScalarField::speed:
      r.velocities = true;
      return;
    case ScalarField::strain:
      r.vertex_strain = true;
      return;
    case ScalarField::contact:
      r.contact_gaps = true;
      return;
    case ScalarField::none:
    case ScalarField::height:  // from the positions
    case ScalarField::error:   // handed in by the window (FieldSnapshot::set_reference_distance)
      return;
  }
}

}  // namespace

bool springs_may_replace_total(const ViewSettings& view) {
  return view.springs_at_rest && view.force_source == ForceSource::total &&
         view.color.range != RangeMode::fixed;
}

FieldRequest frame_request(const ViewSettings& view, const Renderer& renderer, bool probe) {
  FieldRequest r;
  r.spring_strain = renderer.draws_springs(view) && !(view.strain_range > 0.0f);
  add_color_field(view, r);
  if (view.arrows.force) {
    r.add_force(view.force_source);
    if (springs_may_replace_total(view)) r.add_force(ForceSource::springs);
  }
  r.normals = view.arrows.normals;
  if (probe) {
    r.add_force(ForceSource::total);
    r.velocities = true;
  }
  return r;
}

void require_field(const std::vector<float>& field, std::size_t size, const char* what) {
  if (field.size() != size)
    throw std::logic_error(std::string("the frame's field snapshot lacks ") + what +
                           " (take it with frame_request(view, ...))");
}

}  // namespace clothlab::vis
