#version 450 core
// Vertex pass of the smoothed normals (gpu/gpu_cloth.cpp), one invocation per vertex, as
// sim/forces/force_field.cpp compute_vertex_normals: the sum of the incident faces' c (area
// weighted, Max 1999) over the padded slot-major incidence table, in slot order, normalised; the
// vertex area is a third of the incident areas. `precise`, so it matches the CPU bit for bit.
layout(local_size_x = 64) in;

layout(binding = 0) uniform isamplerBuffer incident;  // slot s of vertex i at s * n + i
layout(binding = 1) uniform samplerBuffer faces;      // (c, area) per triangle, dummy last
layout(std430, binding = 0) writeonly buffer Normals { vec4 normals[]; };  // (unit n, area m^2)

uniform uint n;
uniform int slots;

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= n) return;
  precise float nx = 0.0, ny = 0.0, nz = 0.0, sum_area = 0.0;
  for (int s = 0; s < slots; ++s) {
    const vec4 f = texelFetch(faces, texelFetch(incident, s * int(n) + int(i)).r);
    nx += f.x;
    ny += f.y;
    nz += f.z;
    sum_area += f.w;
  }
  precise float len = sqrt(nx * nx + ny * ny + nz * nz);
  precise float inv = len > 0.0 ? 1.0 / len : 0.0;  // a vertex with no area has no normal
  normals[i] = vec4(nx * inv, ny * inv, nz * inv, sum_area * (1.0 / 3.0));
}
