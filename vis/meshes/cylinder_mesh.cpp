// Cylinder along +x (the pole): two rings for the smooth side, the seam duplicated, and
// optional flat caps with their own vertices (flat normals, planar uvs).
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "vis/meshes/shapes.hpp"

namespace clothlab::vis {

Mesh make_cylinder(float radius, float length, int slices, bool caps) {
  if (!(radius > 0.0f) || !(length > 0.0f))
    throw std::invalid_argument("make_cylinder: radius and length must be > 0");
  if (slices < 3) throw std::invalid_argument("make_cylinder: need slices >= 3");
  constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
  // Angle a runs from +y towards -z, so with u along +x and v along a the side's
  // dP/du x dP/dv points outward (tangent handedness +1).
  const auto dir = [&](int j) {
    const float a = kTwoPi * float(j % slices) / float(slices);
    return glm::vec3(0.0f, std::cos(a), -std::sin(a));
  };
  Mesh mesh;
  auto& idx = mesh.indices;
  const auto tri = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    idx.push_back(a);
    idx.push_back(b);
    idx.push_back(c);
  };
  // Side: vertex (i, j) = i * (slices + 1) + j, i = 0 at x = 0, i = 1 at x = length.
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j <= slices; ++j) {
      const glm::vec3 n = dir(j);
      mesh.positions.push_back(glm::vec3(i * length, 0.0f, 0.0f) + radius * n);
      mesh.normals.push_back(n);
      mesh.uvs.emplace_back(float(i), float(j) / float(slices));
    }
  }
  const auto side = [&](int i, int j) { return std::uint32_t(i * (slices + 1) + j); };
  for (int j = 0; j < slices; ++j) {
    tri(side(0, j), side(1, j), side(1, j + 1));
    tri(side(0, j), side(1, j + 1), side(0, j + 1));
  }
  if (caps) {
    for (int end = 0; end < 2; ++end) {
      const float x = end == 0 ? 0.0f : length;
      const glm::vec3 n(end == 0 ? -1.0f : 1.0f, 0.0f, 0.0f);
      // Seen from outside: at x = 0 (looking +x) +z is to the right, at x = length it is -z.
      const float u_sign = end == 0 ? 1.0f : -1.0f;
      const auto centre = std::uint32_t(mesh.positions.size());
      mesh.positions.emplace_back(x, 0.0f, 0.0f);
      mesh.normals.push_back(n);
      mesh.uvs.emplace_back(0.5f, 0.5f);
      for (int j = 0; j < slices; ++j) {
        const glm::vec3 d = dir(j);
        mesh.positions.push_back(glm::vec3(x, 0.0f, 0.0f) + radius * d);
        mesh.normals.push_back(n);
        mesh.uvs.emplace_back(0.5f + 0.5f * u_sign * d.z, 0.5f + 0.5f * d.y);
      }
      for (int j = 0; j < slices; ++j) {
        const std::uint32_t a = centre + 1 + std::uint32_t(j);
        const std::uint32_t b = centre + 1 + std::uint32_t((j + 1) % slices);
        if (end == 0)
          tri(centre, a, b);
        else
          tri(centre, b, a);
      }
    }
  }
  compute_tangents(mesh);
  return mesh;
}

}  // namespace clothlab::vis
