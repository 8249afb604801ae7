#version 450 core

// One separable Gaussian blur pass of the irradiance atlas: 7 taps one standard deviation apart
// (weights exp(-x^2 / 2) normalised). The deviation is given in metres of cloth along one atlas
// axis and turned into atlas uv by the stretch map at this texel, so a stretched cloth keeps the
// width of its glow in the world (d'Eon & Luebke 2007: kernel width times stretch). Texels
// outside the cloth (alpha 0) are left out and the weights renormalised, so the border does not
// darken (d'Eon & Luebke's seam problem).
layout(location = 0) uniform vec2 u_sigma_m;   // standard deviation in metres, (s, 0) or (0, s)
layout(location = 1) uniform vec2 u_fallback;  // metres per atlas uv where the stretch map is empty
layout(binding = 0) uniform sampler2D u_source;
layout(binding = 1) uniform sampler2D u_stretch;  // metres of cloth per atlas uv (x, y)

in vec2 v_uv;
out vec4 color;

void main() {
  vec2 m = texelFetch(u_stretch, ivec2(gl_FragCoord.xy), 0).xy;
  // Outside the cloth (the stretch map is empty) the blur still runs, so that bilinear lookups
  // at the border see cloth values; the rest layout's scale serves there.
  if (m.x <= 0.0 || m.y <= 0.0) m = u_fallback;
  vec2 sigma_uv = u_sigma_m / m;
  vec4 sum = vec4(0.0);
  float weights = 0.0;
  for (int k = -3; k <= 3; ++k) {
    float x = float(k);  // in units of sigma
    float w = exp(-0.5 * x * x);
    vec4 s = texture(u_source, v_uv + sigma_uv * x);
    sum += w * s.a * vec4(s.rgb, 1.0);
    weights += w * s.a;
  }
  color = weights > 0.0 ? vec4(sum.rgb / weights, texture(u_source, v_uv).a) : vec4(0.0);
}
