// Which plane collider the floor stands for. A static plane facing straight up is the ground the
// cloth lands on, so the viewer's tiled floor is drawn there (rather than at default_view's guess
// below the cloth) and the plane itself is not drawn again; every other plane (tilted, facing
// down, moving) is drawn as a large quad by ColliderScenery.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "sim/scene/collider_spec.hpp"

namespace clothlab::vis {

// The first static plane whose normal is +y (to 1e-6 in angle), if any.
inline std::optional<std::size_t> floor_collider(const std::vector<ColliderSpec>& colliders) {
  for (std::size_t i = 0; i < colliders.size(); ++i) {
    const ColliderSpec& c = colliders[i];
    if (c.kind != ColliderKind::plane || c.moves()) continue;
    const Vec3d& n = c.normal;
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0.0 && n[1] / len > 1.0 - 1e-12) return i;
  }
  return std::nullopt;
}

}  // namespace clothlab::vis
