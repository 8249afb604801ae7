// Per-vertex tangents, after E. Lengyel, "Computing Tangent Space Basis Vectors for an Arbitrary
// Mesh" (Terathon Software, 2001; Mathematics for 3D Game Programming and Computer Graphics,
// sec. 7.8). Written from the published formulas.
#include <cmath>

#include "vis/meshes/shapes.hpp"

namespace clothlab::vis {

void compute_tangents(Mesh& mesh) {
  const std::size_t nv = mesh.positions.size();
  if (mesh.uvs.size() != nv || mesh.normals.size() != nv) {
    mesh.tangents.clear();
    return;
  }
  std::vector<glm::dvec3> sdir(nv, glm::dvec3(0.0)), tdir(nv, glm::dvec3(0.0));
  for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
    const std::uint32_t i0 = mesh.indices[k], i1 = mesh.indices[k + 1], i2 = mesh.indices[k + 2];
    const glm::dvec3 p0(mesh.positions[i0]);
    const glm::dvec3 e1 = glm::dvec3(mesh.positions[i1]) - p0;
    const glm::dvec3 e2 = glm::dvec3(mesh.positions[i2]) - p0;
    const glm::dvec2 w0(mesh.uvs[i0]);
    const glm::dvec2 d1 = glm::dvec2(mesh.uvs[i1]) - w0;
    const glm::dvec2 d2 = glm::dvec2(mesh.uvs[i2]) - w0;
    const double det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) < 1e-20) continue;  // degenerate uvs: no information
    const double inv = 1.0 / det;
    // [e1 e2] = [T B] [d1 d2]  =>  T = (e1 * d2.v - e2 * d1.v) / det, B = (e2 * d1.u - e1 * d2.u)
    // / det: dP/du and dP/dv of the triangle. Summing them unnormalised weights each triangle by
    // its uv-to-surface stretch, as in Lengyel's listing.
    const glm::dvec3 s = (e1 * d2.y - e2 * d1.y) * inv;
    const glm::dvec3 t = (e2 * d1.x - e1 * d2.x) * inv;
    for (std::uint32_t i : {i0, i1, i2}) {
      sdir[i] += s;
      tdir[i] += t;
    }
  }
  mesh.tangents.resize(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(mesh.normals[i]));
    glm::dvec3 t = sdir[i] - n * glm::dot(n, sdir[i]);  // Gram-Schmidt
    double len = glm::length(t);
    if (!(len > 1e-12)) {
      // No usable dP/du (isolated vertex or all its uv triangles degenerate): any perpendicular.
      const glm::dvec3 a = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
      t = a - n * glm::dot(n, a);
      len = glm::length(t);
    }
    t /= len;
    const double w = glm::dot(glm::cross(n, t), tdir[i]) < 0.0 ? -1.0 : 1.0;
    mesh.tangents[i] = glm::vec4(glm::vec3(t), float(w));
  }
}

}  // namespace clothlab::vis
