// The panel's editors for scene values, built from the parameter table (sim/scene/parameters.hpp):
// every record of a section with a widget gets its editor, labelled with its key and unit, with
// the record's slider range, shown only for the integrators it applies to.
#pragma once

#include <string_view>

#include "sim/scene/parameters.hpp"
#include "sim/scene/scene.hpp"
#include "sim/solver.hpp"

namespace clothlab::vis {

// True when an edit of the last widget is finished -- a slider released, typed text confirmed, a
// combo item or checkbox clicked -- so the solver is rebuilt once per edit, not once per frame
// of a drag (a rebuild of a 512 x 512 cloth takes a while).
bool committed(bool changed);

// Editors for `section`'s records on `object` (that section's struct). True when an edit was
// finished this frame (a slider released, text confirmed, an item picked).
bool edit_section(Section section, void* object, IntegratorKind integrator, const Solver& running);

}  // namespace clothlab::vis
