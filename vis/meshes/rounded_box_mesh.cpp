// Rounded box: each face is a grid over the box's outer surface whose every point q is pushed
// onto the rounded surface, c + r * normalize(q - c) with c the nearest point of the inner box
// (half extents h - r). Grid lines sit only in the rounding bands, spaced so the normal turns
// by equal angles; the flat middle of a face is one quad. Neighbouring faces meet on the same
// points of the outer box's edges, so their vertices coincide there (watertight once welded).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "vis/meshes/shapes.hpp"

namespace clothlab::vis {

Mesh make_rounded_box(glm::vec3 half_extents, float rounding, int segments) {
  if (!(half_extents.x > 0.0f && half_extents.y > 0.0f && half_extents.z > 0.0f))
    throw std::invalid_argument("make_rounded_box: half extents must be > 0");
  if (segments < 1) throw std::invalid_argument("make_rounded_box: need segments >= 1");
  const glm::vec3 h = half_extents;
  const float r = std::min({rounding, h.x, h.y, h.z});
  if (!(r > 0.0f)) return make_box(h);
  const glm::vec3 inner = h - r;
  struct Face {
    glm::vec3 n, t, b;  // as make_box: normal, +u, +v with cross(t, b) = n
  };
  static constexpr Face kFaces[6] = {
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
  };
  // Coordinates along an axis of half extent e: through the band -e..-(e - r), then (e - r)..e,
  // at angles 0..45 degrees of the normal's turn (the neighbouring face turns the other 45).
  const auto samples = [&](float e) {
    std::vector<float> s;
    for (int k = segments; k >= 0; --k)
      s.push_back(-(e - r) - r * std::tan(0.25f * std::numbers::pi_v<float> * k / segments));
    for (int k = 0; k <= segments; ++k)
      s.push_back((e - r) + r * std::tan(0.25f * std::numbers::pi_v<float> * k / segments));
    return s;
  };
  Mesh mesh;
  for (const Face& f : kFaces) {
    const float et = glm::dot(glm::abs(f.t), h), eb = glm::dot(glm::abs(f.b), h),
                en = glm::dot(glm::abs(f.n), h);
    const std::vector<float> su = samples(et), sv = samples(eb);
    const auto base = std::uint32_t(mesh.positions.size());
    const auto cols = std::uint32_t(su.size());
    for (float v : sv) {
      for (float u : su) {
        const glm::vec3 q = en * f.n + u * f.t + v * f.b;
        const glm::vec3 c = glm::clamp(q, -inner, inner);
        const glm::vec3 n = glm::normalize(q - c);
        mesh.positions.push_back(c + r * n);
        mesh.normals.push_back(n);
        mesh.uvs.emplace_back(0.5f * (u / et + 1.0f), 0.5f * (v / eb + 1.0f));
      }
    }
    for (std::uint32_t j = 0; j + 1 < sv.size(); ++j) {
      for (std::uint32_t i = 0; i + 1 < cols; ++i) {
        const std::uint32_t a = base + j * cols + i, b = a + 1, c = a + cols + 1, d = a + cols;
        for (std::uint32_t k : {a, b, c, a, c, d}) mesh.indices.push_back(k);
      }
    }
  }
  compute_tangents(mesh);
  return mesh;
}

}  // namespace clothlab::vis
