// The lab's own count of cloth passing through cloth (docs/contact.md section 7): the number of
// (edge, triangle) pairs of the cloth surfaces, sharing no vertex, whose edge segment passes
// through the triangle (sim/contact/segment_crossing.hpp). Within a cloth and between cloths;
// touching and coplanar pairs are not crossings. The count is what the trace summary, the Python
// module and the contact suite report; 0 is the no-crossing guarantee's target.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "sim/contact/surface_features.hpp"
#include "sim/contact/triangle_bvh.hpp"

namespace clothlab {

// One crossing: edge `edge` of features().edges passes through triangle `triangle`.
struct Crossing {
  int edge = 0, triangle = 0;
};

class IntersectionCounter {
 public:
  // triangles over the vertices of `rest` (the shape the tree is cut from).
  IntersectionCounter(const std::vector<std::array<int, 3>>& triangles,
                      const std::vector<Eigen::Vector3d>& rest);

  // Crossing pairs at positions x (one per vertex); each one into `crossings` when given
  // (cleared first; it grows only past its capacity).
  long count(const std::vector<Eigen::Vector3d>& x, std::vector<Crossing>* crossings = nullptr);
  const SurfaceFeatures& features() const { return features_; }

 private:
  SurfaceFeatures features_;
  TriangleBvh bvh_;
};

// Every edge against every triangle: the definition itself, for tests of the counter.
long count_crossings_brute_force(const std::vector<std::array<int, 3>>& triangles,
                                 const std::vector<Eigen::Vector3d>& x);

// The centroid of each triangle at x.
std::vector<Eigen::Vector3d> triangle_centroids(const std::vector<std::array<int, 3>>& triangles,
                                                const std::vector<Eigen::Vector3d>& x);

}  // namespace clothlab
