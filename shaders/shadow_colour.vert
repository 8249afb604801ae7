#version 450 core
#include "frame.glsl"

// Mode 5's transmittance map (vis/passes/shadow_pass.cpp): the translucent cloth as the light
// sees it, carrying its UVs for the fabric's colour.
layout(location = 0) in vec3 position;
layout(location = 2) in vec2 uv;

out vec2 v_uv;

void main() {
  v_uv = uv;
  gl_Position = light_view_proj * vec4(position, 1.0);
}
