// Capsule: a UV sphere cut at its equator and pulled apart along y, so the two hemispheres and
// the cylinder between them share the equator rings (smooth normals across the joins).
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "vis/meshes/shapes.hpp"

namespace clothlab::vis {

Mesh make_capsule(float radius, float half_length, int slices, int cap_stacks) {
  if (!(radius > 0.0f) || !(half_length >= 0.0f))
    throw std::invalid_argument("make_capsule: need radius > 0 and half_length >= 0");
  if (slices < 3 || cap_stacks < 1)
    throw std::invalid_argument("make_capsule: need slices >= 3 and cap_stacks >= 1");
  constexpr float kPi = std::numbers::pi_v<float>;
  Mesh mesh;
  // Rows from the top pole (k = 0) to the bottom pole (k = rows - 1): the upper hemisphere's
  // latitudes 0..pi/2, then the lower's pi/2..pi, so the equator appears twice (at +-h). Every
  // row holds slices + 1 vertices (the seam duplicated); the pole rows' vertices coincide and
  // their degenerate half of each quad is left out.
  const int rows = 2 * (cap_stacks + 1);
  const int row = slices + 1;
  const float total = 2.0f * (half_length + radius);  // v runs 0 (bottom) .. 1 (top)
  for (int k = 0; k < rows; ++k) {
    const bool upper = k <= cap_stacks;
    const int step = upper ? k : k - 1;  // the equator's latitude twice
    const float phi = 0.5f * kPi * float(step) / float(cap_stacks);
    const float y_offset = upper ? half_length : -half_length;
    for (int j = 0; j <= slices; ++j) {
      // Longitude runs from +x towards -z, as on the UV sphere: u eastwards seen from outside.
      const float theta = 2.0f * kPi * float(j % slices) / float(slices);
      const bool pole = k == 0 || k == rows - 1;
      const glm::vec3 n = pole ? glm::vec3(0.0f, upper ? 1.0f : -1.0f, 0.0f)
                               : glm::vec3(std::sin(phi) * std::cos(theta), std::cos(phi),
                                           -std::sin(phi) * std::sin(theta));
      const glm::vec3 p = radius * n + glm::vec3(0.0f, y_offset, 0.0f);
      mesh.positions.push_back(p);
      mesh.normals.push_back(n);
      mesh.uvs.emplace_back(float(j) / float(slices), (p.y + half_length + radius) / total);
      // East, as on the sphere (analytic, so the seam's duplicates agree); handedness +1.
      mesh.tangents.emplace_back(-std::sin(theta), 0.0f, -std::cos(theta), 1.0f);
    }
  }
  const auto at = [&](int k, int j) { return std::uint32_t(k * row + j); };
  auto& idx = mesh.indices;
  const auto tri = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    idx.push_back(a);
    idx.push_back(b);
    idx.push_back(c);
  };
  for (int k = 0; k + 1 < rows; ++k) {
    for (int j = 0; j < slices; ++j) {
      if (k + 2 != rows) tri(at(k, j), at(k + 1, j), at(k + 1, j + 1));  // not at the bottom pole
      if (k != 0) tri(at(k, j), at(k + 1, j + 1), at(k, j + 1));         // not at the top pole
    }
  }
  return mesh;
}

}  // namespace clothlab::vis
