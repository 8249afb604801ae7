#include "sim/mesh/closest_point.hpp"

namespace clothlab {

TrianglePoint closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                  const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  using V3 = Eigen::Vector3d;
  const V3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {a, V3(1, 0, 0)};  // vertex region a
  const V3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {b, V3(0, 1, 0)};  // vertex region b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {  // edge ab
    const double v = d1 / (d1 - d3);
    return {a + v * ab, V3(1 - v, v, 0)};
  }
  const V3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {c, V3(0, 0, 1)};  // vertex region c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {  // edge ac
    const double w = d2 / (d2 - d6);
    return {a + w * ac, V3(1 - w, 0, w)};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {  // edge bc
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + w * (c - b), V3(0, 1 - w, w)};
  }
  const double denom = 1.0 / (va + vb + vc);  // the face
  const double v = vb * denom, w = vc * denom;
  return {a + ab * v + ac * w, V3(1 - v - w, v, w)};
}

}  // namespace clothlab
