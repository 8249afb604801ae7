#version 450 core
#include "frame.glsl"

// A cloth without triangles (two vertices and a spring, a chain): its vertices as round dots
// (vis/passes/springs_pass.cpp), over the cloth's own vertex buffer.
layout(location = 0) in vec3 position;

void main() {
  gl_Position = view_proj * vec4(position, 1.0);
  gl_PointSize = 9.0;  // pixels
}
