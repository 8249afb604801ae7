#version 450 core
#include "frame.glsl"

// The shadow pass (vis/passes/shadow_pass.cpp): every caster's depth as the light sees it. The
// floor comes from gl_VertexID like shaders/floor.vert; everything else from its vertex buffer
// (position at location 0) placed by u_model.
layout(location = 0) uniform mat4 u_model;
layout(location = 1) uniform int u_floor;     // 1: draw the floor square
layout(location = 2) uniform vec2 u_floor_at;  // x: height (m), y: half size (m)

layout(location = 0) in vec3 position;

void main() {
  vec3 world;
  if (u_floor == 1) {
    const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1),
                                   vec2(1, 1), vec2(-1, 1));
    vec2 c = corners[gl_VertexID] * u_floor_at.y;
    world = vec3(c.x, u_floor_at.x, c.y);
  } else {
    world = (u_model * vec4(position, 1.0)).xyz;
  }
  gl_Position = light_view_proj * vec4(world, 1.0);
}
