// Where the scene's light is and how its shadow map sees the scene: a spot light gets a
// perspective frustum, a directional light an orthographic box, each fitted to the casters and
// reaching on to where their shadows land (docs/rendering.md section 6).
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

// A shadow that would run out nearly parallel to the floor is followed at most this many times
// the casters' diameter (so long and grazing, it is too faint to matter).
inline constexpr float kShadowReach = 3.0f;

// Fits the light of `view` for a map of map_size texels to the box (lo, hi) around every
// caster. Every shadow lies on a ray from the light through a caster, so the frustum's sides
// (spot) or the box's width (directional) need only hold the casters; its depth range reaches
// on to where their shadows land on the floor at floor_height, so none is cut off by the far
// plane. A spot points at view.light_target, or else at the middle of the casters and the floor
// under them.
LightRig fit_light(const ViewSettings& view, glm::vec3 lo, glm::vec3 hi, float floor_height,
                   int map_size);

}  // namespace clothlab::vis
