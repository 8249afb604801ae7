#version 450 core
#include "frame.glsl"

// Instanced arrow glyphs (vis/passes/arrow_pass.cpp). The mesh gives each vertex a direction
// around the axis and a ring; the ring's radius and height follow from the arrow's length:
// shaft radius r = min(u_radius, L / 10), head 2.2 r wide and L / 4 long (Polyscope keeps the
// radius at most a fifth of the length so the length stays readable).
layout(location = 0) uniform float u_radius;  // largest shaft radius, m

layout(location = 0) in vec3 ring_point;  // cos, sin, ring
layout(location = 1) in vec3 base;        // per instance: m
layout(location = 2) in vec3 vector;      // per instance: the arrow, m
layout(location = 3) in float value;      // per instance: colour map coordinate

out vec3 v_normal;
out vec3 v_world;
out vec3 v_direction;
out float v_value;

// An orthonormal basis around unit n without a branch on a fixed axis: Duff et al. 2017,
// "Building an Orthonormal Basis, Revisited" (JCGT 6(1)).
void basis(vec3 n, out vec3 b1, out vec3 b2) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float b = n.x * n.y * a;
  b1 = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
  b2 = vec3(b, s + n.y * n.y * a, -n.y);
}

void main() {
  float len = length(vector);
  vec3 axis = len > 0.0 ? vector / len : vec3(0.0, 0.0, 1.0);  // zero arrows collapse to a point
  vec3 b1, b2;
  basis(axis, b1, b2);
  float r = min(u_radius, 0.1 * len);
  float head = 0.25 * len;
  float head_r = 2.2 * r;
  int ring = int(ring_point.z + 0.5);
  vec2 around = ring_point.xy;
  // radius, height along the axis, and the normal's (radial, axial) parts for each ring.
  float radius = r, height = 0.0;
  vec2 n_parts = vec2(1.0, 0.0);
  vec2 cone_n = normalize(vec2(head, head_r));  // the cone side's normal, (radial, axial)
  if (ring == 1) {
    height = len - head;
  } else if (ring == 2) {
    radius = head_r, height = len - head, n_parts = cone_n;
  } else if (ring == 3) {
    radius = 0.0, height = len, n_parts = cone_n;
  } else if (ring == 4) {
    radius = 0.0, n_parts = vec2(0.0, -1.0);
  } else if (ring == 5) {
    n_parts = vec2(0.0, -1.0);
  } else if (ring == 6) {
    height = len - head, n_parts = vec2(0.0, -1.0);
  } else if (ring == 7) {
    radius = head_r, height = len - head, n_parts = vec2(0.0, -1.0);
  }
  vec3 radial = around.x * b1 + around.y * b2;
  v_world = base + radius * radial + height * axis;
  v_normal = n_parts.x * radial + n_parts.y * axis;
  v_direction = axis;
  v_value = value;
  gl_Position = view_proj * vec4(v_world, 1.0);
}
