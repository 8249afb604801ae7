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

long whole_steps(double duration, double dt) {
  // The same relative margin as advance(): 1.0 / 0.001 is 999.99...
  const double steps = std::floor(duration / dt * (1.0 + 1e-12));
  if (!(steps >= 0.0 && steps <= kMaxTraceSteps)) return -1;
  return static_cast<long>(steps);
}

namespace {

// A row about to hold a non-finite value is a divergence: the trace is not written.
bool row_is_finite(const TraceWriter& writer, const Solver& solver, TraceRunResult& r) {
  if (writer.finite()) return true;
  Divergence d;
  d.step = solver.step_count();
  d.time = solver.time();
  d.quantity = writer.first_non_finite() + " in the trace row";
  r.divergence = d;
  return false;
}

// The row just written: its energy (when the trace has energy columns) beyond the divergence
// monitor's limit is a divergence at its step, checked once per row.
bool row_energy_is_bounded(const TraceWriter& writer, const Solver& solver, TraceRunResult& r) {
  const std::optional<Energy>& e = writer.last_energy();
  if (!e || !writer.finite()) return true;  // a non-finite row is row_is_finite's
  r.divergence = solver.energy_divergence(*e);
  return !r.divergence;
}

}  // namespace

TraceRunResult run_trace(Solver& solver, const TraceSpec& spec, bool multi_cloth,
                         bool double_digits, long total, const std::string& out_path,
                         const TraceProgress& progress) {
  using Clock = std::chrono::steady_clock;
  // Steps between progress reports, so that a trace written rarely (every = 1e6) still reports:
  // one at first, doubling while a stretch takes under kReportSeconds, up to kReportSteps (a
  // large cloth's first report comes after one step, not after 256).
  constexpr long kReportSteps = 256;
  constexpr double kReportSeconds = 0.05;
  long stretch = 1;
  TraceRunResult r;
  TraceWriter writer(out_path, spec, multi_cloth, double_digits);
  writer.write_step(solver);
  ++r.written_steps;
  Clock::duration stepping{};
  long next_row = std::min<long>(spec.every, total);
  const bool first_row_bounded = row_energy_is_bounded(writer, solver, r);
  while (first_row_bounded && r.steps < total && row_is_finite(writer, solver, r)) {
    const long chunk = std::min<long>(stretch, next_row - r.steps);
    const auto t0 = Clock::now();
    const AdvanceResult a = solver.step(chunk);
    const auto took = Clock::now() - t0;
    stepping += took;
    if (std::chrono::duration<double>(took).count() < kReportSeconds)
      stretch = std::min(2 * stretch, kReportSteps);
    r.steps += a.steps;
    if (a.divergence) {
      r.divergence = a.divergence;
      break;  // the writer's destructor removes the temporary file
    }
    if (progress && !progress(r.steps, total, std::chrono::duration<double>(stepping).count())) {
      r.stopped = true;
      break;
    }
    if (r.steps < next_row) continue;
    writer.write_step(solver);
    ++r.written_steps;
    if (!row_energy_is_bounded(writer, solver, r)) break;
    next_row = std::min<long>(next_row + spec.every, total);
  }
  if (!r.divergence && !r.stopped) row_is_finite(writer, solver, r);
  r.step_seconds = std::chrono::duration<double>(stepping).count();
  r.simulated_time = solver.time();
  r.final_energy = solver.energy();
  // The summary's energy is checked like a row's: a state stretched beyond the scale is a
  // divergence even where the velocities have not grown yet.
  if (!r.divergence && !r.stopped) r.divergence = solver.energy_divergence(r.final_energy);
  if (!r.divergence && !r.stopped) writer.commit();
  return r;
}

}  // namespace clothlab
