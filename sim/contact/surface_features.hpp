// The features of a triangle surface that contact tests pair up (docs/contact.md section 7): its
// unique edges, and for each triangle the vertices and sides it owns. Every vertex and every edge
// is owned by exactly one triangle, the first that has it, so that a pair of triangles whose
// boxes meet yields each (vertex, triangle) and (edge, edge) pair, and each (edge, triangle) pair
// of the crossing count, once and only once (a feature's box lies inside its owner's box).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace clothlab {

struct SurfaceFeatures {
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<int, 2>> edges;  // each edge once, oriented as its owner triangle's side
  std::vector<std::array<int, 3>> triangle_edges;  // sides (t0 t1), (t1 t2), (t2 t0) as edges
  std::vector<std::uint8_t> owned_vertices;        // per triangle: bit k = it owns vertex t[k]
  std::vector<std::uint8_t> owned_edges;           // per triangle: bit k = it owns side k
};

// Built once per model, from its triangles over n vertices.
SurfaceFeatures surface_features(const std::vector<std::array<int, 3>>& triangles, std::size_t n);

inline bool shares_vertex(const std::array<int, 3>& t, int v) {
  return t[0] == v || t[1] == v || t[2] == v;
}
inline bool shares_vertex(const std::array<int, 2>& e, const std::array<int, 3>& t) {
  return shares_vertex(t, e[0]) || shares_vertex(t, e[1]);
}
inline bool shares_vertex(const std::array<int, 2>& e, const std::array<int, 2>& f) {
  return e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1];
}

}  // namespace clothlab
