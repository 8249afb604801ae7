#include "vis/render/light_rig.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace clothlab::vis {
namespace {

// An up vector not parallel to `forward` for lookAt.
glm::vec3 up_for(glm::vec3 forward) {
  return std::abs(forward.y) > 0.95f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

// Where the shadow of each corner of the casters' box lands: the corner carried along the
// light's ray down to the floor, at most `longest` from the corner (a ray that runs nearly
// parallel to the floor, or upwards, would land far off or never). Corners at or below the
// floor land where they are.
std::array<glm::vec3, 8> shadow_landings(const ViewSettings& view, glm::vec3 lo, glm::vec3 hi,
                                         float floor_height, float longest) {
  std::array<glm::vec3, 8> out;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
    out[k] = corner;
    const glm::vec3 ray = view.light_type == LightType::directional ? view.light_direction
                                                                    : corner - view.light_position;
    const float len = glm::length(ray), height = corner.y - floor_height;
    if (len < 1e-6f || height <= 0.0f) continue;
    const float along = ray.y < 0.0f ? std::min(longest, height * len / -ray.y) : longest;
    out[k] = corner + ray * (along / len);
  }
  return out;
}

}  // namespace

LightRig fit_light(const ViewSettings& view, glm::vec3 lo, glm::vec3 hi, float floor_height,
                   int map_size) {
  LightRig rig;
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 0.05f);
  const auto landings = shadow_landings(view, lo, hi, floor_height, kShadowReach * 2.0f * radius);
  // The depth range must reach the farthest landing, so that no shadow is cut off by the far
  // plane (receivers beyond it read as lit).
  auto farthest = [&](glm::vec3 from, glm::vec3 axis) {
    float d = 0.0f;
    for (const glm::vec3& p : landings) d = std::max(d, glm::dot(p - from, axis));
    return d;
  };
  if (view.light_type == LightType::directional) {
    rig.directional = true;
    rig.direction = glm::normalize(view.light_direction);
    const float back = 2.0f * radius;
    rig.position = centre - rig.direction * back;
    const glm::mat4 v = glm::lookAt(rig.position, centre, up_for(rig.direction));
    rig.near = back - radius;
    rig.far = std::max(back + radius, 1.01f * farthest(rig.position, rig.direction));
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
  // The spot points at its target, unless the scene names one at the middle of the casters and
  // the floor under them; the frustum around that axis just holds the casters' sphere, and the
  // cone lights it and a little more.
  const glm::vec3 middle = 0.5f * (glm::vec3(lo.x, std::min(lo.y, floor_height), lo.z) + hi);
  const glm::vec3 aim = view.light_target ? *view.light_target : middle;
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
  rig.far = std::max(d + radius, 1.01f * farthest(rig.position, axis));
  const glm::mat4 v = glm::lookAt(rig.position, rig.position + axis, up_for(axis));
  const glm::mat4 p = glm::perspective(2.0f * half, 1.0f, rig.near, rig.far);
  rig.view_proj = p * v;
  const float tan_half = std::tan(half);
  rig.size_uv = view.light_size / (2.0f * rig.near * tan_half);
  rig.normal_offset = 2.0f * d * tan_half / static_cast<float>(map_size);
  return rig;
}

}  // namespace clothlab::vis
