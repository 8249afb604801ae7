// Keys and mouse of the window (docs/design.md, "Keys (window)"). One table binds each key to an
// action and a help line, so the H overlay always lists exactly the keys that work.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "vis/render/view_settings.hpp"

namespace clothlab::vis {

enum class Action {
  mode_springs,          // 1: springs <-> the previous shaded mode
  mode_normals,          // 2
  mode_lambert,          // 3
  mode_cloth_brdf,       // 4
  mode_translucent,      // 5
  mode_weave,            // 6
  mode_light_depth,      // 7
  probe_force,           // 8: probe the force under the cursor (again: off)
  probe_velocity,        // 9
  probe_position,        // 0
  toggle_force_arrows,   // F
  toggle_normal_arrows,  // N
  toggle_contact_view,   // C: colour by the gap to other cloth, crossings in magenta
  toggle_error_view,     // E: a reference run beside the shown one; colour by the distance
  push,                  // P
  toggle_wind,           // W
  release_pins,          // D: drop the cloth (onto the colliders); R pins it again
  pause,                 // Space
  single_step,           // .
  reset,                 // R
  more_vertices,         // ]
  fewer_vertices,        // [
  more_copies,           // +: twice the copies of the cloth
  fewer_copies,          // -: half
  toggle_parallel,       // M
  toggle_help,           // H
  screenshot,            // F12
  quit,                  // Esc
  toggle_record,         // the panel's Record button (no key)
};

struct KeyBinding {
  Action action;
  std::string_view name;  // as shown in the help and accepted by the test hook (CLOTHLAB_VIEW_KEYS)
  std::string_view help;
  int keys[3];   // GLFW key codes, 0 = unused
  bool repeats;  // also fires on key repeat (held ] / [ / .)
};

std::span<const KeyBinding> key_bindings();

// The mouse's gestures (handled by the window's mouse callbacks, not through actions), as the help
// overlay and `clothlab view --help` list them.
struct MouseBinding {
  std::string_view gesture, help;
};
std::span<const MouseBinding> mouse_bindings();

// The action of a GLFW key event (GLFW_PRESS or GLFW_REPEAT), if any.
std::optional<Action> action_for_key(int glfw_key, int glfw_action);
// The action named like a binding ("P", "Space", "F12"; "[" and "]" also as "LeftBracket" and
// "RightBracket"), for the test hook.
std::optional<Action> action_named(std::string_view name);

// Display mode after key 1-3: key 1 toggles between springs and the last shaded mode.
void select_mode(ViewSettings& view, DisplayMode& last_shaded, Action action);

// Mouse camera control: left drag orbits, right drag pans, the wheel zooms (Ctrl + left drag
// pulls the cloth instead: apps/view/cloth_grab.hpp).
class MouseCamera {
 public:
  // A button went down or up at (x, y) window pixels. A press over the UI (ui_has_mouse) or with
  // Ctrl held (reserved for pulling the cloth) starts no drag.
  void button(int glfw_button, int glfw_action, int mods, bool ui_has_mouse, double x, double y);
  // The cursor moved; window_height (pixels) scales panning so the target follows the cursor.
  void move(ViewSettings& view, double x, double y, int window_height);
  void scroll(ViewSettings& view, double wheel_steps, bool ui_has_mouse) const;

 private:
  enum class Drag { none, orbit, pan } drag_ = Drag::none;
  double last_x_ = 0.0, last_y_ = 0.0;
};

}  // namespace clothlab::vis
