// One vertex of a structure-of-arrays Vec3Array as an Eigen vector in double, for the per-vertex
// geometry of the contact code (distances, normals), which works in double whatever the solver's
// scalar type.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "sim/core/vec3_array.hpp"

namespace clothlab {

template <class T>
Eigen::Vector3d load3(const Vec3Array<T>& a, std::size_t i) {
  return {double(a.x[i]), double(a.y[i]), double(a.z[i])};
}

// Every vertex as an Eigen vector in double.
template <class T>
std::vector<Eigen::Vector3d> points_of(const Vec3Array<T>& a) {
  std::vector<Eigen::Vector3d> x(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) x[i] = load3(a, i);
  return x;
}

template <class T>
void store3(Vec3Array<T>& a, std::size_t i, const Eigen::Vector3d& v) {
  a.x[i] = static_cast<T>(v.x());
  a.y[i] = static_cast<T>(v.y());
  a.z[i] = static_cast<T>(v.z());
}

}  // namespace clothlab
