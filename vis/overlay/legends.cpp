#include "vis/overlay/legends.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "vis/overlay/color_bar.hpp"
#include "vis/render/scalar_field.hpp"

namespace clothlab::vis {

namespace {

struct Bar {
  std::string title, unit;
  ScalarRange range;
  ColorMap map;
};

}  // namespace

std::vector<LegendBar> draw_legends(ImDrawList* draw, ImVec2 area_min, ImVec2 area_max,
                                    const ViewSettings& view, const Diagnostics& diagnostics,
                                    const std::optional<ScalarRange>& strain) {
  std::vector<Bar> bars;
  if (const auto& range = diagnostics.color_range())
    bars.push_back({std::string(scalar_field_title(view.color.field)),
                    std::string(scalar_field_unit(view.color.field)), *range, view.color.map});
  if (const auto& range = diagnostics.force_range()) {
    // (Built with append: GCC 12 warns falsely, -Wrestrict, on "|" + std::string + "|".)
    std::string title = "|";
    title.append(force_source_name(diagnostics.shown_force_source())).append(" force|");
    if (diagnostics.showing_springs_at_rest()) title.append(" (total ~ 0)");
    bars.push_back({title, "N", *range, view.color.map});
  }
  // Mode 1's lines use Moreland's cool-warm map (shaders/springs.geom), whatever the view's map.
  if (strain) bars.push_back({"spring strain", "", *strain, ColorMap::coolwarm});
  const float height = std::min(kLegendBarHeight, 0.6f * (area_max.y - area_min.y));
  const float top = area_min.y + 0.5f * (area_max.y - area_min.y - height);
  const ImVec2 size(kLegendBarWidth, height);
  float right = area_max.x - kLegendGap;
  std::vector<LegendBar> placed;
  for (const Bar& b : bars) {
    const float x = right - color_bar_extent(size, b.range, b.title.c_str(), b.unit.c_str());
    draw_color_bar(draw, ImVec2(x, top), size, b.map, b.range, b.title.c_str(), b.unit.c_str());
    placed.push_back({ImVec2(x, top), size, b.range});
    right = x - kLegendGap;
  }
  return placed;
}

}  // namespace clothlab::vis
