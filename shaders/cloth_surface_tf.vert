#version 450 core
// The wind's surface for the transform-feedback step (gpu/tf_cloth.cpp): vertex i of a GL_POINTS
// draw, rasterisation discarded, sums c = (x1 - x0) x (x2 - x0) over its incident triangles in
// slot order and captures (unit normal, a third of the incident area), as the compute path's two
// passes do (cloth_faces.comp, cloth_normals.comp) with the same terms in the same order. Each
// triangle is computed once per corner instead of once: a vertex pass has no shared memory.
layout(binding = 0) uniform samplerBuffer positions;  // m (xyz, w unused)
layout(binding = 1) uniform isamplerBuffer incident;  // slot s of vertex i at s * n + i
layout(binding = 2) uniform isamplerBuffer corners;   // 3 per triangle

uniform uint n;
uniform int slots;
uniform int triangles;  // the padding's triangle index

out vec4 surface_out;  // (unit n, area m^2)

void main() {
  const int i = gl_VertexID;
  precise float nx = 0.0, ny = 0.0, nz = 0.0, sum_area = 0.0;
  for (int s = 0; s < slots; ++s) {
    const int t = texelFetch(incident, s * int(n) + i).r;
    if (t >= triangles) continue;  // padding: the compute path's zero dummy face
    const vec3 p0 = texelFetch(positions, texelFetch(corners, 3 * t).r).xyz;
    const vec3 p1 = texelFetch(positions, texelFetch(corners, 3 * t + 1).r).xyz;
    const vec3 p2 = texelFetch(positions, texelFetch(corners, 3 * t + 2).r).xyz;
    precise float ax = p1.x - p0.x, ay = p1.y - p0.y, az = p1.z - p0.z;
    precise float bx = p2.x - p0.x, by = p2.y - p0.y, bz = p2.z - p0.z;
    precise float cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    nx += cx;
    ny += cy;
    nz += cz;
    sum_area += 0.5 * sqrt(cx * cx + cy * cy + cz * cz);
  }
  precise float len = sqrt(nx * nx + ny * ny + nz * nz);
  precise float inv = len > 0.0 ? 1.0 / len : 0.0;  // a vertex with no area has no normal
  surface_out = vec4(nx * inv, ny * inv, nz * inv, sum_area * (1.0 / 3.0));
}
