// Ctrl + left drag pulls the cloth (docs/design.md "Keys (window)"): the press picks the vertex
// under the cursor with the probes' field pass, the drag moves its target in the plane through the
// vertex that faces the camera (so the vertex stays at the depth where it was grabbed and
// follows the cursor), the release lets go. The solver does the pulling (Solver::grab: a stiff
// damped spring to the target). No GL here but through probe_fields.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "vis/render/view_settings.hpp"

namespace clothlab {
class Solver;
struct FrameFields;
}  // namespace clothlab

namespace clothlab::vis {

class FieldPass;
class Renderer;

class ClothGrab {
 public:
  // A Ctrl + left press at window point (x, y): the vertex is picked at the next pick(), which
  // needs the field pass and so runs in the frame's draw.
  void press(double x, double y) { pending_ = std::array<double, 2>{x, y}; }
  // Picks the vertex under a pending press (window of window_w x window_h points, framebuffer
  // of width x height pixels, `pass` rebuilt at that size when needed) and starts pulling it.
  // Returns false when nothing was pending or no free vertex lies under the press.
  // `fields`: the frame's snapshot, taken with the probe's fields (frame_request(..., true)).
  bool pick(Solver& solver, const FrameFields& fields, const Renderer& renderer,
            std::unique_ptr<FieldPass>& pass, const ViewSettings& view, int width, int height,
            int window_w, int window_h);
  // The cursor moved to window point (x, y) while dragging: the target follows it.
  void drag_to(Solver& solver, const OrbitCamera& camera, double x, double y, int window_w,
               int window_h);
  // Lets go. Returns a line about the pull (the vertex and its distance to the last target at
  // the press and now), empty when nothing was grabbed.
  std::string release(Solver& solver);
  // The solver was rebuilt: whatever was grabbed is gone with it.
  void forget() {
    pending_.reset();
    vertex_ = -1;
  }

  bool active() const { return vertex_ >= 0; }
  bool pending() const { return pending_.has_value(); }

 private:
  std::optional<std::array<double, 2>> pending_;
  int vertex_ = -1;
  glm::vec3 anchor_{0.0f};  // where the vertex was grabbed: its plane faces the camera
  glm::vec3 target_{0.0f};  // the last target
};

}  // namespace clothlab::vis
