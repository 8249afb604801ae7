// Where the scene's light is and how its shadow map sees the scene: a spot light gets a
// perspective frustum, a directional light an orthographic box, each fitted to a sphere around
// everything that casts or receives shadows (rendering.md section 6).
#pragma once

#include <glm/glm.hpp>

#include "vis/render/view_settings.hpp"

namespace clothlab::vis {

struct LightRig {
  bool directional = false;
  glm::vec3 position{0.0f};        // spot: the light; directional: a point behind the scene
  glm::vec3 direction{0.0f};       // unit: the way the light travels (spot: its axis)
  float cone_cos = 0.0f;           // spot: cosine of the cone's edge
  glm::mat4 view_proj{1.0f};       // world -> shadow-map clip space
  float near = 0.1f, far = 10.0f;  // m along the light's axis
  // The light's size in shadow-map uv: at the near plane per the light's width (spot), or per
  // metre of depth (directional: angular size / box width); PCSS scales its kernels by it.
  float size_uv = 0.0f;
  float normal_offset = 0.0f;  // m: about one shadow-map texel at the scene's centre
};

// Fits the light of `view` to the sphere (centre, radius) for a map of map_size texels.
LightRig fit_light(const ViewSettings& view, glm::vec3 centre, float radius, int map_size);

}  // namespace clothlab::vis
