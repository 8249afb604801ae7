#include "apps/view/view_app.hpp"

#include "load/scene_load.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <utility>

#include "apps/view/imgui_layer.hpp"
#include "apps/view/probe_readout.hpp"
#include "apps/view/scene_edit.hpp"
#include "apps/view/screenshot.hpp"
#include "apps/view/views_panel.hpp"
#include "factory/solver_factory.hpp"
#include "gl/draw_state.hpp"
#include "gl/gl.hpp"
#include "gl/offscreen_target.hpp"
#include "sim/solver.hpp"
#include "sim/trace/trace_run.hpp"
#include "vis/passes/field_pass.hpp"
#include "vis/render/diagnostics.hpp"
#include "vis/render/frame_request.hpp"
#include "vis/render/render_quality.hpp"
#include "vis/render/renderer.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace clothlab::vis {
namespace {

constexpr int kInitialWidth = 1280, kInitialHeight = 800;
constexpr double kResolutionFactor = 1.25;  // per ] / [ press
constexpr double kTitleRefreshSeconds = 0.25;
constexpr double kClickSlopPixels = 4.0;  // a press and release closer than this is a click

// A per-frame measurement smoothed over frames (a frame's few steps are noisy): the last value
// weighted 0.3.
double smoothed(double previous, double sample) {
  return 0.7 * previous + 0.3 * sample;
}

// The app behind a GLFW window, set with glfwSetWindowUserPointer (no globals).
ViewApp& app_of(GLFWwindow* window) {
  return *static_cast<ViewApp*>(glfwGetWindowUserPointer(window));
}

}  // namespace

ViewApp::ViewApp(Scene scene, ViewHooks hooks)
    : scene_name_(std::filesystem::path(scene.file).filename().string()),
      window_("ClothLab — " + scene_name_, kInitialWidth, kInitialHeight),
      session_(std::move(scene), make_backend_solver),
      hooks_(std::move(hooks)),
      music_(hooks_.no_audio),
      renderer_(std::make_unique<Renderer>()),
      diagnostics_(std::make_unique<Diagnostics>()),
      view_(scene_view(session_.scene(), session_.solver())) {
  install_callbacks();
  imgui_ = std::make_unique<ImGuiLayer>(window_.handle());
  // A push of 0.5 m/s on average over the whole cloth: visible, never violent.
  panel_.push_strength = 0.5 * total_mass(session_.scene());
  panel_.gl_renderer = renderer_->gl_renderer();
  music_.load(session_.scene());
  report_backend();
  last_frame_time_ = glfwGetTime();
}

std::string ViewApp::copies_text() const {
  const int n = session_.copies();
  return std::to_string(n) + (n == 1 ? " copy" : " copies");
}

void ViewApp::report_backend() {
  if (session_.backend_note() == shown_backend_note_) return;
  shown_backend_note_ = session_.backend_note();
  if (shown_backend_note_.empty()) return;
  panel_.message = shown_backend_note_;
  std::printf("clothlab view: %s\n", shown_backend_note_.c_str());
}

// + and -: the scene's cloth repeated side by side, framed so every copy is in view.
void ViewApp::change_copies(int copies) {
  stop_recording();  // a new run starts at t = 0
  const std::string why = session_.set_copies(copies);
  if (!why.empty()) {
    panel_.message = "copies: " + why;
    std::printf("clothlab view: %s\n", panel_.message.c_str());
    return;
  }
  view_.camera = scene_view(session_.scene(), session_.solver()).camera;
  std::printf("clothlab view: %s (%zu vertices)\n", copies_text().c_str(),
              session_.solver().vertex_count());
  last_title_time_ = -1.0;
}

// The GL objects and the UI go before the window, which owns the context.
ViewApp::~ViewApp() {
  imgui_.reset();
  field_pass_.reset();
  diagnostics_.reset();
  renderer_.reset();
}

void ViewApp::install_callbacks() {
  GLFWwindow* w = window_.handle();
  glfwSetWindowUserPointer(w, this);
  glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int) {
    if (const auto a = action_for_key(key, action)) app_of(win).pending_actions_.push_back(*a);
  });
  glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int mods) {
    ViewApp& app = app_of(win);
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(win, &x, &y);
    const bool ui = app.imgui_ && app.imgui_->wants_mouse();
    app.mouse_.button(button, action, mods, ui, x, y);
    // A left press and release in place (not a drag) is a click: it pins the probe.
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    // Ctrl + left drag pulls the cloth: the vertex is picked in the frame's draw.
    if (action == GLFW_PRESS && !ui && (mods & GLFW_MOD_CONTROL)) app.grab_.press(x, y);
    if (action == GLFW_RELEASE) app.grab_released(app.grab_.release(app.session_.solver()));
    if (action == GLFW_PRESS && !ui && !(mods & GLFW_MOD_CONTROL)) {
      app.left_press_ = std::array<double, 2>{x, y};
    } else if (action == GLFW_RELEASE && app.left_press_) {
      const auto [x0, y0] = *app.left_press_;
      app.left_press_.reset();
      if (std::hypot(x - x0, y - y0) < kClickSlopPixels) app.click(x, y);
    }
  });
  glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) {
    ViewApp& app = app_of(win);
    int width = 0, height = 0;
    glfwGetWindowSize(win, &width, &height);
    app.mouse_.move(app.view_, x, y, height);
    app.grab_.drag_to(app.session_.solver(), app.view_.camera, x, y, width, height);
  });
  glfwSetScrollCallback(w, [](GLFWwindow* win, double, double dy) {
    ViewApp& app = app_of(win);
    app.mouse_.scroll(app.view_, dy, app.imgui_ && app.imgui_->wants_mouse());
  });
}

int ViewApp::run() {
  while (!window_.should_close()) {
    frame();
    if (hooks_.exit_after_frames > 0 && frame_index_ >= hooks_.exit_after_frames) break;
  }
  // Closing the window while recording finishes the file: it is complete, never cut short.
  if (session_.recording()) std::printf("clothlab view: %s\n", session_.stop_recording().c_str());
  const std::string errors = error_.summary();
  if (!errors.empty()) std::printf("clothlab view: %s\n", errors.c_str());
  // The run's timing in one line (the panel shows it live): what a benchmark of the window reads.
  if (run_frames_ > 0) {
    const double n = static_cast<double>(run_frames_);
    std::printf(
        "clothlab view: %ld frames: %.2f ms/frame, %.2f ms/frame simulation (%.1f steps), "
        "%.0f %% of real time simulated (%s, %s backend, %zu vertices, scene drawn at %dx%d, "
        "drawn by %s)\n",
        run_frames_, 1e3 * run_totals_.frame_seconds / n, 1e3 * run_totals_.step_seconds / n,
        double(run_totals_.steps) / n,
        run_totals_.frame_seconds > 0.0 ? 100.0 * run_totals_.simulated / run_totals_.frame_seconds
                                        : 0.0,
        copies_text().c_str(), backend_name(session_.solver()), session_.solver().vertex_count(),
        panel_.scene_width, panel_.scene_height, renderer_->gl_renderer().c_str());
  }
  return 0;
}

void ViewApp::frame() {
  ++frame_index_;
  glfwPollEvents();
  imgui_->begin_frame();
  if (imgui_->wants_keyboard()) pending_actions_.clear();  // typing into a field, not commands
  const std::size_t hook = static_cast<std::size_t>(frame_index_ - 1);
  if (hook < hooks_.keys.size()) {
    if (const auto a = action_named(hooks_.keys[hook]))
      pending_actions_.push_back(*a);
    else if (!hooks_.keys[hook].empty())
      std::fprintf(stderr, "clothlab view: test hook: unknown key \"%s\"\n",
                   hooks_.keys[hook].c_str());
  }
  // The record hook presses Record after the click hook (if any), so a pinned vertex is traced.
  if (!hooks_.record.empty() && frame_index_ == std::max(1L, hooks_.click_frame + 1)) {
    try {
      session_.start_recording(hooks_.record, record_spec());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "clothlab view: %s\n", e.what());
    }
  }
  if (frame_index_ == hooks_.click_frame && hooks_.cursor)
    click((*hooks_.cursor)[0], (*hooks_.cursor)[1]);
  drag_hook();
  if (frame_index_ == hooks_.open_frame && !hooks_.open_scene.empty())
    panel_.open_scene = hooks_.open_scene;
  for (Action a : pending_actions_) dispatch(a);
  pending_actions_.clear();

  const double now = glfwGetTime();
  const double wall = now - last_frame_time_;
  last_frame_time_ = now;
  // A rebuilt cloth is shown once at t = 0 before it moves (and before a scene that diverges at
  // once has nothing sane left to show).
  if (rendered_generation_ == session_.generation()) simulate(wall);

  if (const auto clicked = draw_control_panel(session_, view_, panel_, stats_)) dispatch(*clicked);
  // Colouring by the error needs the reference: choosing it in the panel turns the view on.
  if (view_.color.field == ScalarField::error && !error_.on()) toggle_error_view();
  if (colour_by_error_ && error_.has_comparison()) {
    view_.color.field = ScalarField::error;
    colour_by_error_ = false;
  }
  error_.draw_panel();
  if (panel_.open_scene) {
    open_scene(*panel_.open_scene);
    panel_.open_scene.reset();
  }
  report_backend();
  if (view_.mode != DisplayMode::springs) last_shaded_ = view_.mode;
  draw_help_overlay(panel_.show_help);
  draw_status_overlay(session_, stats_);
  if (session_.scene().music)
    draw_music_panel(*session_.scene().music, session_.solver().time(), music_.status(),
                     music_plot_);

  int width = 0, height = 0;
  window_.framebuffer_size(width, height);
  if (width > 0 && height > 0) {
    draw(width, height);
  } else {
    imgui_->end_frame_without_drawing();  // minimised
  }
  const bool last_hook_frame =
      hooks_.exit_after_frames > 0 && frame_index_ >= hooks_.exit_after_frames;
  if (screenshot_requested_) take_screenshot(screenshot_file_name(), width, height);
  if (last_hook_frame && !hooks_.screenshot.empty())
    take_screenshot(hooks_.screenshot, width, height);
  screenshot_requested_ = false;
  window_.swap_buffers();
  update_title();
}

// Advances by the wall time of the last frame (up to the music's playback position while it
// plays) within the solver's share of that frame (FrameStepper), and measures the solver.
void ViewApp::simulate(double wall_seconds) {
  FrameSample sample;
  sample.frame_seconds = wall_seconds;
  if (session_.builds() != costed_build_) {  // another solver: its cost is measured afresh
    costed_build_ = session_.builds();
    step_cost_ = 0.0;
  }
  const double before = session_.solver().time();
  // The error view's shown run waits while the reference is on its way to the last time.
  const bool waiting = !error_.may_advance();
  const bool running = !session_.paused && !session_.divergence() && !waiting;
  const double dt = session_.solver().dt();
  const StepCostProbe probe =
      running && step_cost_ == 0.0 ? time_first_steps(wall_seconds) : StepCostProbe{};
  if (probe.steps > 0) step_cost_ = probe.cost;
  const double probed = double(probe.steps) * dt;  // simulated by the timed steps
  // What the frames spend outside the solver (drawing, events), smoothed as the step's cost is:
  // the solver may fill a 1/20 s frame beside it.
  if (last_step_seconds_) {
    const double other = std::max(0.0, wall_seconds - *last_step_seconds_);
    other_seconds_ = other_seconds_ ? smoothed(*other_seconds_, other) : other;
  }
  FrameCap cap = stepper_.cap(wall_seconds, step_cost_, dt, other_seconds_);
  cap.seconds = std::max(0.0, cap.seconds - probed);
  // Without music the frame also asks for what earlier frames' caps dropped (catch_up_); the
  // music's clock keeps its own time.
  const double owed =
      music_.audible() || !running ? 0.0 : FrameStepper::catch_up(catch_up_, wall_seconds);
  const double request =
      waiting ? 0.0 : music_.frame_advance(session_, wall_seconds - probed + owed, cap.seconds);
  const auto t0 = std::chrono::steady_clock::now();
  const FrameAdvance r = session_.advance(stepper_, request, cap);
  catch_up_ = running && !music_.audible() ? FrameStepper::owed_after(catch_up_, owed, r) : 0.0;
  sample.step_seconds =
      probe.seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  sample.steps = probe.steps + r.steps;
  last_step_seconds_ = sample.step_seconds;
  sample.simulated = session_.solver().time() - before;
  sample.requested = running ? std::max(0.0, request - owed) + probed : 0.0;
  sample.limit = r.capped ? r.limit : FrameLimit::none;
  stats_.add(sample);
  error_.after_advance(session_, sample.step_seconds, sample.simulated, wall_seconds);
  if (running)
    session_.measured_frame(sample.steps, sample.step_seconds,
                            std::chrono::duration<double>(t0.time_since_epoch()).count());
  // The cost of a step, smoothed over frames (a frame's steps can be few and noisy).
  if (r.steps > 0 && probe.steps == 0) {
    const double cost = sample.step_seconds / double(r.steps);
    step_cost_ = step_cost_ > 0.0 ? smoothed(step_cost_, cost) : cost;
  }
  if (frame_index_ > 1) {  // the first frame's wall time includes start-up
    run_totals_.frame_seconds += sample.frame_seconds;
    run_totals_.step_seconds += sample.step_seconds;
    run_totals_.steps += sample.steps;
    run_totals_.simulated += sample.simulated;
    ++run_frames_;
  }
}

// A new solver's first steps of this frame, one at a time and timed (probe_step_cost), within
// the frame's solver share and the real time it asks for.
StepCostProbe ViewApp::time_first_steps(double wall_seconds) {
  const double dt = session_.solver().dt();
  const long fit = static_cast<long>(std::floor(wall_seconds / dt));
  return probe_step_cost(
      stepper_.solver_share() * wall_seconds, std::min(FrameStepper::kCostSteps, fit), [&] {
        const auto t0 = std::chrono::steady_clock::now();
        session_.single_step();
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return session_.divergence() ? -1.0 : s;
      });
}

void ViewApp::dispatch(Action action) {
  if (!dispatch_view(action)) dispatch_session(action);
}

// What only changes the view (modes, probes, arrows, the help, a screenshot, quitting); false
// for the session's actions.
bool ViewApp::dispatch_view(Action action) {
  switch (action) {
    case Action::mode_springs:
    case Action::mode_normals:
    case Action::mode_lambert:
    case Action::mode_cloth_brdf:
    case Action::mode_translucent:
    case Action::mode_weave:
    case Action::mode_light_depth:
      select_mode(view_, last_shaded_, action);
      return true;
    case Action::probe_force:
      toggle_probe(Field::force);
      return true;
    case Action::probe_velocity:
      toggle_probe(Field::velocity);
      return true;
    case Action::probe_position:
      toggle_probe(Field::position);
      return true;
    case Action::toggle_force_arrows:
      view_.arrows.force = !view_.arrows.force;
      return true;
    case Action::toggle_normal_arrows:
      view_.arrows.normals = !view_.arrows.normals;
      return true;
    case Action::toggle_contact_view:
      view_.color.field =
          view_.color.field == ScalarField::contact ? ScalarField::none : ScalarField::contact;
      return true;
    case Action::toggle_help:
      panel_.show_help = !panel_.show_help;
      return true;
    case Action::screenshot:
      screenshot_requested_ = true;
      return true;
    case Action::quit:
      window_.request_close();
      return true;
    default:
      return false;
  }
}

// What acts on the simulation: pushes, wind, pins, pause and steps, reset, resolution, copies,
// threads, recording.
void ViewApp::dispatch_session(Action action) {
  switch (action) {
    case Action::toggle_record:
      toggle_record();
      break;
    case Action::push:
      push();
      break;
    case Action::toggle_wind:
      session_.toggle_wind();
      break;
    case Action::release_pins:
      release_pins();
      break;
    case Action::pause:
      session_.paused = !session_.paused;
      break;
    case Action::single_step:  // from a running simulation: stop there, then step
      if (session_.paused) session_.single_step();
      session_.paused = true;
      break;
    case Action::reset:
      stop_recording();  // the rows so far are one run; a new run starts at t = 0
      session_.reset();
      break;
    case Action::more_vertices:
    case Action::fewer_vertices:
      stop_recording();  // the traced vertices change with the resolution
      session_.scale_resolution(action == Action::more_vertices ? kResolutionFactor
                                                                : 1.0 / kResolutionFactor);
      break;
    case Action::more_copies:
      change_copies(2 * session_.copies());
      break;
    case Action::fewer_copies:
      change_copies(session_.copies() / 2);
      break;
    case Action::toggle_parallel:
      session_.toggle_parallel();
      break;
    case Action::toggle_error_view:
      toggle_error_view();
      break;
    default:
      break;
  }
}

// Along the camera's view direction, so the cloth moves away from the viewer.
void ViewApp::push() {
  const glm::vec3 d = glm::normalize(view_.camera.target - view_.camera.eye());
  const double s = panel_.push_strength;
  session_.push(Vec3d{s * d.x, s * d.y, s * d.z});
  restart_comparison("push");
}

// D: the cloth lets go of its pins and drops (onto the colliders); R pins it again.
void ViewApp::release_pins() {
  session_.solver().release_pins();
  if (!session_.solver().pins_released()) return;
  restart_comparison("drop");
  std::printf("clothlab view: %s\n", kPinsReleasedMessage);
}

// E (and the panel's colour-by "error"): the reference beside the shown run, the cloth coloured
// by its distance; again: off, and the cloth's colours back to none.
void ViewApp::toggle_error_view() {
  panel_.message = error_.toggle(session_);
  std::printf("clothlab view: %s\n", panel_.message.c_str());
  // The cloth takes the error's colours with the first comparison (none before: not a distance
  // of zero).
  colour_by_error_ = error_.on();
  if (!error_.on() && view_.color.field == ScalarField::error)
    view_.color.field = ScalarField::none;
}

// A pull changed the shown run by hand: the comparison starts again from where it left the cloth.
void ViewApp::grab_released(const std::string& line) {
  if (!line.empty()) restart_comparison("pull");
}

// The shown run was changed by hand: the error view compares afresh from its state now.
void ViewApp::restart_comparison(const char* why) {
  if (!error_.on()) return;
  error_.restart(session_, why);
  std::printf("clothlab view: error view: %s\n", error_.note().c_str());
}

// The scripted Ctrl + left drag of CLOTHLAB_VIEW_DRAG: what the mouse callbacks would do.
void ViewApp::drag_hook() {
  if (!hooks_.drag) return;
  const std::array<double, 6>& d = *hooks_.drag;
  const long f0 = std::lround(d[4]), f1 = std::lround(d[5]);
  if (frame_index_ == f0) {
    grab_.press(d[0], d[1]);
  } else if (frame_index_ > f0 && frame_index_ < f1) {
    const double s =
        std::min(1.0, double(frame_index_ - f0) / std::max(1.0, 0.5 * double(f1 - f0)));
    int w = 0, h = 0;
    glfwGetWindowSize(window_.handle(), &w, &h);
    grab_.drag_to(session_.solver(), view_.camera, d[0] + s * (d[2] - d[0]),
                  d[1] + s * (d[3] - d[1]), w, h);
  } else if (frame_index_ == f1) {
    const std::string line = grab_.release(session_.solver());
    std::printf("clothlab view: grab: %s\n", line.empty() ? "nothing grabbed" : line.c_str());
    grab_released(line);
  }
}

// The scene picker (or CLOTHLAB_VIEW_OPEN): the chosen file replaces the running scene, with
// its own view; a file that cannot be read or built leaves the running one and says why.
void ViewApp::open_scene(const std::string& path) {
  try {
    session_.load(read_scene_file(path));
  } catch (const SceneError& e) {
    panel_.message = e.what();
    std::printf("clothlab view: not opened: %s\n", e.what());
    return;
  }
  view_ = scene_view(session_.scene(), session_.solver());
  scene_name_ = std::filesystem::path(path).filename().string();
  panel_.push_strength = 0.5 * total_mass(session_.scene());
  panel_.probe.reset();
  music_.load(session_.scene());
  std::printf("clothlab view: opened %s (%zu vertices, %zu colliders)\n", scene_name_.c_str(),
              session_.solver().vertex_count(), session_.scene().colliders.size());
  update_title();
}

// The open control panel's rectangle in framebuffer pixels (GL's bottom-left origin), shrunk to
// whole pixels it covers: the scene is not shaded there.
vis::PixelRect ViewApp::covered_by_panel(int width, int height, int window_w, int window_h) const {
  if (!panel_.panel_open || window_w <= 0 || window_h <= 0) return {};
  const float sx = float(width) / float(window_w), sy = float(height) / float(window_h);
  const int x0 = int(std::ceil(panel_.panel_x * sx));
  const int x1 = int(std::floor((panel_.panel_x + panel_.panel_w) * sx));
  const int top = int(std::ceil(panel_.panel_y * sy));
  const int bottom = int(std::floor((panel_.panel_y + panel_.panel_h) * sy));
  if (x1 <= x0 || bottom <= top) return {};
  return {x0, height - bottom, x1 - x0, bottom - top};
}

void ViewApp::draw(int width, int height) {
  Solver& solver = session_.solver();
  int window_w = 0, window_h = 0;  // points, as the panel's rectangle (framebuffer: pixels)
  glfwGetWindowSize(window_.handle(), &window_w, &window_h);
  view_.camera.lens_shift = framing_shift(panel_, float(window_w));
  if (rendered_generation_ != session_.generation()) {
    renderer_->set_cloth(solver);  // a reset may have changed the vertex count
    renderer_->set_scene(session_.scene().render, solver, session_.scene().colliders);
    diagnostics_->set_cloth();
    snapshot_.forget_topology();
    pinned_vertex_ = -1;
    grab_.forget();  // its vertex belonged to the old solver
    rendered_generation_ = session_.generation();
  }
  // A diverged state is all NaN or kilometres away: keep showing the last sane one. One field
  // snapshot per frame serves the cloth, the diagnostics, the probe and a grab's pick.
  const bool probing = panel_.probe || grab_.pending();
  if (!session_.divergence()) {
    snapshot_.take(solver, frame_request(view_, *renderer_, probing));
    if (view_.color.field == ScalarField::error)
      snapshot_.set_reference_distance(error_.per_vertex());
    const FrameFields& fields = snapshot_.fields();
    renderer_->update_cloth(fields);
    diagnostics_->update(solver, fields, view_, *renderer_);
  }
  // At fast quality the scene is drawn at fewer pixels and scaled up (render_quality.hpp).
  const float scale = window_scale(renderer_->quality(view_), view_.mode, view_.window_scale);
  const int scene_w = std::max(1, int(std::lround(scale * float(width))));
  const int scene_h = std::max(1, int(std::lround(scale * float(height))));
  bind_scene_target(scene_w, scene_h, scene_w != width || scene_h != height);
  // The shadow map scales with the pixels drawn: as many of its texels to a pixel as at 1.
  ViewSettings drawn = view_;
  drawn.shadow_map_size = scaled_shadow_map(view_.shadow_map_size, scale);
  renderer_->draw(drawn, scene_w, scene_h, covered_by_panel(scene_w, scene_h, window_w, window_h));
  panel_.cloth_stride = renderer_->cloth_stride();
  panel_.scene_width = scene_w;
  panel_.scene_height = scene_h;
  diagnostics_->draw(view_, *renderer_);
  if (scene_target_) {  // the opaque panel covers its rectangle: nothing is scaled up there
    const vis::PixelRect panel = covered_by_panel(width, height, window_w, window_h);
    scene_target_->resolve_around(0, width, height, panel.x, panel.y, panel.width, panel.height);
  }
  draw_legends(view_, *diagnostics_, renderer_->strain_range(), error_.panel_bottom());
  if (grab_.pending() && session_.divergence()) grab_.forget();  // nothing sane to pull
  if (grab_.pending()) {
    grab_.pick(solver, snapshot_.fields(), *renderer_, field_pass_, view_, width, height, window_w,
               window_h);
    if (!panel_.probe) field_pass_.reset();
  }
  if (panel_.probe) probe_under_cursor(width, height);
  bind_target(0, width, height);
  // The UI's colours are sRGB already: no second encoding.
  set_capability(GL_FRAMEBUFFER_SRGB, false);
  imgui_->end_frame();
}

// Where the scene is drawn: a target of its own when the render quality asks for MSAA or fewer
// pixels than the window's (resolved or scaled into the window after), else the window's
// framebuffer itself.
void ViewApp::bind_scene_target(int width, int height, bool scaled) {
  const int samples = msaa_samples(renderer_->quality(view_), view_.mode);
  if (samples <= 1 && !scaled) {
    scene_target_.reset();
    bind_target(0, width, height);
    return;
  }
  if (!scene_target_ || scene_target_->width() != width || scene_target_->height() != height ||
      scene_target_->samples() != samples)
    scene_target_ = std::make_unique<OffscreenTarget>(width, height, samples);
  scene_target_->bind();
}

void ViewApp::take_screenshot(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0) return;
  try {
    write_png(read_default_framebuffer(width, height), path);
    panel_.message = "screenshot: " + path;
    std::printf("clothlab view: wrote %s\n", path.c_str());
  } catch (const std::exception& e) {
    panel_.message = e.what();  // a full disk is no reason to close the window
    std::fprintf(stderr, "clothlab view: %s\n", e.what());
  }
}

// "ClothLab — default.toml — sim 0.041 ms/step, frame 16 ms, 60 fps, t = 3.20 s — 4 copies on
// the GPU" (the solver's time per step, the whole frame, frames per second, simulated time),
// refreshed a few times a second; when the solver cannot keep up, what it keeps of real time.
void ViewApp::update_title() {
  const double now = glfwGetTime();
  if (now - last_title_time_ < kTitleRefreshSeconds) return;
  last_title_time_ = now;
  char timing[160];
  std::snprintf(timing, sizeof timing, "sim %.3g ms/step, frame %.0f ms, %.0f fps, t = %.2f s",
                stats_.ms_per_step(), stats_.frame_ms(), stats_.fps(), session_.solver().time());
  std::string title = "ClothLab — " + scene_name_ + " — " + timing + " — " + copies_text() +
                      " on the " + backend_name(session_.solver());
  if (stats_.behind() && !session_.paused && !session_.divergence())
    title += " — " + stats_.behind_reason(session_.solver().dt());
  if (session_.divergence())
    title += " — diverged (R resets)";
  else if (session_.paused)
    title += " — paused";
  if (error_.on()) title += " — " + error_.title_note();
  if (panel_.probe && !probe_title_.empty()) title += " — " + probe_title_;
  window_.set_title(title);
}

}  // namespace clothlab::vis
