#version 450 core

// Raw values, not colours: float targets, no sRGB encoding, no blending. Alpha 1 marks cloth
// (the targets are cleared to 0); the triangle id is gl_PrimitiveID + 1 (0 = no cloth).
in vec3 v_force;
in vec3 v_velocity;
in vec3 v_world;
layout(location = 0) out vec4 force;
layout(location = 1) out vec4 velocity;
layout(location = 2) out vec4 world;
layout(location = 3) out int triangle;

void main() {
  force = vec4(v_force, 1.0);
  velocity = vec4(v_velocity, 1.0);
  world = vec4(v_world, 1.0);
  triangle = gl_PrimitiveID + 1;
}
