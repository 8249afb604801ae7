// `clothlab trace`: run a scene for a simulated duration and write its CSV trace.
#pragma once

#include <optional>
#include <string>

#include "sim/solver.hpp"

namespace clothlab {

struct TraceRunResult {
  long steps = 0;
  double simulated_time = 0.0;  // s
  double step_seconds = 0.0;    // wall-clock seconds spent in steps (file output excluded)
  long rows = 0;
  Energy final_energy;
  std::optional<Divergence> divergence;  // set: no file was written
};

// The trace a scene without a [trace] table gets: all fields of the middle vertex of the last
// row of the first cloth (the free edge of the default hanging sheet), every step.
TraceSpec default_trace(const Scene& scene);

// Writes the state at step 0 and then every `every` steps and at the last step. On divergence
// the temporary file is removed and nothing is written.
TraceRunResult run_trace(Solver& solver, const TraceSpec& spec, bool multi_cloth,
                         bool double_digits, double duration, const std::string& out_path);

}  // namespace clothlab
