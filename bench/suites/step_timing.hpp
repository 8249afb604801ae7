// Timing a solver's step: batches of steps, each about 20 ms long, and the median seconds per
// step over them (robust against a batch disturbed by another process).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "bench/suites/report.hpp"
#include "sim/solver.hpp"

namespace clothlab::bench {

// Median seconds per step of `run(steps)` (which runs that many steps, and waits for them where
// they are queued, as on a GPU) over batches of about 20 ms, after a warm-up of 3 steps.
template <class Run>
double median_seconds_per_step(Run&& run, double total_seconds) {
  run(3L);  // warm-up: caches, OpenMP pool or shader compilation, the integrator's first step
  Stopwatch probe;
  run(1L);
  const double one = std::max(probe.seconds(), 1e-7);
  const long batch = std::max(1L, std::lround(0.02 / one));
  std::vector<double> samples;
  Stopwatch all;
  while (samples.size() < 5 || all.seconds() < total_seconds) {
    Stopwatch clock;
    run(batch);
    samples.push_back(clock.seconds() / double(batch));
  }
  return median(samples);
}

// `work` runs after every step when given (e.g. the field export being measured).
template <class Work>
double seconds_per_step(Solver& solver, double total_seconds, Work&& work) {
  return median_seconds_per_step(
      [&](long steps) {
        for (long k = 0; k < steps; ++k) {
          solver.step(1);
          work(solver);
        }
      },
      total_seconds);
}

inline double seconds_per_step(Solver& solver, double total_seconds) {
  return seconds_per_step(solver, total_seconds, [](Solver&) {});
}

}  // namespace clothlab::bench
