#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "apps/clothlab/commands.hpp"
#include "apps/clothlab/progress_bar.hpp"
#include "factory/solver_factory.hpp"
#include "sim/core/passive_openmp.hpp"
#include "sim/scene/scene_parser.hpp"
#include "sim/solver.hpp"
#include "sim/stability/step_advice.hpp"
#include "sim/trace/trace_run.hpp"

namespace clothlab::app {

std::string replay_command(const std::string& scene, const std::vector<std::string>& overrides,
                           double duration) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", duration);
  std::string cmd = "clothlab trace '" + scene + "' --duration " + buf + " --out replay.csv";
  for (const auto& o : overrides) cmd += " --set '" + o + "'";
  return cmd;
}

namespace {

// A trace longer than this (estimated from its first half second of steps) is refused: 24 hours.
constexpr double kMaxTraceSeconds = 24.0 * 3600.0;
// From this estimated length on, the run says its size and shows a progress bar.
constexpr double kAnnounceSeconds = 5.0;
// Steps timed before the estimate is made.
constexpr double kProbeSeconds = 0.5;

std::string duration_words(double seconds) {
  char buf[48];
  if (seconds < 120.0)
    std::snprintf(buf, sizeof buf, "%.3g s", seconds);
  else if (seconds < 7200.0)
    std::snprintf(buf, sizeof buf, "%.3g min", seconds / 60.0);
  else if (seconds < 172800.0)
    std::snprintf(buf, sizeof buf, "%.3g h", seconds / 3600.0);
  else
    std::snprintf(buf, sizeof buf, "%.0f days", seconds / 86400.0);
  return buf;
}

// Watches a run: after kProbeSeconds of stepping it estimates the whole run; one beyond
// kMaxTraceSeconds stops (said, exit 2), one beyond kAnnounceSeconds is announced and gets a
// progress bar with the time left.
class TraceWatch {
 public:
  // quiet: the estimate still refuses a run beyond kMaxTraceSeconds, but says nothing else.
  TraceWatch(double dt, long total, bool quiet)
      : dt_(dt), quiet_(quiet), bar_(total, false, "steps") {}

  bool operator()(long done, long total, double seconds) {
    if (!estimated_ && (seconds >= kProbeSeconds || done == total)) {
      estimated_ = true;
      estimate_ = seconds * double(total) / double(done);
      if (estimate_ > kMaxTraceSeconds) return false;
      if (estimate_ > kAnnounceSeconds && !quiet_) {
        std::fprintf(stderr, "clothlab trace: %ld steps of %g s, about %s (%.3g ms/step)\n", total,
                     dt_, duration_words(estimate_).c_str(), 1e3 * seconds / double(done));
        bar_.enable();
      }
    }
    bar_.update(done);
    return true;
  }

  double estimate() const { return estimate_; }

 private:
  double dt_;
  bool quiet_;
  bool estimated_ = false;
  double estimate_ = 0.0;
  ProgressBar bar_;
};

// The step count of --duration at the solver's step, said and refused (exit 2) when it is 0 or
// beyond what a trace may take.
long step_count(const TraceArgs& args, const Scene& scene, double dt) {
  const long total = whole_steps(args.duration, dt);
  const char* why = nullptr;
  if (total < 0)
    why = "is more steps than a trace may take";
  else if (total == 0)
    why = "is shorter than one step";
  if (!why) return total;
  std::fprintf(stderr,
               "clothlab trace: --duration %g at solver.dt = %g s%s %s (%.3g steps; at most %.0e, "
               "at least 1): shorten the run or change solver.dt\n",
               args.duration, dt, scene.solver.dt_auto ? " (auto)" : "", why, args.duration / dt,
               kMaxTraceSteps);
  return -1;
}

// The scene's solver; solver.backend = "gpu" steps the cloth in a headless GL context of its
// own (`context`), and without one on the CPU, saying why.
std::unique_ptr<Solver> make_trace_solver(const Scene& scene, GlContextHandle& context) {
  std::string note;
  auto solver = make_headless_backend_solver(scene, context, note);
  if (!note.empty()) std::printf("clothlab trace: %s\n", note.c_str());
  return solver;
}

// The summary of a finished trace: time, steps, cost, method, threads, energy and the file; the
// iterative methods' work (PCG iterations or sweeps per substep) on a second line.
void print_summary(const TraceArgs& args, const Scene& scene, const Solver& solver,
                   const TraceRunResult& r) {
  const bool doubles = scene.solver.precision == Precision::f64;
  const double ms_per_step = r.steps > 0 ? 1e3 * r.step_seconds / r.steps : 0.0;
  char substeps[64] = "";
  if (solver.substeps() > 1)
    std::snprintf(substeps, sizeof substeps, " (%d substeps)", solver.substeps());
  std::printf(
      "trace: %.6g s simulated in %ld steps of %g s%s%s, %.4g ms/step (%s, %s, %s, %d thread(s), "
      "%s, %zu vertices), final energy %.6g J (kinetic %.4g, elastic %.4g, gravity %.6g); "
      "wrote %s (%ld of the steps)\n",
      r.simulated_time, r.steps, solver.dt(), scene.solver.dt_auto ? " (auto)" : "", substeps,
      ms_per_step, to_string(scene.solver.integrator), doubles ? "double" : "float",
      backend_name(solver), solver.threads(), openmp_wait_policy().c_str(), solver.vertex_count(),
      r.final_energy.total(), r.final_energy.kinetic, r.final_energy.elastic,
      r.final_energy.gravity, args.out.c_str(), r.written_steps);
  // Cloth through cloth at the end (sim/contact/intersections.hpp), and what triangle contact did
  // in its last pass when it is on.
  std::printf("contact: %ld crossing edge/triangle pairs at the end", solver.intersections());
  if (const auto c = solver.last_cloth_contact())
    std::printf(
        "; cloth contact in its last pass: %d candidate pairs, %d pushed apart, %d "
        "vertices rolled back, %d triangles in %d flat patches",
        c->candidates, c->contacts, c->rolled_back, c->flat_triangles, c->flat_patches);
  if (const auto c = solver.last_cloth_contact(); c && c->overflow)
    std::printf(" (a tangle beyond the pair bound: the substep was undone)");
  std::printf("\n");
  const SolveTotals& t = solver.solve_totals();
  if (t.iterations > 0) {
    std::printf("solver: %.3g iterations per substep (max %d)",
                double(t.iterations) / double(t.substeps), t.max_iterations);
    if (t.solves > 0) std::printf(" in %.3g linear solves", double(t.solves) / double(t.substeps));
    std::printf(", largest relative residual %.3g, %ld substeps stopped at the iteration cap\n",
                t.max_residual, t.unconverged);
  }
}

// The exit status of a run that did not finish: refused as too long (2, with the estimate) or
// diverged (1, with the replay command).
int unfinished(const TraceArgs& args, const Scene& scene, const Solver& solver,
               const TraceRunResult& r, long total, const TraceWatch& watch) {
  if (r.stopped) {
    std::fprintf(stderr,
                 "clothlab trace: %ld steps of %g s would take about %s here (%.3g ms/step over "
                 "the first %ld steps; at most %s): shorten --duration or raise solver.dt; no "
                 "trace written\n",
                 total, solver.dt(), duration_words(watch.estimate()).c_str(),
                 1e3 * r.step_seconds / double(r.steps), r.steps,
                 duration_words(kMaxTraceSeconds).c_str());
    return kBadInput;
  }
  std::fprintf(stderr, "clothlab trace: %s\n  no trace written; replay with: %s\n",
               r.divergence->message().c_str(),
               replay_command(args.scene, args.overrides, r.divergence->time).c_str());
  if (const auto advice = step_advice(scene); advice && advice->above())
    std::fprintf(stderr, "  %s\n", step_advice_line(*advice, scene.solver.integrator).c_str());
  return 1;
}

}  // namespace

int run_trace_command(const TraceArgs& args) {
  std::optional<Scene> loaded = load_scene_to_run("trace", args.scene, args.overrides, args.quiet);
  if (!loaded) return kBadInput;
  Scene& scene = *loaded;
  GlContextHandle context;
  const auto solver = make_trace_solver(scene, context);
  const TraceSpec spec = scene.trace ? *scene.trace : default_trace(scene);
  const bool doubles = scene.solver.precision == Precision::f64;
  const long total = step_count(args, scene, solver->dt());
  if (total < 0) return kBadInput;
  TraceWatch watch(solver->dt(), total, args.quiet);
  TraceRunResult r;
  try {
    r = run_trace(*solver, spec, scene.multi_cloth, doubles, total, args.out, std::ref(watch));
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "clothlab trace: %s\n", e.what());
    return 1;
  }
  if (r.stopped || r.divergence) return unfinished(args, scene, *solver, r, total, watch);
  if (!args.quiet) print_summary(args, scene, *solver, r);
  return 0;
}

}  // namespace clothlab::app
