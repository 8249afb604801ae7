#version 450 core

// The field pass (vis/passes/field_pass.cpp): the cloth as in the main pass, carrying the
// solver's per-vertex force and velocity to be read back as floats under a probed pixel.
layout(location = 0) uniform mat4 u_view_proj;  // the main pass's camera (view_projection())

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 force;     // N
layout(location = 2) in vec3 velocity;  // m/s

out vec3 v_force;
out vec3 v_velocity;
out vec3 v_world;

void main() {
  v_force = force;
  v_velocity = velocity;
  v_world = position;  // the solver works in world space
  gl_Position = u_view_proj * vec4(position, 1.0);
}
