#include "sim/contact/rigid_fit.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace clothlab {

Eigen::Matrix3d kabsch_rotation(const Eigen::Matrix3d& H) {
  if (!H.allFinite()) return Eigen::Matrix3d::Identity();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d V = svd.matrixV(), U = svd.matrixU();
  Eigen::Vector3d d(1.0, 1.0, (V * U.transpose()).determinant() < 0.0 ? -1.0 : 1.0);
  return V * d.asDiagonal() * U.transpose();
}

double interpolated_rotation_shrink(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  // cos^2(theta / 2) = (1 + cos theta) / 2 = (trace(A^T B) + 1) / 4; rounded down.
  const double c2 = ((A.transpose() * B).trace() + 1.0) / 4.0;
  return std::sqrt(std::clamp(c2, 0.0, 1.0)) * (1.0 - 1e-9);
}

}  // namespace clothlab
