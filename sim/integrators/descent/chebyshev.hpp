// Chebyshev semi-iterative acceleration of a stationary iteration (Wang 2015, "A Chebyshev
// semi-iterative approach for accelerating projective and position-based dynamics", ACM TOG
// 34(6), eq. (12)): after the plain update x^ of iteration k + 1,
//   x^(k+1) = omega_(k+1) (x^ - x^(k-1)) + x^(k-1),
//   omega_(S+1) = 2 / (2 - rho^2),   omega_(k+1) = 4 / (4 - rho^2 omega_k),
// with rho the iteration's spectral radius (an estimate: too large and the iteration diverges, too
// small and it gains little) and the first S iterations plain, as Wang does. Each new iterate is
// an affine combination of two iterates (the weights omega and 1 - omega sum to 1), so whatever
// each plain iterate conserves (momentum, pinned positions) the accelerated one conserves too.
#pragma once

namespace clothlab {

struct Chebyshev {
  double rho = 0.0;  // spectral radius estimate, in [0, 1)
  int delay = 1;     // S: plain iterations before the first accelerated one (at least 1)
};

// solver.chebyshev_rho that leaves the iteration plain: omega = 2 / (2 - 1e-18) is 1 in double.
inline constexpr double kChebyshevOff = 1e-9;

// The acceleration a method runs: solver.chebyshev_rho when set (> 0), else its own default.
inline Chebyshev chebyshev_of(double requested_rho, double default_rho, int delay) {
  return {requested_rho > 0.0 ? requested_rho : default_rho, delay};
}

// The weight of iteration `it` (0-based: the update that makes x^(it + 1)), given the previous
// iteration's weight; 1 while the iteration is still plain.
inline double chebyshev_weight(const Chebyshev& c, int it, double previous) {
  const double rho2 = c.rho * c.rho;
  if (it < c.delay) return 1.0;
  if (it == c.delay) return 2.0 / (2.0 - rho2);
  return 4.0 / (4.0 - rho2 * previous);
}

}  // namespace clothlab
