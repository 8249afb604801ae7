#include "sim/contact/surface_features.hpp"

#include <algorithm>
#include <tuple>

namespace clothlab {

SurfaceFeatures surface_features(const std::vector<std::array<int, 3>>& triangles, std::size_t n) {
  SurfaceFeatures f;
  f.triangles = triangles;
  const std::size_t count = triangles.size();
  f.triangle_edges.assign(count, {0, 0, 0});
  f.owned_vertices.assign(count, 0);
  f.owned_edges.assign(count, 0);
  std::vector<bool> vertex_owned(n, false);
  // Every side as (a, b, triangle, side), sorted: equal edges are adjacent, the first triangle's
  // first.
  std::vector<std::tuple<int, int, int, int>> sides;
  sides.reserve(3 * count);
  for (std::size_t t = 0; t < count; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = triangles[t][std::size_t(k)], w = triangles[t][std::size_t((k + 1) % 3)];
      sides.emplace_back(std::min(v, w), std::max(v, w), int(t), k);
      if (!vertex_owned[std::size_t(v)]) {
        vertex_owned[std::size_t(v)] = true;
        f.owned_vertices[t] |= std::uint8_t(1u << k);
      }
    }
  }
  std::sort(sides.begin(), sides.end());
  for (std::size_t i = 0; i < sides.size(); ++i) {
    const auto [a, b, t, k] = sides[i];
    const bool first = i == 0 || std::get<0>(sides[i - 1]) != a || std::get<1>(sides[i - 1]) != b;
    if (first) {
      // Oriented as its owner's side, not by vertex number: a renumbering changes nothing.
      const auto& tri = triangles[std::size_t(t)];
      f.edges.push_back({tri[std::size_t(k)], tri[std::size_t((k + 1) % 3)]});
      f.owned_edges[std::size_t(t)] |= std::uint8_t(1u << k);
    }
    f.triangle_edges[std::size_t(t)][std::size_t(k)] = int(f.edges.size()) - 1;
  }
  return f;
}

}  // namespace clothlab
