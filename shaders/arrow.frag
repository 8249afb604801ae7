#version 450 core
#include "frame.glsl"

// Arrow glyphs: the colour map's value (force arrows) or the direction as colour (normal
// arrows, as mode 2 shows normals). A head-light shade shows the shape but leaves faces within
// about 25 degrees of the view at exactly the map's colour, so the colour can be read (and
// tested) against the colour bar.
layout(location = 1) uniform int u_coloring;  // 0: colour map, 1: direction
layout(binding = 1) uniform sampler2D u_lut;  // 256 x 1, sRGB

in vec3 v_normal;
in vec3 v_world;
in vec3 v_direction;
in float v_value;
out vec4 color;

void main() {
  vec3 base_color = u_coloring == 1
                        ? srgb_to_linear(v_direction * 0.5 + 0.5)
                        : texture(u_lut, vec2((0.5 + 255.0 * v_value) / 256.0, 0.5)).rgb;
  vec3 to_eye = normalize(eye.xyz - v_world);
  float facing = abs(dot(normalize(v_normal), to_eye));
  color = vec4(base_color * mix(0.55, 1.0, smoothstep(0.0, 0.9, facing)), 1.0);
}
