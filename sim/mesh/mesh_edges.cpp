#include "sim/mesh/mesh_edges.hpp"

#include <algorithm>

namespace clothlab {

std::vector<std::array<int, 2>> mesh_edges(const std::vector<std::array<int, 3>>& triangles) {
  std::vector<std::array<int, 2>> edges;
  edges.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int c = 0; c < 3; ++c)
      edges.push_back({std::min(t[c], t[(c + 1) % 3]), std::max(t[c], t[(c + 1) % 3])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace clothlab
