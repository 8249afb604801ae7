// `clothlab view`: the window's frame loop. Each frame: poll input, advance the simulation by
// the wall-clock time since the previous frame (FrameStepper, so the motion does not depend on
// the frame rate) or, while a scene's music plays, up to the playback position (MusicSync), draw
// the cloth and the panel, and show the time per step and per frame in the title.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/view/cloth_grab.hpp"
#include "apps/view/control_panel.hpp"
#include "apps/view/error_view.hpp"
#include "apps/view/frame_stats.hpp"
#include "apps/view/glfw_window.hpp"
#include "apps/view/input.hpp"
#include "apps/view/music_panel.hpp"
#include "apps/view/music_sync.hpp"
#include "apps/view/sim_session.hpp"
#include "sim/fields/frame_fields.hpp"
#include "sim/realtime/frame_stepper.hpp"
#include "sim/scene/scene.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab::vis {

class Diagnostics;
class OffscreenTarget;
class FieldPass;
class ImGuiLayer;
class Renderer;

// Test hooks, read from the environment so the window can be tested under a virtual display
// (xvfb-run) without a person at the keyboard. Not part of the documented interface:
//   CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=N  quit by itself after frame N;
//   CLOTHLAB_VIEW_SCREENSHOT=file.png  write the last frame (N, default 60) to file.png;
//   CLOTHLAB_VIEW_KEYS="H,1,,P"        press these keys, one per frame from frame 1, by their
//                                      names in the help (an empty entry presses nothing);
//   CLOTHLAB_VIEW_CURSOR="X,Y"           probes (keys 8 / 9 / 0) read at window point (X, Y)
//                                      instead of the mouse cursor;
//   CLOTHLAB_VIEW_CLICK=N              a left click at that point on frame N (pins the probe);
//   CLOTHLAB_VIEW_RECORD=file.csv      press Record on frame 1 (or the frame after the click),
//                                      writing to file.csv (the window closing while recording
//                                      must leave it complete);
//   CLOTHLAB_VIEW_OPEN="F:PATH"          opens PATH through the scene picker on frame F (prints
//                                      "clothlab view: opened NAME ...");
//   CLOTHLAB_VIEW_DRAG="X0,Y0,X1,Y1,F0,F1"  a Ctrl + left drag: press at (X0, Y0) on frame F0,
//                                      the cursor moving to (X1, Y1) by the frame halfway to
//                                      F1 and held there, release on frame F1 (prints a line
//                                      "clothlab view: grab: released vertex ...");
//   CLOTHLAB_VIEW_NO_AUDIO=1           never open an audio device: a scene with music runs on
//                                      the simulation clock, as where no device opens (prints
//                                      "clothlab view: audio off ...; running silently ...").
struct ViewHooks {
  long exit_after_frames = 0;  // 0: run until the user quits
  std::string screenshot;
  std::vector<std::string> keys;
  std::optional<std::array<double, 2>> cursor;
  long click_frame = 0;
  std::string record;
  std::optional<std::array<double, 6>> drag;
  long open_frame = 0;  // CLOTHLAB_VIEW_OPEN="FRAME:PATH": the scene picker, on that frame
  std::string open_scene;
  bool no_audio = false;  // CLOTHLAB_VIEW_NO_AUDIO=1

  static ViewHooks from_environment();
};

class ViewApp {
 public:
  // Opens the window and builds the solver. Throws GlUnavailable (no display, no GL 4.5 core),
  // ShaderError, or SceneError (a scene that cannot be built).
  ViewApp(Scene scene, ViewHooks hooks);
  ~ViewApp();
  ViewApp(const ViewApp&) = delete;
  ViewApp& operator=(const ViewApp&) = delete;

  int run();  // until Esc or the window is closed; returns the exit status (0)
  // [ and ] (and --copies): this many copies of the cloth side by side, framed in the view; a
  // scene that cannot be copied says why in the panel and on stdout.
  void change_copies(int copies);

 private:
  void install_callbacks();
  void frame();
  void simulate(double wall_seconds);
  StepCostProbe time_first_steps(double wall_seconds);
  vis::PixelRect covered_by_panel(int width, int height, int window_w, int window_h) const;
  void dispatch(Action action);
  bool dispatch_view(Action action);
  void dispatch_session(Action action);
  void draw(int width, int height);
  void toggle_probe(Field field);
  void probe_under_cursor(int width, int height);
  void click(double x, double y);  // a left click (press and release in place) on the view
  void toggle_record();
  void stop_recording();
  TraceSpec record_spec() const;
  void take_screenshot(const std::string& path, int width, int height);
  void bind_scene_target(int width, int height, bool scaled);
  void update_title();
  void push();
  void release_pins();
  void toggle_error_view();                     // E
  void grab_released(const std::string& line);  // a pull ended: `line` says what was pulled
  void restart_comparison(const char* why);     // push, drop, pull: the error view restarts
  void drag_hook();                             // CLOTHLAB_VIEW_DRAG
  void open_scene(const std::string& path);
  void report_backend();            // prints the session's backend note when it changes
  std::string copies_text() const;  // "1 copy", "4 copies"

  // The window (and its GL context) first: the GPU backend's solver needs the context to be
  // built, and goes before it on destruction.
  std::string scene_name_;
  GlfwWindow window_;
  SimSession session_;
  std::string shown_backend_note_;  // the session's note last printed
  ViewHooks hooks_;
  MusicSync music_;  // the scene's music, and the audio clock while it plays
  MusicPlot music_plot_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<OffscreenTarget> scene_target_;  // only for MSAA or a scaled scene
  // Only while a probe is on (and for the pick of a Ctrl + drag); sized to the framebuffer.
  std::unique_ptr<FieldPass> field_pass_;
  std::unique_ptr<Diagnostics> diagnostics_;  // colour-by scalar and arrows (what is on)
  FieldSnapshot snapshot_;                    // the fields of the frame being drawn
  // Clicking with a probe on pins it to the vertex under the cursor: it follows that vertex.
  std::optional<std::array<double, 2>> pending_click_;
  int pinned_vertex_ = -1;
  std::optional<std::array<double, 2>> left_press_;  // where a left press began, for clicks
  std::string probe_title_;                          // the probe's short readout for the title
  std::unique_ptr<ImGuiLayer> imgui_;  // created after our GLFW callbacks, which it chains to
  ViewSettings view_;
  DisplayMode last_shaded_ = DisplayMode::lambert;
  MouseCamera mouse_;
  ClothGrab grab_;                // Ctrl + left drag
  ErrorView error_;               // E: the distance from a reference run beside this one
  bool colour_by_error_ = false;  // E was pressed: colour by the error from its first comparison
  PanelState panel_;
  FrameStepper stepper_;
  double step_cost_ = 0.0;  // s of wall time per solver step, smoothed; 0: not measured yet
  long costed_build_ = -1;  // the session's build step_cost_ belongs to
  std::optional<double> last_step_seconds_;  // the solver's wall time in the last frame
  std::optional<double> other_seconds_;      // a frame's wall time outside the solver, smoothed
  // Simulated seconds the frames' caps dropped and the frames still owe (FrameStepper::catch_up).
  double catch_up_ = 0.0;
  FrameStats stats_;
  FrameSample run_totals_;  // summed over the run from the second frame, printed on exit
  long run_frames_ = 0;
  // Key actions of this frame, handled after ImGui's NewFrame has decided whether it wants the
  // keyboard (a text field being edited).
  std::vector<Action> pending_actions_;
  long rendered_generation_ = -1;
  long frame_index_ = 0;
  double last_frame_time_ = 0.0, last_title_time_ = -1.0;
  bool screenshot_requested_ = false;
};

}  // namespace clothlab::vis
