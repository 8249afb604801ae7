#include "sim/trace/trace_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "sim/trace/csv_trace.hpp"

namespace clothlab {

TraceSpec default_trace(const Scene& scene) {
  TraceSpec spec;
  const ClothSpec& c = scene.cloths.front();
  spec.vertices.push_back({0, c.resolution[0] / 2, c.resolution[1] - 1});
  return spec;
}

TraceRunResult run_trace(Solver& solver, const TraceSpec& spec, bool multi_cloth,
                         bool double_digits, double duration, const std::string& out_path) {
  using Clock = std::chrono::steady_clock;
  TraceRunResult r;
  TraceWriter writer(out_path, spec, multi_cloth, double_digits);
  // The same whole-step count advance() would take for this duration.
  const auto total = static_cast<long>(std::floor(duration / solver.dt() * (1.0 + 1e-12)));
  writer.write_step(solver);
  ++r.rows;
  Clock::duration stepping{};
  while (r.steps < total) {
    const long chunk = std::min<long>(spec.every, total - r.steps);
    const auto t0 = Clock::now();
    const AdvanceResult a = solver.step(chunk);
    stepping += Clock::now() - t0;
    r.steps += a.steps;
    if (a.divergence) {
      r.divergence = a.divergence;
      break;  // the writer's destructor removes the temporary file
    }
    writer.write_step(solver);
    ++r.rows;
  }
  r.step_seconds = std::chrono::duration<double>(stepping).count();
  r.simulated_time = solver.time();
  r.final_energy = solver.energy();
  if (!r.divergence) writer.commit();
  return r;
}

}  // namespace clothlab
