// Box: 4 vertices per face so every face keeps its flat normal and its own [0,1]^2 uvs.
#include <stdexcept>

#include "vis/meshes/shapes.hpp"

namespace clothlab::vis {

Mesh make_box(glm::vec3 half_extents) {
  if (!(half_extents.x > 0.0f && half_extents.y > 0.0f && half_extents.z > 0.0f))
    throw std::invalid_argument("make_box: half extents must be > 0");
  struct Face {
    glm::vec3 n, t, b;  // normal, +u, +v with cross(t, b) = n (u right, v up seen from outside)
  };
  static constexpr Face kFaces[6] = {
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
  };
  static constexpr float kCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  Mesh mesh;
  for (const Face& f : kFaces) {
    const auto base = std::uint32_t(mesh.positions.size());
    for (const auto& c : kCorner) {
      mesh.positions.push_back((f.n + c[0] * f.t + c[1] * f.b) * half_extents);
      mesh.normals.push_back(f.n);
      mesh.uvs.emplace_back(0.5f * (c[0] + 1.0f), 0.5f * (c[1] + 1.0f));
      mesh.tangents.emplace_back(f.t, 1.0f);
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
  }
  return mesh;
}

}  // namespace clothlab::vis
