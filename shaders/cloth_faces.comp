#version 450 core
// Face pass of the smoothed normals (gpu/gpu_cloth.cpp), one invocation per triangle, as
// sim/forces/force_field.cpp compute_faces: c = (x1 - x0) x (x2 - x0), twice the area times the
// unit normal, and the area |c| / 2; written out term by term and `precise` (no fused multiply-add)
// so it matches the CPU bit for bit. The face array keeps one zero dummy at index `triangles` for
// the padded incidence table (filled once at upload).
layout(local_size_x = 64) in;

layout(binding = 0) uniform samplerBuffer positions;  // m (xyz, w unused)
layout(std430, binding = 0) readonly buffer Triangles { int corners[]; };  // 3 per triangle
layout(std430, binding = 1) writeonly buffer Faces { vec4 faces[]; };     // (c, area m^2)

uniform uint triangles;

void main() {
  const uint t = gl_GlobalInvocationID.x;
  if (t >= triangles) return;
  const vec3 p0 = texelFetch(positions, corners[3 * t]).xyz;
  const vec3 p1 = texelFetch(positions, corners[3 * t + 1]).xyz;
  const vec3 p2 = texelFetch(positions, corners[3 * t + 2]).xyz;
  precise float ax = p1.x - p0.x, ay = p1.y - p0.y, az = p1.z - p0.z;
  precise float bx = p2.x - p0.x, by = p2.y - p0.y, bz = p2.z - p0.z;
  precise float cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
  precise float area = 0.5 * sqrt(cx * cx + cy * cy + cz * cz);
  faces[t] = vec4(cx, cy, cz, area);
}
