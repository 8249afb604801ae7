// `clothlab bench --suite scaling`: the cost of a step from 32x32 to 512x512 on 1 and 2 threads,
// memory per vertex, parallel speed-up, and how far the step is from what this machine can do;
// then, per method at its automatic step, the largest grid that keeps real time at 60 Hz.
#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "bench/bench_scenes.hpp"
#include "bench/suites/machine_limits.hpp"
#include "bench/suites/step_timing.hpp"
#include "bench/suites/suites.hpp"
#include "sim/solver.hpp"

namespace clothlab::bench {

namespace {

std::size_t heap_in_use() {
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
}

// Work of one spring-step of the default step (symplectic Euler, float, damped springs; the
// band kernel evaluates every spring once and adds it to both ends): counted from
// sim/forces/grid_spring_forces.hpp, an FMA as 2 flops, sqrt and divide as 1 each.
constexpr double kFlopsPerVisit = 37.0;  // 19 for Hooke, 12 for the damping term, 6 adds
constexpr double kVisitsPerSpring = 1.0;
// Bytes per vertex and step that must come from memory when the arrays do not fit in cache:
// the force pass reads x, v and m (28 B) and writes f (12 B); the update reads f, v, x and
// 1/m (40 B) and writes v and x (24 B).
constexpr double kBytesPerVertex = 104.0;

Table machine_table(const MachineLimits& limit1, const MachineLimits& limit2) {
  Table machine;
  machine.name = "machine";
  machine.title = "This machine, measured by the same command";
  machine.columns = {"threads", "copy (GB/s)", "FMA peak (GFLOP/s)", "sqrt+div pairs (G/s)"};
  for (int t : {1, 2}) {
    const MachineLimits& l = t == 1 ? limit1 : limit2;
    machine.add({std::to_string(t), fixed(l.copy_bytes_per_s * 1e-9, 1),
                 fixed(l.flops_per_s * 1e-9, 1), fixed(l.sqrt_div_per_s * 1e-9, 2)});
  }
  return machine;
}

// One grid on 1 and 2 threads: ns per spring-step, heap per vertex, speed-up and the ratio to
// each bound of the machine.
void add_scaling_rows(Table& data, int res, double seconds, const MachineLimits& limit1,
                      const MachineLimits& limit2, std::ostream* log) {
  double one_thread = NAN;
  for (int threads : {1, 2}) {
    const std::size_t before = heap_in_use();
    const auto solver_owner = make_solver(sheet_scene(res, threads, false));
    Solver& solver = *solver_owner;
    const double bytes = double(heap_in_use() - before);
    const double per_step = seconds_per_step(solver, seconds);
    const double springs = double(solver.spring_count());
    const double vertices = double(solver.vertex_count());
    const double ns = 1e9 * per_step / springs;
    if (threads == 1) one_thread = ns;
    const MachineLimits& l = threads == 1 ? limit1 : limit2;
    const double by_flops = 1e9 * kFlopsPerVisit * kVisitsPerSpring / l.flops_per_s;
    const double by_sqrt = 1e9 * kVisitsPerSpring / l.sqrt_div_per_s;
    const double by_bytes = 1e9 * kBytesPerVertex * vertices / springs / l.copy_bytes_per_s;
    const double bound = std::max({by_flops, by_sqrt, by_bytes});
    const char* by = bound == by_sqrt ? "sqrt+div" : (bound == by_flops ? "flops" : "memory");
    data.add({std::to_string(res) + "x" + std::to_string(res), num(vertices), num(springs),
              std::to_string(threads), fixed(ns, 3), fixed(bytes / vertices, 0),
              threads == 1 ? "1.00" : fixed(one_thread / ns, 2), fixed(bound, 3),
              fixed(ns / bound, 2), by, fixed(ns / by_sqrt, 2), fixed(ns / by_bytes, 2)});
    if (log) *log << "scaling: " << res << "^2, " << threads << " thread(s): " << ns << " ns\n";
  }
}

// One method at its automatic step (dt = "auto") on growing grids until a simulated second
// takes more than a wall second: a row per grid into `realtime`, and the largest real-time grid
// (a power law between the last two grids) into `largest`.
void add_realtime_rows(IntegratorKind kind, const std::vector<int>& grids, double seconds,
                       Table& realtime, Table& largest, std::ostream* log) {
  double prev_res = NAN, prev_cost = NAN, found = NAN;
  for (int res : grids) {
    Scene scene = sheet_scene(res, 2, false);
    scene.solver.integrator = kind;
    scene.solver.dt_auto = true;
    const auto solver_owner = make_solver(scene);
    Solver& solver = *solver_owner;
    const double cost = seconds_per_step(solver, seconds) / solver.dt();
    realtime.add({to_string(kind), std::to_string(res) + "x" + std::to_string(res),
                  num(solver.dt()), std::to_string(solver.substeps()), fixed(cost, 3)});
    if (log)
      *log << "scaling: real time " << to_string(kind) << " " << res << "^2: " << cost << "\n";
    if (cost > 1.0) {
      if (std::isfinite(prev_cost))  // cost ~ res^p between the two grids
        found = prev_res *
                std::pow(res / prev_res, std::log(1.0 / prev_cost) / std::log(cost / prev_cost));
      break;
    }
    prev_res = res;
    prev_cost = cost;
  }
  const bool beyond = std::isnan(found) && std::isfinite(prev_cost);
  largest.add({to_string(kind),
               std::isfinite(found) ? std::to_string(int(found)) + "x" + std::to_string(int(found))
               : beyond             ? "> " + std::to_string(grids.back())
                                    : "< " + std::to_string(grids.front()),
               std::isfinite(found) ? num(std::floor(found) * std::floor(found)) : "-"});
}

}  // namespace

std::vector<Table> scaling_suite(const SuiteOptions& o) {
  const std::vector<int> grids =
      o.quick ? std::vector<int>{32, 64} : std::vector<int>{32, 64, 128, 256, 512};
  const double seconds = o.quick ? 0.05 : 0.4;  // per measurement

  if (o.log) *o.log << "scaling: measuring the machine's limits\n";
  const MachineLimits limit1 = measure_machine_limits(1), limit2 = measure_machine_limits(2);
  Table data;
  data.title = "Scaling: symplectic Euler step, float, damped springs + gravity (bench scene)";
  data.columns = {"grid",           "vertices",          "springs",   "threads",
                  "ns/spring-step", "memory (B/vertex)", "speed-up",  "limit ns/spring-step",
                  "measured/limit", "limit by",          "/sqrt+div", "/memory"};
  for (int res : grids) add_scaling_rows(data, res, seconds, limit1, limit2, o.log);

  // Real time at 60 Hz: one simulated second may take at most one wall second (the frame's
  // drawing comes on top). Every method but explicit Euler and seed_hack, whose steps no one
  // would run a cloth at.
  const std::vector<int> rt_grids =
      o.quick ? std::vector<int>{16, 32} : std::vector<int>{32, 64, 96, 128, 192, 256};
  Table realtime;
  realtime.name = "realtime";
  realtime.title = "Real time: wall seconds per simulated second at dt = \"auto\", 2 threads";
  realtime.columns = {"integrator", "grid", "dt (s)", "substeps", "wall/simulated"};
  Table largest;
  largest.name = "largest";
  largest.title = "Largest grid in real time (wall/simulated <= 1), interpolated as a power law";
  largest.columns = {"integrator", "largest grid", "vertices"};
  for (IntegratorKind kind : kAllIntegrators) {
    if (kind == IntegratorKind::explicit_euler || kind == IntegratorKind::seed_hack) continue;
    add_realtime_rows(kind, rt_grids, 0.5 * seconds, realtime, largest, o.log);
  }
  data.note = quick_note(o.quick,
                         "grids 128, 256 and 512 (32 and 64 only), real time on 16 and 32 "
                         "instead of 32 to 256; 0.05 s per measurement instead of 0.4 s");
  return {data, machine_table(limit1, limit2), realtime, largest};
}

}  // namespace clothlab::bench
