// Closest points between the primitives of triangle contact (docs/contact.md section 7): a point
// and a triangle, two segments. In double, with every degenerate case (a zero-area triangle, a
// zero-length or parallel segment) answered by a nearby regular one, so callers never divide by
// zero. The region tests follow Ericson 2005, "Real-Time Collision Detection", sections 5.1.5
// (point-triangle Voronoi regions) and 5.1.9 (segment-segment with clamping). Defined here,
// inline: triangle contact calls them millions of times a second from its pair tests.
#pragma once

#include <algorithm>

#include <Eigen/Core>

namespace clothlab {

// The closest point of triangle (a, b, c) to p is w[0] a + w[1] b + w[2] c.
struct PointTriangleClosest {
  double w[3] = {1, 0, 0};
  double dist2 = 0.0;
};

// The closest points of segments p0p1 and q0q1 are p0 + s (p1 - p0) and q0 + t (q1 - q0).
struct EdgeEdgeClosest {
  double s = 0.0, t = 0.0;
  double dist2 = 0.0;
};

// The helpers of the functions below.
namespace primitive_detail {

using V3 = Eigen::Vector3d;

inline PointTriangleClosest closest_at(const V3& p, const V3& a, const V3& b, const V3& c, double u,
                                       double v, double w) {
  PointTriangleClosest r;
  r.w[0] = u;
  r.w[1] = v;
  r.w[2] = w;
  r.dist2 = (p - (u * a + v * b + w * c)).squaredNorm();
  return r;
}

// The closest point on segment ab as the weight of b.
inline double segment_parameter(const V3& p, const V3& a, const V3& b) {
  const V3 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (!(len2 > 0.0)) return 0.0;
  return std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
}

// A degenerate triangle (its face region's determinant vanishes): the best of its three sides.
inline PointTriangleClosest closest_on_sides(const V3& p, const V3& a, const V3& b, const V3& c) {
  const double tab = segment_parameter(p, a, b), tbc = segment_parameter(p, b, c),
               tca = segment_parameter(p, c, a);
  PointTriangleClosest best = closest_at(p, a, b, c, 1 - tab, tab, 0);
  const PointTriangleClosest on_bc = closest_at(p, a, b, c, 0, 1 - tbc, tbc);
  const PointTriangleClosest on_ca = closest_at(p, a, b, c, tca, 0, 1 - tca);
  if (on_bc.dist2 < best.dist2) best = on_bc;
  if (on_ca.dist2 < best.dist2) best = on_ca;
  return best;
}

}  // namespace primitive_detail

// Ericson 2005, section 5.1.5: the Voronoi regions of the vertices, then the edges, then the face.
inline PointTriangleClosest closest_point_triangle(const Eigen::Vector3d& p,
                                                   const Eigen::Vector3d& a,
                                                   const Eigen::Vector3d& b,
                                                   const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return primitive_detail::closest_at(p, a, b, c, 1, 0, 0);
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return primitive_detail::closest_at(p, a, b, c, 0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0) {
    const double v = d1 / (d1 - d3);
    return primitive_detail::closest_at(p, a, b, c, 1 - v, v, 0);
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return primitive_detail::closest_at(p, a, b, c, 0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0) {
    const double w = d2 / (d2 - d6);
    return primitive_detail::closest_at(p, a, b, c, 1 - w, 0, w);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 && (d4 - d3) + (d5 - d6) > 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return primitive_detail::closest_at(p, a, b, c, 0, 1 - w, w);
  }
  const double sum = va + vb + vc;
  // sum is twice the squared area's worth (|ab x ac|^2): a sliver's face region is unreliable.
  if (!(sum > 1e-30 * (ab.squaredNorm() * ac.squaredNorm() + 1e-300)))
    return primitive_detail::closest_on_sides(p, a, b, c);
  const double v = vb / sum, w = vc / sum;
  return primitive_detail::closest_at(p, a, b, c, 1 - v - w, v, w);
}

// Ericson 2005, section 5.1.9: the unclamped closest parameters of the two lines, clamped to
// the segments one after the other; a zero-length segment is a point, parallel lines take s = 0.
inline EdgeEdgeClosest closest_edge_edge(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                         const Eigen::Vector3d& q0, const Eigen::Vector3d& q1) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  constexpr double kTiny = 1e-300;
  EdgeEdgeClosest out;
  if (a <= kTiny && e <= kTiny) {
    out.dist2 = r.squaredNorm();
    return out;
  }
  double s = 0.0, t = 0.0;
  if (a <= kTiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= kTiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      // Parallel (denom within round-off of 0): any s works; 0 keeps it deterministic.
      s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      // t clamped to an end, s again for that end; both ends' s computed and one chosen (a
      // select, not a branch: which end, if any, is as likely as not).
      const double free_t = (b * s + f) / e;
      const double s_at0 = std::clamp(-c / a, 0.0, 1.0), s_at1 = std::clamp((b - c) / a, 0.0, 1.0);
      s = free_t < 0.0 ? s_at0 : free_t > 1.0 ? s_at1 : s;
      t = free_t < 0.0 ? 0.0 : free_t > 1.0 ? 1.0 : free_t;
    }
  }
  out.s = s;
  out.t = t;
  out.dist2 = (p0 + s * d1 - (q0 + t * d2)).squaredNorm();
  return out;
}

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
