#version 450 core
#include "frame.glsl"
#include "lighting.glsl"
#include "weave.glsl"

// The irradiance (no albedo) on the side of the cloth that faces the light, with the weave's
// relief and the shadows, at each texel of the UV atlas.
layout(location = 0) uniform float u_repeat;      // fabric repeats per cloth
layout(location = 1) uniform float u_atlas_size;  // texels per side of the atlas

in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
layout(location = 0) out vec4 color;
// The stretch map (d'Eon & Luebke 2007, section 14.4.2): metres of cloth as it is now per unit of
// atlas uv, along the atlas's x and y. The atlas is drawn flat, so the screen derivatives of the
// world position are its derivatives per atlas texel, exact within a triangle (affine there).
layout(location = 1) out vec2 metres_per_uv;

void main() {
  vec3 n_front = normalize(v_normal);
  vec3 l = light_vector(v_world);
  bool front_lit = dot(n_front, l) >= 0.0;
  vec3 mapped = weave_normal_front(n_front, v_tangent, v_uv * u_repeat);
  vec3 n = front_lit ? mapped : -mapped;
  vec3 vis = shadow_visibility(v_world, front_lit ? n_front : -n_front);
  metres_per_uv = vec2(length(dFdx(v_world)), length(dFdy(v_world))) * u_atlas_size;
  color = vec4(light_irradiance(v_world) * max(dot(n, l), 0.0) * vis, 1.0);
}
