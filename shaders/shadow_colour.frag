#version 450 core

// The cloth's transmittance T = (1 - c) + c * tau * filter(albedo) (docs/rendering.md section 5):
// light passes through the gaps between the threads (1 - c) and, tinted by the dye, through the
// threads themselves (shaders/yarn.glsl). Blended multiplicatively, so layers multiply.
#include "yarn.glsl"

layout(location = 0) uniform float u_repeat;        // fabric repeats per cloth
layout(location = 1) uniform vec3 u_flat_albedo;    // sRGB, when u_use_flat
layout(location = 2) uniform int u_use_flat;
layout(location = 3) uniform vec2 u_coverage_tau;  // c, tau
layout(binding = 0) uniform sampler2D u_fabric;     // sRGB albedo

in vec2 v_uv;
out vec4 color;

vec3 decode(vec3 c) {
  return mix(pow((c + 0.055) / 1.055, vec3(2.4)), c / 12.92, lessThanEqual(c, vec3(0.04045)));
}

void main() {
  vec3 albedo = u_use_flat == 1 ? decode(u_flat_albedo) : texture(u_fabric, v_uv * u_repeat).rgb;
  float c = u_coverage_tau.x, tau = u_coverage_tau.y;
  color = vec4(vec3(1.0 - c) + c * tau * yarn_filter(albedo), 1.0);
}
