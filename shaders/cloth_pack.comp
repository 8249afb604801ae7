#version 450 core
// The GPU backend's state into the renderer's vertex buffer without a trip through the CPU
// (vis/render/renderer.cpp update_cloth): render vertex k takes solver vertex k, a seam copy
// (k >= n: the second copy of a vertex on a UV seam) the vertex it copies. The buffer holds the
// positions of every render vertex, then their normals, 3 floats each.
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };  // m
layout(std430, binding = 1) readonly buffer Normals { vec4 normals[]; };      // (unit n, area)
layout(std430, binding = 2) readonly buffer Seams { int seam_source[]; };
layout(std430, binding = 3) writeonly buffer Vertices { float vertices[]; };

uniform uint n;         // solver vertices
uniform uint render_n;  // render vertices, n plus the seam copies

void main() {
  const uint k = gl_GlobalInvocationID.x;
  if (k >= render_n) return;
  const uint s = k < n ? k : uint(seam_source[k - n]);
  const vec3 p = positions[s].xyz, m = normals[s].xyz;
  vertices[3 * k] = p.x;
  vertices[3 * k + 1] = p.y;
  vertices[3 * k + 2] = p.z;
  vertices[3 * (render_n + k)] = m.x;
  vertices[3 * (render_n + k) + 1] = m.y;
  vertices[3 * (render_n + k) + 2] = m.z;
}
