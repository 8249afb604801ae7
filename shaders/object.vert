#version 450 core
#include "frame.glsl"

// Scenery (vis/render/scenery.cpp): a mesh placed by its model matrix.
layout(location = 0) uniform mat4 u_model;

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

out vec3 v_world;
out vec3 v_normal;
#if SHADOW_FAST_COORD
out vec4 v_shadow_clip;
#endif

void main() {
  v_world = (u_model * vec4(position, 1.0)).xyz;
  v_normal = transpose(inverse(mat3(u_model))) * normal;
  gl_Position = view_proj * vec4(v_world, 1.0);
#if SHADOW_FAST_COORD
  v_shadow_clip = shadow_clip_vertex(v_world, normalize(v_normal));
#endif
}
