#include "vis/meshes/mesh.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace clothlab::vis {

Bounds mesh_bounds(const Mesh& mesh) {
  Bounds b;
  b.min = glm::vec3(std::numeric_limits<float>::infinity());
  b.max = glm::vec3(-std::numeric_limits<float>::infinity());
  for (const glm::vec3& p : mesh.positions) {
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
  }
  return b;
}

void transform_mesh(Mesh& mesh, const glm::mat4& m) {
  const glm::mat3 linear(m);
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
  const bool mirrored = glm::determinant(linear) < 0.0f;
  for (glm::vec3& p : mesh.positions) p = glm::vec3(m * glm::vec4(p, 1.0f));
  for (glm::vec3& n : mesh.normals) n = glm::normalize(normal_matrix * n);
  for (std::size_t i = 0; i < mesh.tangents.size(); ++i) {
    glm::vec3 t = linear * glm::vec3(mesh.tangents[i]);
    float w = mesh.tangents[i].w;
    if (i < mesh.normals.size()) {
      const glm::vec3& n = mesh.normals[i];
      t -= n * glm::dot(n, t);
    }
    const float len = glm::length(t);
    if (len > 0.0f) t /= len;
    if (mirrored) w = -w;
    mesh.tangents[i] = glm::vec4(t, w);
  }
  if (mirrored) {
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
      std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
  }
}

double signed_volume(const Mesh& mesh) {
  double v = 0.0;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[i]]);
    const glm::dvec3 b(mesh.positions[mesh.indices[i + 1]]);
    const glm::dvec3 c(mesh.positions[mesh.indices[i + 2]]);
    v += glm::dot(a, glm::cross(b, c));
  }
  return v / 6.0;
}

void append_mesh(Mesh& mesh, const Mesh& other) {
  const bool keep_tangents = mesh.positions.empty()
                                 ? !other.tangents.empty()
                                 : (!mesh.tangents.empty() && !other.tangents.empty());
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), other.positions.begin(), other.positions.end());
  mesh.normals.insert(mesh.normals.end(), other.normals.begin(), other.normals.end());
  mesh.uvs.insert(mesh.uvs.end(), other.uvs.begin(), other.uvs.end());
  if (keep_tangents)
    mesh.tangents.insert(mesh.tangents.end(), other.tangents.begin(), other.tangents.end());
  else
    mesh.tangents.clear();
  for (std::uint32_t i : other.indices) mesh.indices.push_back(base + i);
}

}  // namespace clothlab::vis
