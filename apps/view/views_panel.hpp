// The panel's "Scientific views" section and the colour-bar legends: what the cloth is coloured
// by, the colour map and its range, force and normal arrows (F, N). Immediate mode, like the
// rest of the panel: reads and writes ViewSettings every frame.
#pragma once

#include "vis/render/diagnostics.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab::vis {

// The editors, inside the panel's window.
void draw_view_editors(ViewSettings& view);

// A colour bar for each view that maps a value to a colour (the cloth's scalar, the force
// arrows' magnitude, mode 1's strain), with its range and unit, at the window's right edge,
// below `top` (window points: under a window drawn there, such as the error view's).
void draw_legends(const ViewSettings& view, const Diagnostics& diagnostics,
                  const std::optional<ScalarRange>& strain, float top = 0.0f);

}  // namespace clothlab::vis
