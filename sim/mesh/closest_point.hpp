// The point of a triangle closest to a given point, with its barycentric weights (Ericson 2005,
// "Real-Time Collision Detection", section 5.1.5, by Voronoi regions): the distance queries of the
// mesh collider's grid (sdf_grid.cpp) and the collider features' contacts against cloth
// triangles (sim/contact/feature_contacts.hpp).
#pragma once

#include <Eigen/Core>

namespace clothlab {

struct TrianglePoint {
  Eigen::Vector3d point;    // the closest point, a * w[0] + b * w[1] + c * w[2]
  Eigen::Vector3d weights;  // barycentric, each in [0, 1], summing to 1
  // Whether the point lies strictly inside the triangle (p projects onto its interior).
  bool interior() const { return weights.minCoeff() > 0.0; }
};

TrianglePoint closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                  const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace clothlab
