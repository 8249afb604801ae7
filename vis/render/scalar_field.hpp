// The scalars the cloth can be coloured by (ViewSettings::color): per-vertex values computed on
// the CPU from the frame's field snapshot, only while they are shown. Plain data out, no GL.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "sim/forces/force_source.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab {
struct FrameFields;
}

namespace clothlab::vis {

std::string_view scalar_field_name(ScalarField field);  // "none", "force", "speed", ...
std::optional<ScalarField> parse_scalar_field(std::string_view name);
std::string_view scalar_field_unit(ScalarField field);   // "N", "m/s", "" (strain), "m"
std::string_view scalar_field_title(ScalarField field);  // "|force|", "|velocity|", ...
// Signed fields (strain) read best on a diverging map with a symmetric range.
bool scalar_field_signed(ScalarField field);

// One scalar per vertex from the frame's snapshot into `out`: |force| of `source`, |velocity|,
// strain (the mean engineering strain (l - l0) / l0 of the springs that end at the vertex,
// sim/fields/spring_strain.hpp), height (world y) or contact (the gap to other cloth,
// sim/fields/contact_gaps.hpp: NaN, the warning colour, where cloth crosses cloth) or error (the
// distance from the window's live reference, in mm). The snapshot
// must hold the field (frame_request asks for it); never allocates once `out` has the vertex count.
void scalar_values(const FrameFields& fields, ScalarField field, ForceSource source,
                   std::vector<float>& out);

}  // namespace clothlab::vis
