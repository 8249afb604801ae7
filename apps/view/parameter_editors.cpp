#include "apps/view/parameter_editors.hpp"

#include <imgui.h>

#include <algorithm>
#include <optional>
#include <string>

namespace clothlab::vis {
namespace {

std::string label(const Parameter& p) {
  std::string text(p.name);
  for (char& c : text)
    if (c == '_') c = ' ';
  if (!p.unit.empty()) text += " (" + std::string(p.unit) + ")";
  return text;
}

// A double slider over the record's panel range on a logarithmic scale (Ctrl + click types any
// value; validate_scene then checks it against the full range).
bool log_slider(const Parameter& p, double& value) {
  const double lo = p.ui.lo, hi = p.ui.hi;
  return committed(ImGui::SliderScalar(label(p).c_str(), ImGuiDataType_Double, &value, &lo, &hi,
                                       "%.4g", ImGuiSliderFlags_Logarithmic));
}

// An optional number shows the value it takes (its fallback key's while absent); moving the
// slider gives it its own.
bool optional_log_slider(const Parameter& p, void* object) {
  auto& member = *static_cast<std::optional<double>*>(p.address(object));
  const Parameter* fallback = find_parameter(p.section, p.fallback);
  double value = member     ? *member
                 : fallback ? *static_cast<const double*>(fallback->address(object))
                            : p.ui.lo;
  if (!log_slider(p, value)) return false;
  member = value;
  return true;
}

bool input(const Parameter& p, void* member) {
  if (p.kind == ValueKind::integer)
    return committed(ImGui::InputInt(label(p).c_str(), static_cast<int*>(member)));
  return committed(
      ImGui::InputDouble(label(p).c_str(), static_cast<double*>(member), 0.0, 0.0, "%.6g"));
}

bool combo(const Parameter& p, void* object) {
  const int current = p.choice_index(object);
  bool changed = false;
  const std::string shown(current < 0 ? "(none)" : choice_name(p, current));
  if (ImGui::BeginCombo(label(p).c_str(), shown.c_str())) {
    for (int n = 0; !choice_name(p, n).empty(); ++n) {
      const std::string name(choice_name(p, n));
      if (ImGui::Selectable(name.c_str(), n == current) && n != current) {
        p.choose(object, n);
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

// The step: automatic (from the highest frequency; the running solver says what it chose) or
// typed.
bool step(const Parameter& p, SolverSpec& s, const Solver& running) {
  bool edited = committed(ImGui::Checkbox("auto dt", &s.dt_auto));
  if (s.dt_auto) {
    ImGui::SameLine();
    ImGui::TextDisabled("%.4g s x %d substep(s)", running.dt(), running.substeps());
    return edited;
  }
  return edited | input(p, &s.dt);
}

// Substeps: automatic (the running solver says how many) or typed.
bool substeps(const Parameter& p, SolverSpec& s, const Solver& running) {
  bool is_auto = s.substeps == 0;
  const bool toggled = committed(ImGui::Checkbox("auto substeps", &is_auto));
  if (toggled) s.substeps = is_auto ? 0 : running.substeps();
  if (is_auto) {
    ImGui::SameLine();
    ImGui::TextDisabled("%d", running.substeps());
    return toggled;
  }
  const bool typed = committed(ImGui::InputInt(label(p).c_str(), &s.substeps));
  s.substeps = std::max(1, s.substeps);
  return toggled || typed;
}

}  // namespace

bool committed(bool changed) {
  return (changed && !ImGui::IsItemActive()) || ImGui::IsItemDeactivatedAfterEdit();
}

bool edit_section(Section section, void* object, IntegratorKind integrator, const Solver& running) {
  bool edited = false;
  for (const Parameter& p : parameters()) {
    if (p.section != section || p.widget == Widget::none) continue;
    if (!applies_to(p, to_string(integrator))) continue;
    switch (p.widget) {
      case Widget::log_slider:
        edited |= p.optional ? optional_log_slider(p, object)
                             : log_slider(p, *static_cast<double*>(p.address(object)));
        break;
      case Widget::input:
        edited |= input(p, p.address(object));
        break;
      case Widget::combo:
        edited |= combo(p, object);
        break;
      case Widget::step:
        edited |= step(p, *static_cast<SolverSpec*>(object), running);
        break;
      case Widget::substeps:
        edited |= substeps(p, *static_cast<SolverSpec*>(object), running);
        break;
      case Widget::none:
        break;
    }
  }
  return edited;
}

}  // namespace clothlab::vis
