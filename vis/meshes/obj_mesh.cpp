#include "vis/meshes/obj_mesh.hpp"

#include <cstdint>

namespace clothlab::vis {
namespace {

glm::vec3 to_glm(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

}  // namespace

Mesh make_obj_mesh(const TriangleMesh& obj, bool smooth) {
  Mesh mesh;
  if (smooth) {
    for (const Eigen::Vector3d& p : obj.positions) mesh.positions.push_back(to_glm(p));
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
    mesh.uvs.assign(mesh.positions.size(), glm::vec2(0.0f));
  }
  for (const auto& t : obj.triangles) {
    const glm::vec3 p[3] = {to_glm(obj.positions[std::size_t(t[0])]),
                            to_glm(obj.positions[std::size_t(t[1])]),
                            to_glm(obj.positions[std::size_t(t[2])])};
    const glm::vec3 area = glm::cross(p[1] - p[0], p[2] - p[0]);  // twice the area, outward
    if (glm::dot(area, area) == 0.0f) continue;
    for (int k = 0; k < 3; ++k) {
      if (smooth) {
        mesh.normals[std::size_t(t[k])] += area;
        mesh.indices.push_back(static_cast<std::uint32_t>(t[k]));
      } else {
        mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
        mesh.positions.push_back(p[k]);
        mesh.normals.push_back(glm::normalize(area));
        mesh.uvs.emplace_back(0.0f, 0.0f);
      }
    }
  }
  for (glm::vec3& n : mesh.normals)
    n = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
  return mesh;
}

}  // namespace clothlab::vis
