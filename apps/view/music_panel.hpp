// The "Music" panel for a scene with [music]: where the track came from, the tempo the beat
// tracker found, whether it is heard, the beat the simulation is on, and the three band energies
// over the last few seconds of simulated time with the beats marked -- what the mannequin dances
// to, next to the dance. A window of its own in the view's bottom-right corner: the control
// panel already fills the height of an 800-point window.
#pragma once

#include <imgui.h>

#include <array>

#include "sim/scene/scene.hpp"

namespace clothlab::vis {

// The plot's points, kept between frames: drawing it allocates nothing beyond ImGui's own
// draw-list growth.
struct MusicPlot {
  static constexpr int kPoints = 200;            // per band: 20 ms apart over the window
  static constexpr double kWindowSeconds = 4.0;  // of simulated time, ending now
  std::array<ImVec2, kPoints> line{};
};

// Draws the panel at simulated time t (s). status: how the music is heard (MusicSync).
// Cost: 3 x kPoints band_level look-ups and one binary search in the beats per frame.
void draw_music_panel(const MusicSpec& music, double t, const char* status, MusicPlot& plot);

}  // namespace clothlab::vis
