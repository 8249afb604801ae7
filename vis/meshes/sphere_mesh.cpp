// UV sphere: rings of constant latitude, the longitude seam duplicated so u runs 0..1.
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "vis/meshes/shapes.hpp"

namespace clothlab::vis {

Mesh make_uv_sphere(float radius, int slices, int stacks) {
  if (!(radius > 0.0f)) throw std::invalid_argument("make_uv_sphere: radius must be > 0");
  if (slices < 3 || stacks < 2)
    throw std::invalid_argument("make_uv_sphere: need slices >= 3 and stacks >= 2");
  constexpr float kPi = std::numbers::pi_v<float>;
  Mesh mesh;
  // Vertex layout: pole rows (k = 0 and k = stacks) hold `slices` vertices each (one per slice,
  // u at the slice centre); the inner rows hold slices + 1 (the seam duplicated).
  const int row = slices + 1;
  const auto top = [](int j) { return std::uint32_t(j); };
  const auto inner = [&](int k, int j) { return std::uint32_t(slices + (k - 1) * row + j); };
  const auto bottom = [&](int j) { return std::uint32_t(slices + (stacks - 1) * row + j); };

  const auto add = [&](float phi, float theta, float u) {
    // Longitude theta runs from +x towards -z, so u increases eastwards seen from outside
    // (dP/du x dP/dv points outward: tangent handedness +1).
    const glm::vec3 n(std::sin(phi) * std::cos(theta), std::cos(phi),
                      -std::sin(phi) * std::sin(theta));
    mesh.positions.push_back(radius * n);
    mesh.normals.push_back(n);
    mesh.uvs.emplace_back(u, 1.0f - phi / kPi);
  };
  const auto theta_of = [&](int j) { return 2.0f * kPi * float(j % slices) / float(slices); };

  for (int j = 0; j < slices; ++j) add(0.0f, 0.0f, (j + 0.5f) / float(slices));
  for (int k = 1; k < stacks; ++k) {
    const float phi = kPi * float(k) / float(stacks);
    for (int j = 0; j <= slices; ++j) add(phi, theta_of(j), float(j) / float(slices));
  }
  for (int j = 0; j < slices; ++j) add(kPi, 0.0f, (j + 0.5f) / float(slices));
  // The poles' positions/normals are exact (sin(pi) is not 0 in float).
  for (int j = 0; j < slices; ++j) {
    mesh.positions[bottom(j)] = glm::vec3(0.0f, -radius, 0.0f);
    mesh.normals[bottom(j)] = glm::vec3(0.0f, -1.0f, 0.0f);
  }

  auto& idx = mesh.indices;
  const auto tri = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    idx.push_back(a);
    idx.push_back(b);
    idx.push_back(c);
  };
  for (int j = 0; j < slices; ++j) {
    tri(top(j), inner(1, j), inner(1, j + 1));
    for (int k = 1; k + 1 < stacks; ++k) {
      tri(inner(k, j), inner(k + 1, j), inner(k + 1, j + 1));
      tri(inner(k, j), inner(k + 1, j + 1), inner(k, j + 1));
    }
    tri(inner(stacks - 1, j), bottom(j), inner(stacks - 1, j + 1));
  }
  // Analytic tangents: d/du points east, (-sin theta, 0, -cos theta), for every vertex of a
  // column, so the duplicated seam vertices agree (compute_tangents() would see only one side of
  // the seam and tilt them by a few degrees). Handedness +1: cross(N, east) is north = dP/dv.
  mesh.tangents.resize(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const float theta = 2.0f * kPi * mesh.uvs[i].x;
    mesh.tangents[i] = glm::vec4(-std::sin(theta), 0.0f, -std::cos(theta), 1.0f);
  }
  return mesh;
}

}  // namespace clothlab::vis
