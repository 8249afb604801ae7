// Which fields a frame's views read (sim/fields/frame_fields.hpp): the application takes one
// snapshot per frame with this request and hands it to the renderer, the diagnostics and the
// probe, so nothing the view does not show is computed and nothing is computed twice.
#pragma once

#include <cstddef>
#include <vector>

#include "sim/fields/frame_fields.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab::vis {

class Renderer;

// The fields `view` needs with `renderer`'s cloth (mode 1's automatic strain range needs the
// springs' strain, a colour-by scalar its field, arrows their force or normals), plus the
// total force and the velocities when `probe` (the field pass).
FieldRequest frame_request(const ViewSettings& view, const Renderer& renderer, bool probe = false);

// Whether force arrows of the total may show the springs' force instead (near rest).
bool springs_may_replace_total(const ViewSettings& view);

// Throws std::logic_error naming `what` unless `field` has `size` values: a caller took the
// snapshot with a request that left out a field the view shows.
void require_field(const std::vector<float>& field, std::size_t size, const char* what);

}  // namespace clothlab::vis
