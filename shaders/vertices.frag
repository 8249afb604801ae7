#version 450 core
#include "frame.glsl"

out vec4 color;

// A disc inside the point's square, light grey (the springs' rest-length colour, a bit lighter).
void main() {
  vec2 d = gl_PointCoord * 2.0 - 1.0;
  if (dot(d, d) > 1.0) discard;
  color = vec4(srgb_to_linear(vec3(0.93)), 1.0);
}
