// Closest points between the primitives of triangle contact (docs/contact.md section 7): a point
// and a triangle, two segments. In double, with every degenerate case (a zero-area triangle, a
// zero-length or parallel segment) answered by a nearby regular one, so callers never divide by
// zero. The region tests follow Ericson 2005, "Real-Time Collision Detection", sections 5.1.5
// (point-triangle Voronoi regions) and 5.1.9 (segment-segment with clamping).
#pragma once

#include <Eigen/Core>

namespace clothlab {

// The closest point of triangle (a, b, c) to p is w[0] a + w[1] b + w[2] c.
struct PointTriangleClosest {
  double w[3] = {1, 0, 0};
  double dist2 = 0.0;
};
PointTriangleClosest closest_point_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                            const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// The closest points of segments p0p1 and q0q1 are p0 + s (p1 - p0) and q0 + t (q1 - q0).
struct EdgeEdgeClosest {
  double s = 0.0, t = 0.0;
  double dist2 = 0.0;
};
EdgeEdgeClosest closest_edge_edge(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                  const Eigen::Vector3d& q0, const Eigen::Vector3d& q1);

// Squared distances alone (the CCD's inner loop).
inline double point_triangle_dist2(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                   const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return closest_point_triangle(p, a, b, c).dist2;
}
inline double edge_edge_dist2(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                              const Eigen::Vector3d& q0, const Eigen::Vector3d& q1) {
  return closest_edge_edge(p0, p1, q0, q1).dist2;
}

}  // namespace clothlab
