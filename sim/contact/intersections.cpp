#include "sim/contact/intersections.hpp"

#include "sim/contact/segment_crossing.hpp"

namespace clothlab {

using V3 = Eigen::Vector3d;

std::vector<V3> triangle_centroids(const std::vector<std::array<int, 3>>& triangles,
                                   const std::vector<V3>& x) {
  std::vector<V3> c;
  c.reserve(triangles.size());
  for (const auto& t : triangles)
    c.push_back((x[std::size_t(t[0])] + x[std::size_t(t[1])] + x[std::size_t(t[2])]) / 3.0);
  return c;
}

IntersectionCounter::IntersectionCounter(const std::vector<std::array<int, 3>>& triangles,
                                         const std::vector<V3>& rest)
    : features_(surface_features(triangles, rest.size())),
      bvh_(triangle_centroids(triangles, rest)) {}

namespace {

bool crosses(const std::array<int, 2>& e, const std::array<int, 3>& t, const std::vector<V3>& x) {
  if (shares_vertex(e, t)) return false;
  return segment_crosses_triangle(x[std::size_t(e[0])], x[std::size_t(e[1])], x[std::size_t(t[0])],
                                  x[std::size_t(t[1])], x[std::size_t(t[2])]);
}

}  // namespace

long IntersectionCounter::count(const std::vector<V3>& x, std::vector<Crossing>* crossings) {
  const auto& tris = features_.triangles;
  fill_triangle_boxes(tris, x, 0.0, bvh_.leaf_boxes());
  bvh_.refit();
  if (crossings) crossings->clear();
  long count = 0;
  // Each side a triangle owns against the other triangle, both ways.
  const auto owned_sides_through = [&](int owner, int other) {
    const std::uint8_t mask = features_.owned_edges[std::size_t(owner)];
    for (int k = 0; k < 3; ++k)
      if (mask & (1u << k)) {
        const int edge = features_.triangle_edges[std::size_t(owner)][std::size_t(k)];
        if (!crosses(features_.edges[std::size_t(edge)], tris[std::size_t(other)], x)) continue;
        ++count;
        if (crossings) crossings->push_back({edge, other});
      }
  };
  bvh_.self_pairs([&](int ta, int tb) {
    owned_sides_through(ta, tb);
    owned_sides_through(tb, ta);
    return true;
  });
  return count;
}

long count_crossings_brute_force(const std::vector<std::array<int, 3>>& triangles,
                                 const std::vector<V3>& x) {
  const SurfaceFeatures f = surface_features(triangles, x.size());
  long crossings = 0;
  for (const auto& e : f.edges)
    for (const auto& t : triangles)
      if (crosses(e, t, x)) ++crossings;
  return crossings;
}

}  // namespace clothlab
