// Measuring stability: what "stable" means for a run, and the search for the largest stable step.
#pragma once

#include <string>

#include "sim/scene/scene.hpp"

namespace clothlab::bench {

// A run is stable when, over `duration` simulated seconds from a slightly disturbed start
// (every free vertex displaced by up to `perturbation` edge lengths, so every mode is excited
// from the first step), it
//  - is never caught by the divergence monitor (non-finite values, runaway kinetic energy), and
//  - keeps its mechanical energy (kinetic + elastic + gravity) below its start value plus
//    `energy_tolerance` times the gravity scale M |g| size, checked every few steps: the scenes
//    it is used on have no wind, so energy can only fall (damping, drag) or oscillate (a
//    symplectic method's energy error near its limit is of the order of the energy in the
//    fastest motion, so the margin is wide); an unstable mode grows geometrically per step and
//    crosses any such margin within a few dozen steps of a step just 1 % past the limit.
struct StabilityCheck {
  double duration = 0.5;          // s
  double perturbation = 1e-3;     // edge lengths
  double energy_tolerance = 0.5;  // of M |g| size
};

struct StabilityOutcome {
  bool stable = false;
  long steps = 0;
  std::string reason;  // why not stable: "diverged at step ...", "energy grew by ..."
};

StabilityOutcome check_stability(const Scene& scene, double dt, const StabilityCheck& check);

struct LimitSearch {
  double dt = 0.0;          // the largest step found stable (s); 0 if none above `floor`
  bool at_ceiling = false;  // stable at the ceiling itself: the limit is at least that
  int runs = 0;
};

// Geometric bisection between a stable and an unstable step, starting from `guess`, until the
// bracket is narrower than `relative_tolerance`; steps above `ceiling` are not tried.
LimitSearch largest_stable_dt(const Scene& scene, double guess, double ceiling,
                              double relative_tolerance, const StabilityCheck& check);

}  // namespace clothlab::bench
