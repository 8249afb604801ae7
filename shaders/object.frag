#version 450 core
#include "frame.glsl"
#include "lighting.glsl"

// Scenery: Lambert with the scene's light and shadows, a plain albedo.
layout(location = 1) uniform vec3 u_color;  // sRGB albedo

in vec3 v_world;
in vec3 v_normal;
out vec4 color;

void main() {
  color = vec4(lambert_lit(v_world, normalize(v_normal), srgb_to_linear(u_color)), 1.0);
}
