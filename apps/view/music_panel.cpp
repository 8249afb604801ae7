#include "apps/view/music_panel.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "apps/view/control_panel.hpp"
#include "music/beat_tracker.hpp"
#include "music/music_track.hpp"

namespace clothlab::vis {
namespace {

constexpr float kPlotHeight = 90.0f;
// One colour per band, low to high: warm for the kick, green for the snare's body, blue for the
// hats; the same order as AudioBand.
constexpr std::array<ImU32, 3> kBandColours = {
    IM_COL32(255, 120, 90, 255), IM_COL32(120, 220, 120, 255), IM_COL32(110, 160, 255, 255)};
const char* const kBandNames[3] = {"low", "mid", "high"};

// "beat 17 of 80 (phase 0.42)": the beat the simulation is on and how far to the next, as a bar
// filling once per beat.
void beat_readout(const BeatTrack& analysis, double t) {
  const double phase = beat_phase(analysis.beats, t);
  if (analysis.beats.size() < 2) {
    ImGui::TextDisabled("no beats found");
    return;
  }
  char label[64];
  if (phase < 0.0) {
    std::snprintf(label, sizeof label, "before the first beat");
  } else {
    std::snprintf(label, sizeof label, "beat %ld of %zu  (phase %.2f)",
                  static_cast<long>(std::floor(phase)) + 1, analysis.beats.size(),
                  phase - std::floor(phase));
  }
  const float fraction = phase < 0.0 ? 0.0f : static_cast<float>(phase - std::floor(phase));
  ImGui::ProgressBar(fraction, ImVec2(-1.0f, 0.0f), label);
}

// Band energies from t - kWindowSeconds to t (never before 0) as three lines over a dark box,
// with a vertical tick at every beat in the window.
void band_plot(const BeatTrack& analysis, double t, MusicPlot& plot) {
  const float width = std::max(ImGui::GetContentRegionAvail().x, 50.0f);
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  const ImVec2 p1(p0.x + width, p0.y + kPlotHeight);
  ImGui::InvisibleButton("##bands", ImVec2(width, kPlotHeight));
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(p0, p1, IM_COL32(20, 22, 28, 255));
  const double t0 = t - MusicPlot::kWindowSeconds;
  auto x_of = [&](double time) {
    return p0.x + static_cast<float>((time - t0) / MusicPlot::kWindowSeconds) * width;
  };
  const auto& beats = analysis.beats;
  for (auto it = std::lower_bound(beats.begin(), beats.end(), std::max(t0, 0.0));
       it != beats.end() && *it <= t; ++it) {
    const float x = x_of(*it);
    draw->AddLine(ImVec2(x, p0.y), ImVec2(x, p1.y), IM_COL32(220, 220, 220, 150));
  }
  constexpr int n = MusicPlot::kPoints;
  const double step = MusicPlot::kWindowSeconds / (n - 1);
  // The first sample at or after t = 0: the window reaches back before the start for 4 s.
  const int first = std::clamp(static_cast<int>(std::ceil(-t0 / step)), 0, n);
  const float inner = kPlotHeight - 4.0f;
  for (int band = 0; band < 3; ++band) {
    for (int k = first; k < n; ++k) {
      const double time = t0 + k * step;
      const float level = static_cast<float>(band_level(analysis.bands, time, band));
      plot.line[k] = ImVec2(x_of(time), p1.y - 2.0f - level * inner);
    }
    if (n - first >= 2)
      draw->AddPolyline(plot.line.data() + first, n - first, kBandColours[band], ImDrawFlags_None,
                        1.5f);
  }
  for (int band = 0; band < 3; ++band) {
    if (band > 0) ImGui::SameLine();
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(kBandColours[band]), "%s", kBandNames[band]);
  }
  ImGui::SameLine();
  ImGui::TextDisabled("energy over the last %.0f s; ticks: beats", MusicPlot::kWindowSeconds);
}

}  // namespace

void draw_music_panel(const MusicSpec& music, double t, const char* status, MusicPlot& plot) {
  if (!music.track) return;
  // Kept in the bottom-right corner as the window resizes; its title bar collapses it.
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 10.0f,
                                 viewport->WorkPos.y + viewport->WorkSize.y - 10.0f),
                          ImGuiCond_Always, ImVec2(1.0f, 1.0f));
  const float width = panel_width(viewport->WorkSize.x);  // as the control panel
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, FLT_MAX));
  if (!ImGui::Begin("Music", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  const MusicTrack& track = *music.track;
  ImGui::PushTextWrapPos(0.0f);
  ImGui::Text("source  %s", track.source.c_str());
  ImGui::PopTextWrapPos();
  if (track.analysis.bpm > 0.0)
    ImGui::Text("tempo   %.1f BPM detected, %zu beats", track.analysis.bpm,
                track.analysis.beats.size());
  else
    ImGui::Text("tempo   none detected");
  ImGui::Text("audio   %s", status);
  beat_readout(track.analysis, t);
  band_plot(track.analysis, t, plot);
  ImGui::End();
}

}  // namespace clothlab::vis
