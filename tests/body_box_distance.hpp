// The mannequin's box primitives measured independently of the colliders: the signed distance
// from a point to a posed box, |max(q, 0)| + min(max_i q_i, 0) with q = |p| - h in the box's frame.
#pragma once

#include <Eigen/Dense>
#include <algorithm>

#include "sim/body/mannequin.hpp"

namespace clothlab::testing {

// Signed distance from a point to a box primitive's surface (negative inside).
inline double box_distance(const BodyPrimitive& box, const RigidState& f,
                           const Eigen::Vector3d& x) {
  const Eigen::Vector3d q =
      (f.rotation.conjugate() * (x - f.position)).cwiseAbs() - box.half_extents;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

}  // namespace clothlab::testing
