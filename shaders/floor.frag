#version 450 core
#include "frame.glsl"
#include "lighting.glsl"

layout(binding = 0) uniform sampler2D u_tiles;
// The sky's cube map (shaders/sky.frag): the floor fades into the sky at the horizon.
layout(binding = 1) uniform samplerCube u_sky;
// x: 1 / the haze distance (m; 0: no haze, no sky drawn).
layout(location = 2) uniform vec4 u_haze;

in vec3 v_world;
in vec2 v_uv;
out vec4 color;

void main() {
  vec3 albedo = texture(u_tiles, v_uv).rgb;
  vec3 lit = lambert_lit(v_world, vec3(0.0, 1.0, 0.0), albedo);
  // Aerial perspective, simplified: the floor tends to the sky's colour at the horizon in its
  // own azimuth, 1 - exp(-(d / haze)^2), so the scene's own floor stays clear and the distant
  // floor meets the sky without an edge (the sky below the horizon is that colour too).
  vec3 to_floor = v_world - eye.xyz;
  vec2 across = to_floor.xz;
  float haze = 0.0;
  vec3 horizon = vec3(0.0);
  if (u_haze.x > 0.0 && dot(across, across) > 0.0) {
    float s = length(to_floor) * u_haze.x;
    haze = 1.0 - exp(-s * s);
    horizon = texture(u_sky, normalize(vec3(across.x, 0.0, across.y))).rgb;
  }
  color = vec4(mix(lit, horizon, haze), 1.0);
}
