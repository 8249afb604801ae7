#version 450 core
#include "frame.glsl"

// With the transform-feedback backend a geometry shader (cloth_flat.geom) sits between this
// stage and cloth.frag and gives every triangle its own normal: its inputs take these names.
#ifdef FLAT_NORMALS
#define v_world vg_world
#define v_normal vg_normal
#define v_uv vg_uv
#define v_scalar vg_scalar
#define v_tangent vg_tangent
#define v_atlas_uv vg_atlas_uv
#undef SHADOW_FAST_COORD
#define SHADOW_FAST_COORD 0
#endif

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 4) in float scalar;  // the colour-by field (vis/render/scalar_field.hpp)
layout(location = 5) in vec4 tangent;  // xyz along +u, w handedness (modes 4-6)
layout(location = 6) in vec2 atlas_uv;  // the vertex's place in the cloths' UV atlas (mode 6)

out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
out float v_scalar;
out vec4 v_tangent;
out vec2 v_atlas_uv;
#if SHADOW_FAST_COORD
out vec4 v_shadow_clip;
#endif

void main() {
  v_world = position;  // the solver works in world space
  v_normal = normal;
  v_uv = uv;
  v_scalar = scalar;
  v_tangent = tangent;
  v_atlas_uv = atlas_uv;
  gl_Position = view_proj * vec4(position, 1.0);
#if SHADOW_FAST_COORD
  v_shadow_clip = shadow_clip_vertex(position, normal);
#endif
}
