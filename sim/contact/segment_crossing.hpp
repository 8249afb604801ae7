// Whether a segment passes through a triangle: the crossing the intersection count counts
// (docs/contact.md section 7). Signs of orientation determinants (orient3d, Shewchuk 1997) in
// double: p and q strictly on opposite sides of the triangle's plane, and the line pq strictly
// inside the three edges' planes through it (the signed volumes of pq with each edge agree).
// Touching, coplanar and degenerate configurations (a zero in any sign) are not crossings: the
// count is of pairs that have passed through each other, not of pairs in contact.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace clothlab {

// Six times the signed volume of tetrahedron (a, b, c, d): positive when d lies below the plane
// of a, b, c as seen with a, b, c counter-clockwise.
inline double orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                       const Eigen::Vector3d& d) {
  return (a - d).dot((b - d).cross(c - d));
}

inline bool segment_crosses_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                                     const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                     const Eigen::Vector3d& c) {
  const double sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
  if (!((sp > 0.0 && sq < 0.0) || (sp < 0.0 && sq > 0.0))) return false;
  const double s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
  return (s1 > 0.0 && s2 > 0.0 && s3 > 0.0) || (s1 < 0.0 && s2 < 0.0 && s3 < 0.0);
}

}  // namespace clothlab
