// A scene file's double-precision point or direction as the float vector the renderer draws with.
#pragma once

#include <array>
#include <glm/vec3.hpp>

namespace clothlab::vis {

inline glm::vec3 to_glm(const std::array<double, 3>& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

}  // namespace clothlab::vis
