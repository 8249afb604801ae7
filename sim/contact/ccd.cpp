#include "sim/contact/ccd.hpp"

#include <algorithm>
#include <cmath>

#include "sim/contact/primitive_distance.hpp"

namespace clothlab {

using V3 = Eigen::Vector3d;

double pair_dist2(PrimitivePair kind, const std::array<V3, 4>& x) {
  return kind == PrimitivePair::point_triangle ? point_triangle_dist2(x[0], x[1], x[2], x[3])
                                               : edge_edge_dist2(x[0], x[1], x[2], x[3]);
}

namespace {

// The most the pair's distance can shrink per unit time once the mean motion is removed.
double distance_rate_bound(PrimitivePair kind, const std::array<V3, 4>& d) {
  const double n0 = d[0].norm(), n1 = d[1].norm(), n2 = d[2].norm(), n3 = d[3].norm();
  if (kind == PrimitivePair::point_triangle) return n0 + std::max({n1, n2, n3});
  return std::max(n0, n1) + std::max(n2, n3);
}

// (d^2 - eta^2) / (d + eta): the gap d - eta, from the squared distance without cancellation.
double gap(double dist2, double eta) {
  return (dist2 - eta * eta) / (std::sqrt(dist2) + eta);
}

}  // namespace

double additive_ccd(PrimitivePair kind, const std::array<V3, 4>& x0, const std::array<V3, 4>& x1,
                    const CcdOptions& o) {
  std::array<V3, 4> d, x = x0;
  V3 mean = V3::Zero();
  for (int k = 0; k < 4; ++k) {
    d[std::size_t(k)] = x1[std::size_t(k)] - x0[std::size_t(k)];
    mean += d[std::size_t(k)];
  }
  mean *= 0.25;
  for (V3& dk : d) dk -= mean;
  const double lp = distance_rate_bound(kind, d);
  double dist2 = pair_dist2(kind, x);
  if (!(dist2 > o.eta * o.eta)) return lp > 0.0 ? 0.0 : -1.0;  // touching: moving is contact
  if (!(lp > 0.0)) return -1.0;                                // rigid motion keeps every distance
  const double g0 = gap(dist2, o.eta);
  if (g0 > lp * o.t_max) return -1.0;  // cannot close the gap within the step
  const double stop = o.tolerance > 0.0 ? std::min(o.s * g0, o.tolerance) : o.s * g0;
  double toi = 0.0;
  double advance = (1.0 - o.s) * g0 / lp;
  for (int it = 0; it < CcdOptions::kMaxIterations; ++it) {
    for (int k = 0; k < 4; ++k) x[std::size_t(k)] += advance * d[std::size_t(k)];
    dist2 = pair_dist2(kind, x);
    const double g = dist2 > o.eta * o.eta ? gap(dist2, o.eta) : 0.0;
    // toi is the last time known to keep the gap above `stop`.
    if (toi > 0.0 && g < stop) return toi;
    toi += advance;
    if (toi > o.t_max) return -1.0;
    advance = 0.9 * g / lp;
  }
  return toi;
}

}  // namespace clothlab
