// `clothlab trace`: run a scene for a simulated duration and write its CSV trace.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "sim/solver.hpp"

namespace clothlab {

struct TraceRunResult {
  long steps = 0;
  double simulated_time = 0.0;  // s
  double step_seconds = 0.0;    // wall-clock seconds spent in steps (file output excluded)
  long written_steps = 0;       // steps written to the file (step 0, every `every`-th, the last)
  Energy final_energy;
  std::optional<Divergence> divergence;  // set: no file was written
  bool stopped = false;                  // the progress callback asked to stop: no file written
};

// The most steps one trace may take (1e12: some 30 hours at the fastest step ClothLab has).
inline constexpr double kMaxTraceSteps = 1e12;

// The whole steps a run of `duration` seconds at step `dt` takes, as advance() counts them, or -1
// where the count is not finite or exceeds kMaxTraceSteps (dt = 1e-20 s for 1 s: 1e20 steps,
// beyond a long).
long whole_steps(double duration, double dt);

// Called after every stretch of steps with the steps done, the total and the wall-clock seconds
// spent stepping so far; returning false stops the run (nothing is written).
using TraceProgress = std::function<bool(long done, long total, double seconds)>;

// The trace a scene without a [trace] table gets: all fields of the middle vertex of the last
// row of the first cloth (the free edge of the default hanging sheet), every step.
TraceSpec default_trace(const Scene& scene);

// Writes the state at step 0 and then every `every` steps and at the last step. On divergence
// (the solver's monitor, or a non-finite value in a row about to be written) or a stop the
// temporary file is removed and nothing is written. `total` comes from whole_steps.
TraceRunResult run_trace(Solver& solver, const TraceSpec& spec, bool multi_cloth,
                         bool double_digits, long total, const std::string& out_path,
                         const TraceProgress& progress = {});

}  // namespace clothlab
