#version 450 core

// One separable Gaussian blur pass of the irradiance atlas: 7 taps a third of the kernel's
// standard deviation `u_sigma` (atlas uv along the pass direction) apart, weights
// exp(-x^2 / 2 sigma^2) normalised. Texels outside the cloth (alpha 0) are left out and the
// weights renormalised, so the border does not darken (d'Eon & Luebke's seam problem).
layout(location = 0) uniform vec2 u_sigma;  // the blur's standard deviation, atlas uv (x or y)
layout(binding = 0) uniform sampler2D u_source;

in vec2 v_uv;
out vec4 color;

void main() {
  vec4 sum = vec4(0.0);
  float weights = 0.0;
  for (int k = -3; k <= 3; ++k) {
    float x = float(k) / 1.0;  // in units of sigma
    float w = exp(-0.5 * x * x);
    vec4 s = texture(u_source, v_uv + u_sigma * float(k));
    sum += w * s.a * vec4(s.rgb, 1.0);
    weights += w * s.a;
  }
  color = weights > 0.0 ? vec4(sum.rgb / weights, texture(u_source, v_uv).a) : vec4(0.0);
}
