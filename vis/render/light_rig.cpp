#include "vis/render/light_rig.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace clothlab::vis {
namespace {

// An up vector not parallel to `forward` for lookAt.
glm::vec3 up_for(glm::vec3 forward) {
  return std::abs(forward.y) > 0.95f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace

LightRig fit_light(const ViewSettings& view, glm::vec3 centre, float radius, int map_size) {
  LightRig rig;
  radius = std::max(radius, 0.05f);
  if (view.light_type == LightType::directional) {
    rig.directional = true;
    rig.direction = glm::normalize(view.light_direction);
    const float back = 2.0f * radius;
    rig.position = centre - rig.direction * back;
    const glm::mat4 v = glm::lookAt(rig.position, centre, up_for(rig.direction));
    rig.near = back - radius;
    rig.far = back + radius;
    const glm::mat4 p = glm::ortho(-radius, radius, -radius, radius, rig.near, rig.far);
    rig.view_proj = p * v;
    const float width = 2.0f * radius;
    rig.size_uv = view.light_size / width;  // light_size: angular size in radians
    rig.normal_offset = width / static_cast<float>(map_size);
    return rig;
  }
  rig.position = view.light_position;
  const glm::vec3 to_centre = centre - rig.position;
  const float d = std::max(glm::length(to_centre), 1.01f * radius);
  // The spot points at its target (the scene's centre unless the scene names one); the frustum
  // around that axis just holds the sphere, and the cone lights it and a little more.
  const glm::vec3 aim = view.light_target ? *view.light_target : centre;
  const glm::vec3 axis = glm::length(aim - rig.position) > 1e-6f
                             ? glm::normalize(aim - rig.position)
                             : glm::normalize(to_centre);
  const float off_axis =
      std::acos(std::clamp(glm::dot(axis, glm::normalize(to_centre)), -1.0f, 1.0f));
  const float half = std::min(off_axis + std::asin(std::clamp(radius / d, 0.0f, 0.999f)), 1.4f);
  rig.direction = axis;
  // The cone lights well beyond what casts shadows (a lamp, not a stage spot): at least 70
  // degrees off its axis, so the floor around the scene stays lit.
  rig.cone_cos = std::cos(std::min(std::max(1.15f * half, glm::radians(70.0f)), 1.5f));
  rig.near = std::max(d - radius, 0.02f * d);
  rig.far = d + radius;
  const glm::mat4 v = glm::lookAt(rig.position, rig.position + axis, up_for(axis));
  const glm::mat4 p = glm::perspective(2.0f * half, 1.0f, rig.near, rig.far);
  rig.view_proj = p * v;
  const float tan_half = std::tan(half);
  rig.size_uv = view.light_size / (2.0f * rig.near * tan_half);
  rig.normal_offset = 2.0f * d * tan_half / static_cast<float>(map_size);
  return rig;
}

}  // namespace clothlab::vis
