#include "apps/view/input.hpp"

#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace clothlab::vis {
namespace {

constexpr float kOrbitDegreesPerPixel = 0.3f;
constexpr float kZoomPerWheelStep = 0.9f;

constexpr KeyBinding kBindings[] = {
    {Action::mode_springs,
     "1",
     "springs as lines, coloured by strain (again: back)",
     {GLFW_KEY_1, GLFW_KEY_KP_1},
     false},
    {Action::mode_normals,
     "2",
     "world-space normals as colour",
     {GLFW_KEY_2, GLFW_KEY_KP_2},
     false},
    {Action::mode_lambert, "3", "Lambert + cloth texture", {GLFW_KEY_3, GLFW_KEY_KP_3}, false},
    {Action::mode_cloth_brdf,
     "4",
     "cloth BRDF: Oren-Nayar + sheen, gold or silver threads",
     {GLFW_KEY_4, GLFW_KEY_KP_4},
     false},
    {Action::mode_translucent,
     "5",
     "translucent cloth with coloured shadows",
     {GLFW_KEY_5, GLFW_KEY_KP_5},
     false},
    {Action::mode_weave,
     "6",
     "normal-mapped weave (relief of the threads)",
     {GLFW_KEY_6, GLFW_KEY_KP_6},
     false},
    {Action::mode_light_depth,
     "7",
     "the light's depth map (the shadow map), coloured near to far",
     {GLFW_KEY_7, GLFW_KEY_KP_7},
     false},
    {Action::probe_force,
     "8",
     "probe the force under the cursor (again: off)",
     {GLFW_KEY_8, GLFW_KEY_KP_8},
     false},
    {Action::probe_velocity,
     "9",
     "probe the velocity under the cursor (again: off)",
     {GLFW_KEY_9, GLFW_KEY_KP_9},
     false},
    {Action::probe_position,
     "0",
     "probe the position under the cursor (again: off; click pins it to a vertex)",
     {GLFW_KEY_0, GLFW_KEY_KP_0},
     false},
    {Action::toggle_force_arrows,
     "F",
     "force arrows on/off (source, density, scale in the panel)",
     {GLFW_KEY_F},
     false},
    {Action::toggle_normal_arrows, "N", "normal arrows on/off", {GLFW_KEY_N}, false},
    {Action::toggle_contact_view,
     "C",
     "contact view on/off: colour by the gap to other cloth, crossings in magenta",
     {GLFW_KEY_C},
     false},
    {Action::toggle_error_view,
     "E",
     "error view on/off: a reference run beside this one, the cloth coloured by the distance",
     {GLFW_KEY_E},
     false},
    {Action::push, "P", "push the cloth (strength in the panel)", {GLFW_KEY_P}, false},
    {Action::toggle_wind, "W", "wind on/off", {GLFW_KEY_W}, false},
    {Action::release_pins,
     "D",
     "drop: release the pins (onto the sphere/box; R pins again)",
     {GLFW_KEY_D},
     false},
    {Action::pause, "Space", "pause / run", {GLFW_KEY_SPACE}, false},
    {Action::single_step,
     ".",
     "one step (pauses a running simulation)",
     {GLFW_KEY_PERIOD, GLFW_KEY_KP_DECIMAL},
     true},
    {Action::reset, "R", "reset (applies a new resolution)", {GLFW_KEY_R}, false},
    // The assignment's + / - raise and lower the number of simulated and drawn objects: the
    // copies of the cloth. GLFW names physical US-layout keys: '+' is Shift + '=' there, so '='
    // counts as '+'.
    {Action::more_copies,
     "+",
     "twice the copies of the cloth, side by side (up to 64; restarts)",
     {GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD},
     false},
    {Action::fewer_copies,
     "-",
     "half the copies of the cloth (restarts)",
     {GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT},
     false},
    {Action::more_vertices, "]", "more vertices (x 1.25)", {GLFW_KEY_RIGHT_BRACKET}, true},
    {Action::fewer_vertices, "[", "fewer vertices (/ 1.25)", {GLFW_KEY_LEFT_BRACKET}, true},
    {Action::toggle_parallel, "M", "parallel solver on/off (all cores <-> 1)", {GLFW_KEY_M}, false},
    {Action::toggle_help, "H", "this help", {GLFW_KEY_H}, false},
    {Action::screenshot,
     "F12",
     "screenshot to clothlab_screenshot_<time>.png",
     {GLFW_KEY_F12},
     false},
    {Action::quit, "Esc", "quit", {GLFW_KEY_ESCAPE}, false},
};

}  // namespace

std::span<const KeyBinding> key_bindings() {
  return kBindings;
}

std::span<const MouseBinding> mouse_bindings() {
  static constexpr MouseBinding kMouse[] = {
      {"left drag", "orbit"},
      {"right drag", "pan"},
      {"wheel", "zoom"},
      {"Ctrl + left drag", "pull the cloth at the vertex under the cursor"}};
  return kMouse;
}

std::optional<Action> action_for_key(int glfw_key, int glfw_action) {
  if (glfw_action != GLFW_PRESS && glfw_action != GLFW_REPEAT) return std::nullopt;
  for (const KeyBinding& b : kBindings) {
    for (int key : b.keys) {
      if (key != 0 && key == glfw_key && (glfw_action == GLFW_PRESS || b.repeats)) return b.action;
    }
  }
  return std::nullopt;
}

std::optional<Action> action_named(std::string_view name) {
  for (const KeyBinding& b : kBindings)
    if (b.name == name) return b.action;
  // Spelled out too: CMake lists (the window tests' command lines) mangle square brackets.
  if (name == "RightBracket") return Action::more_vertices;
  if (name == "LeftBracket") return Action::fewer_vertices;
  if (name == "Plus") return Action::more_copies;
  if (name == "Minus") return Action::fewer_copies;
  return std::nullopt;
}

void select_mode(ViewSettings& view, DisplayMode& last_shaded, Action action) {
  if (view.mode != DisplayMode::springs) last_shaded = view.mode;
  switch (action) {
    case Action::mode_springs:
      view.mode = view.mode == DisplayMode::springs ? last_shaded : DisplayMode::springs;
      break;
    case Action::mode_normals:
      view.mode = DisplayMode::normals;
      break;
    case Action::mode_lambert:
      view.mode = DisplayMode::lambert;
      break;
    case Action::mode_cloth_brdf:
      view.mode = DisplayMode::cloth_brdf;
      break;
    case Action::mode_translucent:
      view.mode = DisplayMode::translucent;
      break;
    case Action::mode_weave:
      view.mode = DisplayMode::weave;
      break;
    case Action::mode_light_depth:
      view.mode = DisplayMode::light_depth;
      break;
    default:
      break;
  }
}

void MouseCamera::button(int glfw_button, int glfw_action, int mods, bool ui_has_mouse, double x,
                         double y) {
  if (glfw_action == GLFW_RELEASE) {
    drag_ = Drag::none;
    return;
  }
  if (ui_has_mouse || drag_ != Drag::none) return;
  if (glfw_button == GLFW_MOUSE_BUTTON_LEFT && !(mods & GLFW_MOD_CONTROL)) drag_ = Drag::orbit;
  if (glfw_button == GLFW_MOUSE_BUTTON_RIGHT) drag_ = Drag::pan;
  last_x_ = x;
  last_y_ = y;
}

void MouseCamera::move(ViewSettings& view, double x, double y, int window_height) {
  const float dx = static_cast<float>(x - last_x_), dy = static_cast<float>(y - last_y_);
  last_x_ = x;
  last_y_ = y;
  OrbitCamera& camera = view.camera;
  if (drag_ == Drag::orbit) {
    // Dragging right turns the scene right: the eye moves left around the target.
    camera.orbit(-kOrbitDegreesPerPixel * dx, kOrbitDegreesPerPixel * dy);
  } else if (drag_ == Drag::pan && window_height > 0) {
    // Metres per pixel at the target's distance, so the point under the cursor stays under it.
    const float metres_per_pixel = 2.0f * camera.distance *
                                   std::tan(0.5f * camera.fov_deg * 3.14159265f / 180.0f) /
                                   static_cast<float>(window_height);
    camera.pan(-dx * metres_per_pixel, dy * metres_per_pixel);
  }
}

void MouseCamera::scroll(ViewSettings& view, double wheel_steps, bool ui_has_mouse) const {
  if (ui_has_mouse) return;
  view.camera.zoom(std::pow(kZoomPerWheelStep, static_cast<float>(wheel_steps)));
}

}  // namespace clothlab::vis
