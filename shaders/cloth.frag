#version 450 core
#include "frame.glsl"

// 2: world-space normal as colour (n * 0.5 + 0.5); 3: Lambert with the fabric texture.
layout(location = 0) uniform int u_mode;
layout(location = 1) uniform float u_texture_repeat;  // fabric repeats per cloth
layout(binding = 0) uniform sampler2D u_fabric;

in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
out vec4 color;

void main() {
  // Cloth has two sides: shade the side we see, with the normal turned towards us.
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  if (u_mode == 2) {
    color = vec4(srgb_to_linear(n * 0.5 + 0.5), 1.0);
    return;
  }
  vec3 albedo = texture(u_fabric, v_uv * u_texture_repeat).rgb;
  color = vec4(lambert_point_light(v_world, n, albedo), 1.0);
}
