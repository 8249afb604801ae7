#include "vis/overlay/color_bar.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace clothlab::vis {

namespace {

// colormap_sample is sRGB already, and the UI is drawn without GL_FRAMEBUFFER_SRGB (view_app),
// so the bytes go to the screen as they are.
ImU32 to_imgui(glm::vec3 srgb) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(srgb.r, srgb.g, srgb.b, 1.0f));
}

// Light text over a dark one-pixel shadow: readable on both light and dark backgrounds.
void shadowed_text(ImDrawList* draw, ImVec2 at, const char* text) {
  draw->AddText(ImVec2(at.x + 1.0f, at.y + 1.0f), IM_COL32(0, 0, 0, 220), text);
  draw->AddText(at, IM_COL32(255, 255, 255, 255), text);
}

constexpr float kLabelOffset = 10.0f;  // from the bar's right edge to its labels

// The values labelled beside a bar and their text: both ends of the range (one decimal finer
// than the ticks, so the exact range can be read), then nice ticks at least a text line away
// from the ends. Needs a current ImGui context (font size).
std::vector<std::pair<double, std::string>> bar_labels(ImVec2 size, ScalarRange range) {
  const int target = std::clamp(static_cast<int>(size.y / 40.0f), 2, 10);
  const double step = nice_step(range.min, range.max, target);
  std::vector<std::pair<double, std::string>> labels = {
      {range.min, format_tick(range.min, 0.1 * step)},
      {range.max, format_tick(range.max, 0.1 * step)}};
  const double clearance = 1.2 * ImGui::GetFontSize() / size.y * (range.max - range.min);
  for (double v : nice_ticks(range.min, range.max, target))
    if (v - range.min > clearance && range.max - v > clearance)
      labels.emplace_back(v, format_tick(v, step));
  return labels;
}

}  // namespace

void draw_color_bar(ImDrawList* draw, ImVec2 top_left, ImVec2 size, ColorMap map, ScalarRange range,
                    const char* title, const char* unit) {
  if (!draw || size.x <= 0.0f || size.y <= 0.0f) return;
  const float x0 = top_left.x, x1 = top_left.x + size.x;
  const float top = top_left.y, bottom = top_left.y + size.y;

  // Stacked strips, each a vertical gradient between colormap_sample at its ends. ImGui blends
  // vertex colours in sRGB bytes rather than linear light, so strips are kept at most a few
  // pixels tall (at least 64 of them) to keep that difference below a byte.
  const int strips = std::clamp(static_cast<int>(size.y / 2.0f), 64, 256);
  for (int i = 0; i < strips; ++i) {
    const double t_top = 1.0 - double(i) / strips, t_bottom = 1.0 - double(i + 1) / strips;
    const float y_top = top + size.y * float(i) / strips;
    const float y_bottom = top + size.y * float(i + 1) / strips;
    const ImU32 c_top = to_imgui(colormap_sample(map, t_top));
    const ImU32 c_bottom = to_imgui(colormap_sample(map, t_bottom));
    draw->AddRectFilledMultiColor(ImVec2(x0, y_top), ImVec2(x1, y_bottom), c_top, c_top, c_bottom,
                                  c_bottom);
  }
  const ImU32 frame = IM_COL32(20, 20, 20, 255);
  draw->AddRect(ImVec2(x0 - 1.0f, top - 1.0f), ImVec2(x1 + 1.0f, bottom + 1.0f), frame);

  // The range's ends, then "nice" ticks about every 40 pixels that keep clear of them.
  const float font = ImGui::GetFontSize();
  for (const auto& [v, label] : bar_labels(size, range)) {
    const float y = bottom - size.y * static_cast<float>(normalise(v, range));
    draw->AddLine(ImVec2(x1 + 1.0f, y), ImVec2(x1 + 5.0f, y), frame, 2.0f);
    draw->AddLine(ImVec2(x1 + 1.0f, y), ImVec2(x1 + 4.0f, y), IM_COL32(255, 255, 255, 255));
    // A gap after the tick mark, so it never reads as a minus sign.
    shadowed_text(draw, ImVec2(x1 + kLabelOffset, y - 0.5f * font), label.c_str());
  }

  const std::string heading = color_bar_heading(title, unit);
  if (!heading.empty()) shadowed_text(draw, ImVec2(x0, top - font - 4.0f), heading.c_str());
}

std::string color_bar_heading(const char* title, const char* unit) {
  std::string heading = title ? title : "";
  if (unit && *unit) heading += std::string(heading.empty() ? "[" : " [") + unit + "]";
  return heading;
}

float color_bar_extent(ImVec2 size, ScalarRange range, const char* title, const char* unit) {
  float labels = 0.0f;
  for (const auto& [v, label] : bar_labels(size, range))
    labels = std::max(labels, ImGui::CalcTextSize(label.c_str()).x);
  const float heading = ImGui::CalcTextSize(color_bar_heading(title, unit).c_str()).x;
  return std::max(heading, size.x + kLabelOffset + labels);
}

}  // namespace clothlab::vis
