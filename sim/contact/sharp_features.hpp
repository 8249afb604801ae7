// A collider's sharp features as points, for the contacts between them and the cloth's triangles
// (sim/contact/feature_contacts.hpp): a box's corners and points along its edges (on the rounded
// surface where the box is rounded), a mesh collider's vertices and points along its creases
// (edges whose faces meet at more than kCreaseDegrees). Each point carries the outward direction
// of the surface there (the side of the cloth it belongs on when no earlier state says). Smooth
// shapes (plane, sphere, capsule) have none: the cloth's vertices and edge midpoints find every
// contact with them. Held in the collider's own frame with a uniform grid over the points, so that
// a triangle finds the features near it from its box; built once, read-only afterwards.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "sim/scene/collider_spec.hpp"

namespace clothlab {

struct SharpFeatures {
  static constexpr double kCreaseDegrees = 30.0;

  std::vector<Eigen::Vector3d> points;   // collider frame
  std::vector<Eigen::Vector3d> outward;  // unit, collider frame
  // The grid: cell (i, j, k) spans lo + cell * [i, i + 1) x ...; its points are
  // items[start[c] .. start[c + 1]) for c = i + dims[0] * (j + dims[1] * k). lo and hi bound
  // the points.
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  double cell = 1.0;
  std::array<int, 3> dims{0, 0, 0};
  std::vector<int> start, items;

  // Cells within kNearCells of a cell that holds a point, over the grid grown by kNearCells on
  // every side: near(p) says that no feature lies within kNearCells cells of p along any axis
  // when it is false (with cells of half the cloth's longest edge, two edges).
  static constexpr int kNearCells = 4;
  std::array<int, 3> near_dims{0, 0, 0};
  std::vector<char> near_cells;

  bool empty() const { return points.empty(); }

  bool near(const Eigen::Vector3d& p) const {
    std::array<int, 3> c{};
    for (int d = 0; d < 3; ++d) {
      const double x = (p[d] - lo[d]) / cell + kNearCells;
      if (!(x >= 0.0 && x < near_dims[std::size_t(d)])) return false;
      c[std::size_t(d)] = static_cast<int>(x);
    }
    return near_cells[std::size_t(c[0] + near_dims[0] * (c[1] + near_dims[1] * c[2]))] != 0;
  }

  // Calls fn(index) for every point whose cell meets the box [qlo, qhi] (collider frame); the
  // caller tests the distance itself.
  template <class Fn>
  void for_each_near(const Eigen::Vector3d& qlo, const Eigen::Vector3d& qhi, Fn&& fn) const {
    if (empty()) return;
    std::array<int, 3> a{}, b{};
    for (int d = 0; d < 3; ++d) {
      const double l = (qlo[d] - lo[d]) / cell, h = (qhi[d] - lo[d]) / cell;
      if (h < 0.0 || l >= dims[d]) return;
      a[d] = std::max(0, static_cast<int>(std::floor(l)));
      b[d] = std::min(dims[d] - 1, static_cast<int>(std::floor(h)));
    }
    for (int k = a[2]; k <= b[2]; ++k)
      for (int j = a[1]; j <= b[1]; ++j)
        for (int i = a[0]; i <= b[0]; ++i) {
          const auto c = static_cast<std::size_t>(i + dims[0] * (j + dims[1] * k));
          for (int e = start[c]; e < start[c + 1]; ++e) fn(items[std::size_t(e)]);
        }
  }
};

// The collider's sharp features, points along an edge at most `spacing` apart (half the cloth's
// longest edge: a triangle lying across a collider's edge then always has a point under it), in
// a grid of cells `spacing` wide (wider where that would take more than 64 along an axis).
SharpFeatures sharp_features(const ColliderSpec& spec, double spacing);

}  // namespace clothlab
