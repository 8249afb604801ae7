// The colour bar beside a scientific view (docs/rendering.md section 8): the map drawn from the
// same colours the cloth shows, with "nice" ticks, labels and the field's title and unit.
#pragma once

#include <imgui.h>

#include <string>

#include "vis/colormap/colormap.hpp"

namespace clothlab::vis {

// Draws a vertical bar filling top_left .. top_left + size (range.max at the top, range.min at
// the bottom) into `draw`, e.g. ImGui::GetForegroundDrawList(). Tick labels go to the right of
// the bar and "title [unit]" above it (no brackets when unit is null or empty), all outside the
// given rectangle; text has a dark shadow so it reads over any background. Needs a current
// ImGui context (for the font).
// "title [unit]" (no brackets without a unit), the heading drawn above the bar.
std::string color_bar_heading(const char* title, const char* unit);
// The width draw_color_bar covers from top_left.x: the bar and its tick labels, or the heading
// where that is wider. Needs a current ImGui context.
float color_bar_extent(ImVec2 size, ScalarRange range, const char* title, const char* unit);

void draw_color_bar(ImDrawList* draw, ImVec2 top_left, ImVec2 size, ColorMap map, ScalarRange range,
                    const char* title, const char* unit);

}  // namespace clothlab::vis
