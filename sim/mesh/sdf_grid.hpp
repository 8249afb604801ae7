// The signed distance field of a closed triangle mesh, sampled once at load on a regular grid
// (a mesh collider, docs/contact.md section 1: phi by trilinear lookup, the normal from its
// gradient). Built in three passes:
//  1. exact point-triangle distances (Ericson, "Real-Time Collision Detection" 5.1.5) for the
//     grid points near each triangle (a band of two cells round its box);
//  2. the closest triangle propagated to every other point by sweeps in the eight diagonal
//     directions, each point trying its neighbours' closest triangles (closest-feature
//     propagation, as in Mauch's closest point transform; exact where the propagation holds);
//  3. the sign by ray parity along x for every (y, z) row, the rays nudged off the grid planes
//     so they do not run along an axis-aligned mesh's edges. The mesh must be closed.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "sim/mesh/triangle_mesh.hpp"

namespace clothlab {

class SdfGrid {
 public:
  // `resolution` cells along the mesh's longest side; the grid reaches `margin` cells beyond
  // the mesh on every side.
  SdfGrid(const TriangleMesh& mesh, int resolution = 64, int margin = 4);

  // Signed distance at p (negative inside) by trilinear interpolation, and its gradient
  // (normalised; the outward normal). Beyond the grid: the value at the nearest grid point plus
  // the distance to it.
  double distance(const Eigen::Vector3d& p, Eigen::Vector3d* gradient = nullptr) const;

  Eigen::Vector3d lo() const { return origin_; }
  Eigen::Vector3d hi() const {
    return origin_ + cell_ * Eigen::Vector3d(count_[0] - 1, count_[1] - 1, count_[2] - 1);
  }
  double cell() const { return cell_; }

 private:
  double at(int i, int j, int k) const {
    return phi_[static_cast<std::size_t>(i + count_[0] * (j + count_[1] * k))];
  }

  Eigen::Vector3d origin_;
  double cell_ = 0.0;
  std::array<int, 3> count_{};  // grid points along x, y, z
  std::vector<double> phi_;
};

}  // namespace clothlab
