#version 450 core
#include "frame.glsl"
#include "lighting.glsl"

layout(binding = 0) uniform sampler2D u_tiles;

in vec3 v_world;
in vec2 v_uv;
out vec4 color;

void main() {
  vec3 albedo = texture(u_tiles, v_uv).rgb;
  color = vec4(lambert_lit(v_world, vec3(0.0, 1.0, 0.0), albedo), 1.0);
}
