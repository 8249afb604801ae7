// The Dear ImGui side of the window: the control panel (edits the live scene's draft and shows
// statistics), the help overlay (H) and the status overlay (pause, "can't keep up", divergence).
// Immediate mode: each function reads and writes the state it is given, every frame.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "apps/view/frame_stats.hpp"
#include "apps/view/input.hpp"
#include "apps/view/sim_session.hpp"
#include "vis/passes/field_pass.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab::vis {

// Window options that are not about how the cloth is drawn (those live in ViewSettings).
// What the panel says while the cloth's pins are released (D), and the window prints when it
// happens.
inline constexpr const char* kPinsReleasedMessage =
    "pins released: the cloth drops (R pins it again)";

struct PanelState {
  double push_strength = 0.5;  // N*s, momentum of one push (P)
  bool show_help = false;
  std::optional<Field> probe;  // keys 8 / 9 / 0; nothing: probing off (no field pass drawn)
  std::string message;         // last notice, e.g. where a screenshot went
  // The scene picker: the .toml files beside the running scene (listed once), and the one the
  // user chose this frame, for the app to open.
  std::vector<std::string> scene_files;
  std::optional<std::string> open_scene;
  std::string gl_renderer;  // GL_RENDERER, for what render.quality = "auto" chose
  int cloth_stride = 1;     // the last frame drew every cloth_stride-th vertex of a large grid
  int scene_width = 0, scene_height = 0;  // the pixels the last frame drew the scene at
  bool panel_open = false;                // not collapsed to its title bar last frame
  // The panel's rectangle last frame (window points, origin top-left): the scene is not shaded
  // under it while it is open.
  float panel_x = 0.0f, panel_y = 0.0f, panel_w = 0.0f, panel_h = 0.0f;
  float panel_right() const { return panel_x + panel_w; }
};

// The camera's lens shift (normalised device x) that centres the scene in the part of a window
// `window_width` points wide that the open panel leaves free: the free part's centre is
// panel_right / 2 points right of the window's, panel_right / width in device units.
float framing_shift(const PanelState& state, float window_width);

// Draws the panel. Applies edits to the session (values that keep the topology at once, a
// resolution on Reset) and returns the action of a clicked button, dispatched like its key.
// The panels' width in a window `window_width` points wide: 380 points from 1280 up, narrower
// below (30 % of the window, at least 300), so a 1024-point screen keeps two thirds for the cloth.
float panel_width(float window_width);
// Below this width the control panel starts collapsed (its title bar opens it; H lists the keys).
inline constexpr float kCollapsedPanelBelow = 1100.0f;

std::optional<Action> draw_control_panel(SimSession& session, ViewSettings& view, PanelState& state,
                                         const FrameStats& stats);

// Every key of the key table and the mouse controls.
void draw_help_overlay(bool& open);

// The probe's readout (lines of text) in a small tooltip-like window at (x, y), window
// coordinates, next to the cursor and right of the panel (whose right edge is panel_right).
void draw_probe_overlay(const std::string& text, float x, float y, float panel_right);

const char* field_name(Field field);

// A line at the bottom of the window when the simulation is paused, behind real time or stopped
// on divergence.
void draw_status_overlay(const SimSession& session, const FrameStats& stats);

}  // namespace clothlab::vis
