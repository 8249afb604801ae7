// The rigid motion that best carries one set of points onto another, for the contact's Verlet
// list (sim/contact/triangle_contact.hpp): a rigid motion of every vertex changes no distance, so
// a vertex's stray from it bounds how much its pairs' distances changed.
#pragma once

#include <Eigen/Core>

namespace clothlab {

// The rotation of the least-squares rigid fit (Kabsch 1976): with the cross-covariance
// H = sum_i (a_i - mean a)(b_i - mean b)^T = U S V^T, R = V diag(1, 1, d) U^T, d = det(V U^T),
// minimises sum_i |R (a_i - mean a) + mean b - b_i|^2 over rotations. Any H gives a rotation
// (the identity for H = 0).
Eigen::Matrix3d kabsch_rotation(const Eigen::Matrix3d& H);

// A lower bound on the smallest singular value of (1 - s) A + s B over s in [0, 1] for rotations
// A and B: cos(theta / 2) with theta the angle of A^T B. (1 - s) I + s Q is normal with
// eigenvalues 1 and (1 - s) + s exp(+-i theta), of modulus at least cos(theta / 2) (at s = 1/2).
// A straight motion between two rigid motions shrinks no distance below this factor.
double interpolated_rotation_shrink(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B);

}  // namespace clothlab
