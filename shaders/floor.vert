#version 450 core
#include "frame.glsl"

layout(location = 0) uniform float u_half_size;  // m
layout(location = 1) uniform float u_tile_size;  // m per texture repeat

out vec3 v_world;
out vec2 v_uv;
#if SHADOW_FAST_COORD
out vec4 v_shadow_clip;
#endif

// A square at the floor height, two triangles from gl_VertexID (no vertex buffer).
void main() {
  const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1),
                                 vec2(-1, 1));
  vec2 c = corners[gl_VertexID] * u_half_size;
  v_world = vec3(c.x, params.y, c.y);
  v_uv = c / u_tile_size;
  gl_Position = view_proj * vec4(v_world, 1.0);
#if SHADOW_FAST_COORD
  v_shadow_clip = shadow_clip_vertex(v_world, vec3(0.0, 1.0, 0.0));
#endif
}
