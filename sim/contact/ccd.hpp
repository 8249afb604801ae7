// Continuous collision detection for the primitives of triangle contact (docs/contact.md section
// 7): does a point and a triangle, or two edges, come closer than a separation `eta` while their
// vertices move linearly from x0 to x1 over the substep?
//
// Additive CCD (Li, Kaufman & Jiang 2021, "Codimensional Incremental Potential Contact",
// Algorithm 1): the mean displacement is subtracted (it moves the pair rigidly), lp bounds how
// fast the distance can shrink per unit time (for a point and a triangle |dp| + max |d_i|, for two
// edges max |d_p| + max |d_q|), and time advances by a fraction of gap / lp, which no motion can
// close; it stops when the gap has fallen to `s` of its start, or below `tolerance` when that is
// set and smaller. It is conservative: it never reports a later time than the true first contact
// at distance eta, and never misses one; it may report a pair that only comes within
// eta + min(s gap, tolerance). No cubic is solved, so the parallel, coplanar and touching cases
// need no special treatment. At most kMaxIterations advances; a pair that needs more is reported
// at the time reached (conservative).
#pragma once

#include <Eigen/Core>
#include <array>

namespace clothlab {

enum class PrimitivePair { point_triangle, edge_edge };

struct CcdOptions {
  double eta = 0.0;        // m: the separation counted as contact
  double s = 0.1;          // the gap's fraction at which it stops
  double tolerance = 0.0;  // m: it stops at a gap below this too (0: only s)
  double t_max = 1.0;      // the fraction of the step tested
  static constexpr int kMaxIterations = 1000;
};

// x0[k], x1[k]: the pair's four vertices at the start and end (point, then the triangle's three;
// or edge p's two, then edge q's two). Returns the time of impact in [0, t_max], or a negative
// number when the pair stays apart.
double additive_ccd(PrimitivePair kind, const std::array<Eigen::Vector3d, 4>& x0,
                    const std::array<Eigen::Vector3d, 4>& x1, const CcdOptions& options);

// The pair's squared distance at positions x.
double pair_dist2(PrimitivePair kind, const std::array<Eigen::Vector3d, 4>& x);

}  // namespace clothlab
