// Box tests on one contact pair at one moment (docs/contact.md section 7): the pair's four
// vertices x, its first side the point (x[0]) or edge p (x[0], x[1]), its other side the triangle
// (x[1..3]) or edge q (x[2], x[3]). Cheaper than the exact distance, and never wrong in the
// direction that would drop a pair: two sides whose boxes are farther apart than d along some
// axis, or whose boxes' Euclidean gap exceeds d, are farther apart than d.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>

namespace clothlab {

// The span along axis a of the pair's first side and of its other side.
struct SideSpans {
  double lo_p, hi_p, lo_q, hi_q;
};
[[gnu::always_inline]] inline SideSpans side_spans(bool edge_edge,
                                                   const std::array<Eigen::Vector3d, 4>& x,
                                                   long a) {
  SideSpans s{x[0][a], x[0][a], x[3][a], x[3][a]};
  if (edge_edge) {
    s.lo_p = std::min(s.lo_p, x[1][a]);
    s.hi_p = std::max(s.hi_p, x[1][a]);
    s.lo_q = std::min(s.lo_q, x[2][a]);
    s.hi_q = std::max(s.hi_q, x[2][a]);
  } else {
    s.lo_q = std::min(std::min(s.lo_q, x[1][a]), x[2][a]);
    s.hi_q = std::max(std::max(s.hi_q, x[1][a]), x[2][a]);
  }
  return s;
}

// Whether the two sides' boxes come within d of each other along every axis (false for NaN).
[[gnu::always_inline]] inline bool points_within(bool edge_edge,
                                                 const std::array<Eigen::Vector3d, 4>& x,
                                                 double d) {
  for (long a = 0; a < 3; ++a) {
    const SideSpans s = side_spans(edge_edge, x, a);
    if (!(s.lo_p <= s.hi_q + d) || !(s.lo_q <= s.hi_p + d)) return false;
  }
  return true;
}

// The squared Euclidean gap between the two sides' boxes: at most the sides' squared distance.
[[gnu::always_inline]] inline double box_gap2(bool edge_edge,
                                              const std::array<Eigen::Vector3d, 4>& x) {
  double gap2 = 0.0;
  for (long a = 0; a < 3; ++a) {
    const SideSpans s = side_spans(edge_edge, x, a);
    const double gap = std::max({0.0, s.lo_q - s.hi_p, s.lo_p - s.hi_q});
    gap2 += gap * gap;
  }
  return gap2;
}

}  // namespace clothlab
