// The colour bars of the scientific views, for the window and the headless renderer alike: one
// bar for the cloth's colour-by scalar, one for the force arrows' magnitude and one for the
// springs' strain (mode 1), each with its range, ticks and unit, stacked from the right edge of
// the given area.
#pragma once

#include <imgui.h>

#include <optional>
#include <vector>

#include "vis/render/diagnostics.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab::vis {

// The bars stand side by side from the right edge of area_min .. area_max (window or image
// pixels), vertically centred, kLegendBarWidth wide and at most kLegendBarHeight (and 60 % of the
// area) tall; each takes the width of its labels or heading, whichever is wider.
inline constexpr float kLegendBarWidth = 22.0f, kLegendBarHeight = 260.0f, kLegendGap = 16.0f;

// Where a bar was drawn: its rectangle (range.max at the top edge, range.min at the bottom).
struct LegendBar {
  ImVec2 top_left, size;
  ScalarRange range;
};

// Draws the bars for what the last Diagnostics::update showed and, given `strain` (the
// renderer's Renderer::strain_range()), the springs' strain on Moreland's cool-warm map; nothing
// when no range is on. Returns where they went, right-most first.
std::vector<LegendBar> draw_legends(ImDrawList* draw, ImVec2 area_min, ImVec2 area_max,
                                    const ViewSettings& view, const Diagnostics& diagnostics,
                                    const std::optional<ScalarRange>& strain = std::nullopt);

}  // namespace clothlab::vis
