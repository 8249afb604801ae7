#version 450 core
#include "frame.glsl"

// One line per spring, one colour per line: the strain (|x_b - x_a| / |X_b - X_a| - 1) on the
// diverging cool-warm map of Moreland 2009 ("Diverging Color Maps for Scientific
// Visualization"), blue = compressed, grey = rest length, red = stretched, saturating at
// +-params.x.
layout(lines) in;
layout(line_strip, max_vertices = 2) out;

in vec3 g_position[];
in vec3 g_rest[];
flat out vec3 f_color;

vec3 cool_warm(float t) {  // t in [0, 1]; Moreland's control points, sRGB
  const vec3 c[5] = vec3[](vec3(0.230, 0.299, 0.754), vec3(0.552, 0.690, 0.996),
                           vec3(0.866, 0.866, 0.866), vec3(0.958, 0.604, 0.482),
                           vec3(0.706, 0.016, 0.150));
  float x = clamp(t, 0.0, 1.0) * 4.0;
  int i = min(int(x), 3);
  return mix(c[i], c[i + 1], x - float(i));
}

void main() {
  float rest = max(length(g_rest[1] - g_rest[0]), 1e-9);
  float strain = length(g_position[1] - g_position[0]) / rest - 1.0;
  vec3 c = srgb_to_linear(cool_warm(0.5 + 0.5 * strain / params.x));
  for (int k = 0; k < 2; ++k) {
    f_color = c;
    gl_Position = view_proj * vec4(g_position[k], 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
