#include "apps/view/views_panel.hpp"

#include <algorithm>

#include <imgui.h>

#include <string>

#include "vis/overlay/legends.hpp"
#include "vis/render/scalar_field.hpp"

namespace clothlab::vis {
namespace {

// A combo over the names of an enum's values (first .. last, contiguous).
template <class E, class Name>
bool enum_combo(const char* label, E& value, std::initializer_list<E> values, Name name) {
  bool changed = false;
  const std::string current(name(value));
  if (ImGui::BeginCombo(label, current.c_str())) {
    for (E v : values) {
      const std::string item(name(v));
      if (ImGui::Selectable(item.c_str(), v == value)) {
        changed = v != value;
        value = v;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

}  // namespace

void draw_view_editors(ViewSettings& view) {
  // Closed at first: open, the panel is taller than a small window.
  if (!ImGui::CollapsingHeader("Scientific views")) return;
  ColorSettings& c = view.color;
  const ScalarField before = c.field;
  enum_combo("colour by", c.field,
             {ScalarField::none, ScalarField::force, ScalarField::speed, ScalarField::strain,
              ScalarField::height, ScalarField::contact, ScalarField::error},
             scalar_field_name);
  // A signed field starts on the diverging map with a symmetric range; the user may change it.
  if (c.field != before && scalar_field_signed(c.field)) {
    c.map = ColorMap::coolwarm;
    c.range = RangeMode::symmetric;
  }
  enum_combo("colour map", c.map,
             {ColorMap::viridis, ColorMap::magma, ColorMap::turbo, ColorMap::coolwarm},
             colormap_name);
  enum_combo("range", c.range, {RangeMode::automatic, RangeMode::symmetric, RangeMode::fixed},
             range_mode_name);
  if (c.range == RangeMode::fixed) {
    double lo_hi[2] = {c.fixed.min, c.fixed.max};
    if (ImGui::InputScalarN("min, max", ImGuiDataType_Double, lo_hi, 2, nullptr, nullptr, "%.4g") &&
        lo_hi[0] < lo_hi[1])
      c.fixed = {lo_hi[0], lo_hi[1]};
  }
  ImGui::Checkbox("shaded colours", &c.shaded);
  ImGui::SameLine();
  ImGui::Checkbox("colour bars", &view.legends);

  ArrowSettings& a = view.arrows;
  ImGui::Checkbox("force arrows (F)", &a.force);
  ImGui::SameLine();
  ImGui::Checkbox("normal arrows (N)", &a.normals);
  enum_combo("force", view.force_source,
             {ForceSource::total, ForceSource::springs, ForceSource::gravity, ForceSource::drag,
              ForceSource::wind},
             force_source_name);
  if (view.force_source == ForceSource::total) {
    ImGui::SameLine();
    ImGui::Checkbox("springs at rest", &view.springs_at_rest);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("where the total force is near zero, show the springs' force");
  }
  ImGui::SliderInt("arrow every", &a.stride, 0, 32, a.stride == 0 ? "auto" : "%d vertices");
  enum_combo("arrow length", a.scale, {ArrowScale::linear, ArrowScale::log},
             [](ArrowScale s) { return s == ArrowScale::log ? "log (3 decades)" : "linear"; });
  ImGui::SliderFloat("longest arrow", &a.length, 0.2f, 5.0f, "%.2g x spacing");
}

void draw_legends(const ViewSettings& view, const Diagnostics& diagnostics,
                  const std::optional<ScalarRange>& strain, float top) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const ImVec2 max(viewport->WorkPos.x + viewport->WorkSize.x,
                   viewport->WorkPos.y + viewport->WorkSize.y);
  if (!view.legends) return;
  const ImVec2 min(viewport->WorkPos.x,
                   std::max(viewport->WorkPos.y, std::min(top, max.y - 100.0f)));
  draw_legends(ImGui::GetBackgroundDrawList(), min, max, view, diagnostics, strain);
}

}  // namespace clothlab::vis
