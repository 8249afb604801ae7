#include "apps/view/control_panel.hpp"

#include <algorithm>

#include <imgui.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "apps/view/message_colours.hpp"
#include "apps/view/parameter_editors.hpp"
#include "apps/view/scene_edit.hpp"
#include "apps/view/views_panel.hpp"
#include "sim/scene/parameter_keys.hpp"
#include "vis/render/cloth_detail.hpp"
#include "vis/render/render_quality.hpp"

namespace clothlab::vis {
namespace {

// Integrator, dt, springs, drag, wind: applied to the running motion once an edit is finished.
// The editors come from the parameter table; solver.backend moves the motion (load_state) to the
// other backend, and a scene the GPU cannot run stays on the CPU with the panel's message saying
// why.
bool dynamics_editors(Scene& draft, const Solver& running) {
  const IntegratorKind integrator = draft.solver.integrator;
  bool edited = edit_section(Section::solver, &draft.solver, integrator, running);
  edited |= edit_section(Section::springs, &draft.springs, integrator, running);
  for (ClothSpec& cloth : draft.cloths) {
    if (!cloth.springs) continue;  // this cloth's own springs replace the shared ones
    ImGui::PushID(cloth.key.c_str());
    ImGui::TextDisabled("%s",
                        (cloth.key + "." + std::string(key_of<&ClothSpec::springs>())).c_str());
    edited |= edit_section(Section::springs, &*cloth.springs, integrator, running);
    ImGui::PopID();
  }
  edited |= edit_section(Section::forces, &draft.forces, integrator, running);
  edited |= committed(ImGui::Checkbox("wind (W)", &draft.forces.wind.enabled));
  double speed = wind_speed(draft);
  const double lo = 0.0, hi = 30.0;
  if (committed(ImGui::SliderScalar("wind speed (m/s)", ImGuiDataType_Double, &speed, &lo, &hi,
                                    "%.3g"))) {
    set_wind_speed(draft, speed);
    edited = true;
  } else if (ImGui::IsItemActive()) {
    set_wind_speed(draft, speed);  // follow the slider; applied on release
  }
  return edited;
}

// Resolution per cloth; structural, so it waits for Reset.
bool structure_editors(Scene& draft) {
  bool edited = false;
  for (ClothSpec& cloth : draft.cloths) {
    ImGui::PushID(cloth.key.c_str());
    // "<key> grid": "<key> resolution ([ ])" is wider than the labels' column.
    const std::string label = cloth.key + " grid ([ ])";
    edited |= committed(ImGui::InputInt2(label.c_str(), cloth.resolution.data()));
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s.resolution: vertices along u and v; ] doubles, [ halves",
                        cloth.key.c_str());
    ImGui::PopID();
  }
  return edited;
}

// Shadows: the filter and the map's size (docs/rendering.md section 6).
// render.quality: auto says what it chose for this GL renderer.
void quality_editor(ViewSettings& view, const PanelState& state) {
  const std::string& gl_renderer = state.gl_renderer;
  const RenderQuality chosen = resolve_quality(view.quality, gl_renderer);
  // auto says what it chose and why inside the combo, which is as wide as the panel allows.
  const std::string why = software_renderer(gl_renderer) ? " (software GL)" : " (GPU)";
  const std::string shown = view.quality == RenderQuality::automatic
                                ? std::string("auto: ") + to_string(chosen) + why
                                : std::string(to_string(view.quality));
  if (ImGui::BeginCombo("render quality", shown.c_str())) {
    for (const auto& [quality, name] : kRenderQualityNames)
      if (ImGui::Selectable(name, quality == view.quality)) view.quality = quality;
    ImGui::EndCombo();
  }
  if (chosen == RenderQuality::fast && view.mode != DisplayMode::springs) {
    ImGui::SliderFloat("window scale", &view.window_scale, 0.25f, 1.0f, "%.2f");
    ImGui::TextDisabled("scene drawn at %d x %d, scaled up", state.scene_width, state.scene_height);
  }
  if (state.cloth_stride > 1)
    ImGui::TextDisabled("large cloth drawn at %s", detail_note(state.cloth_stride).c_str());
}

void shadow_editors(ViewSettings& view) {
  if (ImGui::BeginCombo("shadows", to_string(view.shadows))) {
    for (const auto& [filter, name] : kShadowFilterNames)
      if (ImGui::Selectable(name, filter == view.shadows)) view.shadows = filter;
    ImGui::EndCombo();
  }
  // Powers of two over the table's panel range for render.shadow_map_size.
  const Range ui = find_parameter(Section::render, key_of<&RenderSpec::shadow_map_size>())->ui;
  const int lo = static_cast<int>(std::log2(ui.lo)), hi = static_cast<int>(std::log2(ui.hi));
  int size_log2 = static_cast<int>(std::lround(std::log2(view.shadow_map_size)));
  if (ImGui::SliderInt("shadow map", &size_log2, lo, hi, "")) view.shadow_map_size = 1 << size_log2;
  ImGui::SameLine();
  ImGui::TextDisabled("%d^2", view.shadow_map_size);
  float size = view.light_size;
  if (ImGui::SliderFloat(view.light_type == LightType::spot ? "light size (m)" : "light size (rad)",
                         &size, 0.0f, 0.5f, "%.3g"))
    view.light_size = size;
}

std::optional<Action> buttons(const SimSession& session) {
  std::optional<Action> clicked;
  if (ImGui::Button(session.paused ? "Run (Space)" : "Pause (Space)")) clicked = Action::pause;
  ImGui::SameLine();
  if (ImGui::Button("Step (.)")) clicked = Action::single_step;
  ImGui::SameLine();
  if (ImGui::Button("Reset (R)")) clicked = Action::reset;
  ImGui::SameLine();
  // Greyed out once dropped: only Reset pins the cloth again.
  ImGui::BeginDisabled(session.solver().pins_released());
  if (ImGui::Button("Drop (D)")) clicked = Action::release_pins;
  ImGui::EndDisabled();
  if (ImGui::Button("Screenshot (F12)")) clicked = Action::screenshot;
  ImGui::SameLine();
  // Record writes the CSV trace of the pinned probe's vertex (or the scene's traced vertices).
  if (ImGui::Button(session.recording() ? "Stop recording" : "Record CSV"))
    clicked = Action::toggle_record;
  ImGui::PushTextWrapPos(0.0f);  // the panel is narrow: the hint and the path wrap
  if (session.recording())
    ImGui::TextColored(kErrorColour, "%ld rows to %s", session.recorded_rows(),
                       session.recording_path().c_str());
  else
    ImGui::TextDisabled("Record: the pinned probe's vertex, else the scene's [trace]");
  ImGui::PopTextWrapPos();
  return clicked;
}

void statistics(SimSession& session, const FrameStats& stats) {
  const Solver& solver = session.solver();
  ImGui::Text("simulated time   %.3f s  (step %ld)", solver.time(), solver.step_count());
  ImGui::Text("steps per frame  %.1f", stats.steps_per_frame());
  ImGui::Text("time per step    %.4f ms", stats.ms_per_step());
  ImGui::Text("simulation/frame %.2f ms", stats.ms_per_step() * stats.steps_per_frame());
  const SolveStats last = solver.last_solve();
  if (last.iterations > 0)
    ImGui::Text("iterations       %d per substep, residual %.2g%s", last.iterations, last.residual,
                last.converged ? "" : " (at the cap)");
  ImGui::Text("frame time       %.1f ms", stats.frame_ms());
  ImGui::Text("cloth copies     %d  (+ and -)", session.copies());
  ImGui::Text("vertices         %zu", solver.vertex_count());
  ImGui::Text("springs          %zu", solver.spring_count());
  ImGui::Text("threads          %d", solver.threads());
}

void messages(const SimSession& session, const FrameStats& stats, const PanelState& state) {
  if (session.divergence()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kErrorColour, "%s", session.divergence()->message().c_str());
    ImGui::TextColored(kErrorColour, "Stopped. Press R to reset.");
    ImGui::PopTextWrapPos();
  }
  if (stats.behind() && !session.paused && !session.divergence()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kWarningColour, "%s (the drawing is not the cause)",
                       stats.behind_reason(session.solver().dt()).c_str());
    ImGui::PopTextWrapPos();
  }
  // A message about the run belongs to its state: this one shows while the pins are released,
  // and R or another scene takes it away with them.
  if (session.solver().pins_released()) ImGui::TextWrapped("%s", kPinsReleasedMessage);
  if (!state.message.empty()) ImGui::TextWrapped("%s", state.message.c_str());
}

}  // namespace

namespace {

// The scene picker: a combo of the scene files in the running scene's folder (scenes/ for the
// shipped ones); choosing one asks the app to open it.
void scene_picker(const SimSession& session, PanelState& state) {
  namespace fs = std::filesystem;
  const fs::path current(session.scene().file);
  if (state.scene_files.empty()) {
    std::error_code ec;
    const fs::path folder = current.has_parent_path() ? current.parent_path() : fs::path(".");
    for (const auto& entry : fs::directory_iterator(folder, ec))
      if (entry.path().extension() == ".toml") state.scene_files.push_back(entry.path().string());
    std::sort(state.scene_files.begin(), state.scene_files.end());
  }
  const std::string name = current.filename().string();
  ImGui::SetNextItemWidth(180.0f);
  if (!ImGui::BeginCombo("##scene", name.c_str())) return;
  for (const std::string& file : state.scene_files) {
    const std::string label = fs::path(file).filename().string();
    if (ImGui::Selectable(label.c_str(), label == name) && label != name) state.open_scene = file;
  }
  ImGui::EndCombo();
}

// A wrapped error line, when there is one.
void error_line(const std::string& text, const char* prefix = "") {
  if (text.empty()) return;
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextColored(kErrorColour, "%s%s", prefix, text.c_str());
  ImGui::PopTextWrapPos();
}

// The display modes 1-7 (the keys), in two rows: one row does not fit the panel's width.
void display_mode_editor(ViewSettings& view) {
  int mode = static_cast<int>(view.mode);
  ImGui::AlignTextToFramePadding();
  ImGui::Text("display");
  ImGui::SameLine();
  ImGui::RadioButton("1 springs", &mode, 1);
  ImGui::SameLine();
  ImGui::RadioButton("2 normals", &mode, 2);
  ImGui::SameLine();
  ImGui::RadioButton("3 shaded", &mode, 3);
  ImGui::RadioButton("4 cloth", &mode, 4);
  ImGui::SameLine();
  ImGui::RadioButton("5 sheer", &mode, 5);
  ImGui::SameLine();
  ImGui::RadioButton("6 weave", &mode, 6);
  ImGui::SameLine();
  ImGui::RadioButton("7 light depth", &mode, 7);
  view.mode = static_cast<DisplayMode>(mode);
}

// The scene's parameters: dynamics (applied at once), the push, the structure (applied on
// Reset) and the parallel switch; returns a clicked action.
std::optional<Action> scene_editors(SimSession& session, PanelState& state) {
  std::optional<Action> clicked;
  Scene& draft = session.draft();
  if (dynamics_editors(draft, session.solver())) session.apply_dynamics();
  error_line(session.error(), "not applied: ");

  const double push_lo = 0.0, push_hi = 10.0;
  ImGui::SliderScalar("push (N*s)", ImGuiDataType_Double, &state.push_strength, &push_lo, &push_hi,
                      "%.3g");
  ImGui::SameLine();
  if (ImGui::SmallButton("P")) clicked = Action::push;

  if (structure_editors(draft)) session.check_structure();
  if (session.structure_pending() && session.structure_error().empty())
    ImGui::TextColored(kWarningColour, "new resolution applies on Reset (R)");
  error_line(session.structure_error());

  bool parallel = session.parallel();
  if (ImGui::Checkbox("parallel solver (M)", &parallel)) clicked = Action::toggle_parallel;
  if (const ThreadTrial* trial = session.thread_trial()) {
    if (trial->parallel_cost() <= 0.0)
      ImGui::TextDisabled("  auto: measuring both settings");
    else
      ImGui::TextDisabled("  auto, ms/step: 1 thread %.3g, parallel %.3g",
                          1e3 * trial->serial_cost(), 1e3 * trial->parallel_cost());
  }
  return clicked;
}

}  // namespace

float framing_shift(const PanelState& state, float window_width) {
  if (!state.panel_open || window_width <= 0.0f) return 0.0f;
  return std::clamp(state.panel_right() / window_width, 0.0f, 0.5f);
}

float panel_width(float window_width) {
  return std::clamp(0.3f * window_width, 300.0f, 380.0f);
}

std::optional<Action> draw_control_panel(SimSession& session, ViewSettings& view, PanelState& state,
                                         const FrameStats& stats) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  // Width from the window's, height following the content (error lines come and go) up to the
  // window's height, where the panel scrolls.
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float tallest = std::max(100.0f, viewport->WorkSize.y - 20.0f);
  const float width = panel_width(viewport->WorkSize.x);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, tallest));
  ImGui::SetNextWindowCollapsed(viewport->WorkSize.x < kCollapsedPanelBelow,
                                ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(1.0f);  // opaque: the scene is not drawn under it
  std::optional<Action> clicked;
  state.panel_open = ImGui::Begin("ClothLab", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  state.panel_x = ImGui::GetWindowPos().x;
  state.panel_y = ImGui::GetWindowPos().y;
  state.panel_w = ImGui::GetWindowSize().x;
  state.panel_h = ImGui::GetWindowSize().y;
  if (!state.panel_open) {
    ImGui::End();
    return clicked;
  }
  ImGui::PushItemWidth(-150.0f);  // room for the labels on the right
  scene_picker(session, state);
  ImGui::SameLine();
  ImGui::TextDisabled("(H: keys)");
  clicked = buttons(session);
  if (const auto edited = scene_editors(session, state)) clicked = edited;
  display_mode_editor(view);
  quality_editor(view, state);
  shadow_editors(view);
  ImGui::Text("probe (8 force, 9 velocity, 0 position): %s",
              state.probe ? field_name(*state.probe) : "off");
  draw_view_editors(view);
  ImGui::PopItemWidth();

  ImGui::Separator();
  statistics(session, stats);
  messages(session, stats, state);
  ImGui::End();
  return clicked;
}

void draw_help_overlay(bool& open) {
  if (!open) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(
      ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 10.0f, viewport->WorkPos.y + 10.0f),
      ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (ImGui::Begin("Keys", &open,
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                       ImGuiWindowFlags_NoMove)) {
    if (ImGui::BeginTable("keys", 2)) {
      for (const KeyBinding& b : key_bindings()) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(b.name.data(), b.name.data() + b.name.size());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(b.help.data(), b.help.data() + b.help.size());
      }
      for (const MouseBinding& m : mouse_bindings()) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(m.gesture.data(), m.gesture.data() + m.gesture.size());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(m.help.data(), m.help.data() + m.help.size());
      }
      ImGui::EndTable();
    }
    // The assignment asks 9 for the velocity probe and for the parallel solver; one key cannot
    // do both, so the probes keep 8 / 9 / 0 together and M switches the solver.
    ImGui::TextDisabled("9 probes the velocity, so the parallel solver is M, not 9.");
  }
  ImGui::End();
}

const char* field_name(Field field) {
  switch (field) {
    case Field::force:
      return "force";
    case Field::velocity:
      return "velocity";
    case Field::position:
      return "position";
  }
  return "?";
}

void draw_probe_overlay(const std::string& text, float x, float y, float panel_right) {
  // Below right of the cursor, or on the other side where the window's edge is nearer, so the
  // readout stays inside the window; never over the panel (left of panel_right).
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const bool right = x > viewport->WorkPos.x + 0.5f * viewport->WorkSize.x;
  const bool low = y > viewport->WorkPos.y + 0.5f * viewport->WorkSize.y;
  const float left_edge = right ? x - 16.0f : std::max(x + 16.0f, panel_right + 8.0f);
  ImGui::SetNextWindowPos(ImVec2(left_edge, y + (low ? -16.0f : 16.0f)), ImGuiCond_Always,
                          ImVec2(right ? 1.0f : 0.0f, low ? 1.0f : 0.0f));
  ImGui::SetNextWindowBgAlpha(0.85f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                                 ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("probe", nullptr, flags)) ImGui::TextUnformatted(text.c_str());
  ImGui::End();
}

void draw_status_overlay(const SimSession& session, const FrameStats& stats) {
  std::string line;
  ImVec4 colour = kWarningColour;
  if (session.divergence()) {
    line = "Simulation stopped: " + session.divergence()->message() + "  --  R resets";
    colour = kErrorColour;
  } else if (session.paused) {
    line = "Paused  (Space runs, . steps)";
    colour = ImVec4(1, 1, 1, 1);
  } else if (stats.behind()) {
    line = stats.behind_reason(session.solver().dt());
  }
  if (line.empty()) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + 0.5f * viewport->WorkSize.x,
                                 viewport->WorkPos.y + viewport->WorkSize.y - 10.0f),
                          ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                                 ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f),
                                      ImVec2(0.7f * viewport->WorkSize.x, FLT_MAX));
  if (ImGui::Begin("status", nullptr, flags)) {
    ImGui::PushTextWrapPos(0.7f * viewport->WorkSize.x - 20.0f);
    ImGui::TextColored(colour, "%s", line.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

}  // namespace clothlab::vis
