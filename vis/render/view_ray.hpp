// From a point on the screen back into the world: what pulling the cloth with the mouse needs
// (Ctrl + left drag moves a grabbed vertex in the plane through it that faces the camera, so it
// stays under the cursor at the depth where it was grabbed).
#pragma once

#include <glm/glm.hpp>

#include "vis/render/view_settings.hpp"

namespace clothlab::vis {

// The world point under window point (x, y) (pixels from the top-left corner of a view of
// width x height) on the plane through `anchor` perpendicular to the camera's view direction.
// Returns `anchor` for an empty view.
glm::vec3 point_on_view_plane(const OrbitCamera& camera, int width, int height, double x, double y,
                              glm::vec3 anchor);

}  // namespace clothlab::vis
