#version 450 core
#include "frame.glsl"
#include "lighting.glsl"

// Key 7: the light's depth map, linearised to metres from the light and coloured through the
// colour map from the near to the far plane (docs/rendering.md section 6: a plane at distance d
// reads d / f), shown as a square in the middle of the view. Texels no caster reached are dark
// grey.
layout(location = 0) uniform vec2 u_viewport;  // pixels
layout(binding = 1) uniform sampler2D u_lut;   // 256 x 1 colour map, sRGB

in vec2 v_ndc;
out vec4 color;

void main() {
  float side = min(u_viewport.x, u_viewport.y) * 0.95;
  vec2 uv = (gl_FragCoord.xy - 0.5 * (u_viewport - vec2(side))) / side;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) {
    color = vec4(vec3(0.02), 1.0);
    return;
  }
  float d = texture(u_shadow_depth, uv).r;
  if (d >= 1.0) {
    color = vec4(vec3(0.12), 1.0);
    return;
  }
  float n = shadow_range.x, f = shadow_range.y;
  float t = clamp((linear_light_depth(d) - n) / (f - n), 0.0, 1.0);
  color = vec4(texture(u_lut, vec2((0.5 + 255.0 * t) / 256.0, 0.5)).rgb, 1.0);
}
