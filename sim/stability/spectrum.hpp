// The highest frequencies of a cloth's linearised dynamics, for choosing a stable step and for
// the stability benchmark's theoretical limits.
//  omega_max: the largest eigenvalue of M^-1 K at the rest state, square-rooted (rad/s); K holds
//             each spring's k d d^T (no tension at rest), pinned vertices are fixed.
//  gamma_max: the largest damping rate of M^-1 C (1/s), C built like K from the along-spring
//             damping c, plus the linear drag over the smallest vertex mass.
// Both come from a Lanczos iteration on the symmetric form M^-1/2 K M^-1/2 (its top Ritz value
// converges from below within a few dozen products; Golub & Van Loan, "Matrix Computations",
// ch. 10). Gershgorin's bound is reported as a cheap upper limit to check it against.
#pragma once

#include "sim/model/model.hpp"

namespace clothlab {

struct Spectrum {
  double omega_max = 0.0;         // rad/s, Lanczos estimate (a lower bound, converged to ~1 %)
  double omega_gershgorin = 0.0;  // rad/s, an upper bound
  double gamma_max = 0.0;         // 1/s
};

template <class T>
Spectrum estimate_spectrum(const Model<T>& m);

}  // namespace clothlab
