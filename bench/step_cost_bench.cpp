// How many nanoseconds does one spring cost per symplectic Euler step, by grid size and thread
// count? (Issue: foundation, "Numbers to put in the closing note".) A step here is the whole
// step the solver takes: force pass, integration and the divergence check.
//
//   build/release/bench/step_cost_bench [--benchmark_out=step_cost.csv --benchmark_out_format=csv]
//
// Counters: per_spring_step in seconds (lower is better) and springs. The "physics" argument
// selects springs only (0: Hooke + along-spring damping + gravity) or the default scene's full set
// (1: also drag and gusty wind on the surface normals); "kernel" the spring kernel (0: row sweep,
// the default; 1: neighbour list, the general gather).
#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>

#include "bench/bench_scenes.hpp"
#include "sim/core/passive_openmp.hpp"
#include "sim/solver.hpp"

namespace clothlab {
namespace {

// Steps the solver once per benchmark iteration; records and returns its spring count.
double time_steps(benchmark::State& state, Solver& solver) {
  for (auto _ : state) {
    if (!solver.step(1).ok()) {
      state.SkipWithError("diverged");
      break;
    }
  }
  const double springs = static_cast<double>(solver.spring_count());
  state.counters["springs"] = springs;
  return springs;
}

void BM_SymplecticEulerStep(benchmark::State& state) {
  const int res = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const auto kernel = state.range(3) == 0 ? SpringKernel::row_sweep : SpringKernel::neighbour_list;
  const auto solver_owner =
      make_solver(bench::sheet_scene(res, threads, state.range(2) != 0), kernel);
  Solver& solver = *solver_owner;
  solver.step(20);  // warm caches and the thread pool
  const double springs = time_steps(state, solver);
  // Seconds per spring-step (printed with an SI prefix: "2.5n" is 2.5 ns).
  state.counters["per_spring_step"] =
      benchmark::Counter(springs * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Springs only, both kernels; then the default scene's full physics with the default kernel.
BENCHMARK(BM_SymplecticEulerStep)
    ->ArgNames({"res", "threads", "physics", "kernel"})
    ->ArgsProduct({{64, 128, 256}, {1, 2}, {0}, {0, 1}})
    ->ArgsProduct({{64, 128, 256}, {1, 2}, {1}, {0}})
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(0.5);

// One xpbd substep of one sweep (issue 36: "one sweep within 2x of the explicit force pass per
// spring"): the same sheet at dt = 1/60 s in 20 substeps, per spring and sweep, on the solver's
// default path (the grid path on this sheet; kernel 1: the neighbour-list path).
void BM_XpbdSweep(benchmark::State& state) {
  const int res = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const auto kernel = state.range(2) == 0 ? SpringKernel::row_sweep : SpringKernel::neighbour_list;
  constexpr int kSubsteps = 20;
  Scene scene = bench::sheet_scene(res, threads, false);
  scene.solver.integrator = IntegratorKind::xpbd;
  scene.solver.dt = 1.0 / 60.0;
  scene.solver.substeps = kSubsteps;
  scene.solver.iterations = 1;
  scene.solver.tethers = false;  // the sweep alone
  const auto solver_owner = make_solver(scene, kernel);
  Solver& solver = *solver_owner;
  solver.step(2);
  const double springs = time_steps(state, solver);
  state.counters["per_spring_sweep"] =
      benchmark::Counter(springs * kSubsteps * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_XpbdSweep)
    ->ArgNames({"res", "threads", "kernel"})
    ->ArgsProduct({{64, 128, 256}, {1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.5);

// Foreign load spoils 2-thread numbers (docs/design.md, performance notes): record it with the run.
void add_load_context() {
  std::ifstream in("/proc/loadavg");
  std::string one_minute;
  in >> one_minute;
  benchmark::AddCustomContext("loadavg_1min_before_run", one_minute);
}

}  // namespace
}  // namespace clothlab

int main(int argc, char** argv) {
  clothlab::prefer_passive_openmp(argv);
  benchmark::Initialize(&argc, argv);
  clothlab::add_load_context();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
