#version 450 core
#include "frame.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;

out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;

void main() {
  v_world = position;  // the solver works in world space
  v_normal = normal;
  v_uv = uv;
  gl_Position = view_proj * vec4(position, 1.0);
}
