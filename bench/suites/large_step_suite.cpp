// `clothlab bench --suite largestep`: the large-step methods at the display step 1/60 s on the
// accuracy sheet (docs/design.md, "Accuracy benchmark scenes") at stiffness k0 = 1e3, 1e4 and
// 1e5, against a double-precision RK4 run of the same sheet, next to symplectic Euler at its
// own automatic step; one 1/60 s step of vbd on a 256 x 256 sheet against the explicit step
// there (issue 22's targets); and the linear solves' iteration counts from 32 x 32 to 256 x 256
// (issue 39's). docs/results.md "Large steps" has the measured tables.
#include <algorithm>
#include <cmath>
#include <ostream>

#include "bench/suites/lab_scenes.hpp"
#include "bench/suites/suites.hpp"
#include "sim/integrators/descent/chebyshev.hpp"
#include "sim/solver.hpp"

namespace clothlab::bench {

namespace {

// One configuration of a method: what the table calls it and how the scene is set.
struct LargeStepVariant {
  IntegratorKind kind;
  bool dt_auto = false;
  int substeps = 0;            // 0: automatic (solver.substeps = "auto")
  int iterations = 0;          // solver.iterations (xpbd, local_global, vbd)
  int newton = 0;              // solver.newton_iterations (implicit_euler, bdf2)
  bool by_vbd = false;         // bdf2: solver.bdf2_solver = "vbd"
  double cg_tolerance = 0.0;   // solver.cg_tolerance (0: automatic)
  double chebyshev_rho = 0.0;  // solver.chebyshev_rho (0: the method's default)
  std::string label() const {
    std::string s = to_string(kind);
    if (by_vbd) s += " by vbd";
    if (dt_auto) s += " auto";
    if (substeps > 1) s += " x" + std::to_string(substeps);
    if (iterations > 0) s += " it" + std::to_string(iterations);
    if (newton > 0) s += " newton" + std::to_string(newton);
    if (cg_tolerance > 0.0) s += " cg" + num(cg_tolerance);
    if (chebyshev_rho > 0.0) s += " rho" + num(chebyshev_rho);
    return s;
  }
};

// Each method at its defaults, and the settings around them that show what they cost.
std::vector<LargeStepVariant> variants(bool quick) {
  using K = IntegratorKind;
  if (quick) return {{K::symplectic_euler, true}, {K::implicit_euler}, {K::bdf2}, {K::vbd}};
  return {{K::symplectic_euler, true},
          {K::implicit_euler, false, 1, 0, 1},
          {K::implicit_euler},
          {K::implicit_euler, false, 1, 0, 0, false, 1e-6},
          {K::bdf2},
          {K::bdf2, false, 1, 0, 0, false, 1e-6},
          {K::bdf2, false, 1, 0, 0, true},
          {K::vbd, false, 1, 10},
          {K::vbd},
          {K::vbd, false, 1, 100},
          {K::xpbd, true},
          {K::xpbd, false, 10},
          {K::xpbd, false, 20},
          {K::local_global, false, 1, 0, 0, false, 0.0, kChebyshevOff},
          {K::local_global},
          {K::local_global, false, 1, 30}};
}

// Work-precision ladders (the stiffness sweep's curves): each method from its automatic step
// (explicit: its stable step; large-step: 1/60 s) halving, xpbd at 1/60 s with doubling substeps.
struct Ladder {
  IntegratorKind kind;
  bool explicit_step;  // start from the method's automatic step, else from 1/60 s
};

std::vector<Ladder> ladders() {
  using K = IntegratorKind;
  return {{K::symplectic_euler, true},
          {K::verlet, true},
          {K::rk4, true},
          {K::implicit_euler, false},
          {K::bdf2, false},
          {K::vbd, false},
          {K::xpbd, false},
          {K::local_global, false}};
}

struct Outcome {
  std::vector<Vec3d> positions;
  double cost = NAN;  // wall s per simulated s
  double dt = NAN;    // s, the step the solver took (resolved for dt = "auto")
  int substeps = 0;   // 0: automatic (solver.substeps = "auto")
  std::string failure;
};

Outcome run(const Scene& scene, double horizon) {
  Outcome o;
  auto solver = make_solver(scene);
  o.dt = solver->dt();
  o.substeps = solver->substeps();
  Stopwatch clock;
  const AdvanceResult a = solver->step(std::lround(horizon / solver->dt()));
  o.cost = clock.seconds() / horizon;
  if (!a.ok()) o.failure = a.divergence->message();
  o.positions.resize(solver->vertex_count());
  for (std::size_t i = 0; i < o.positions.size(); ++i)
    o.positions[i] = solver->position(static_cast<int>(i));
  return o;
}

double rms_distance(const std::vector<Vec3d>& a, const std::vector<Vec3d>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c) sum += (a[i][c] - b[i][c]) * (a[i][c] - b[i][c]);
  return std::sqrt(sum / double(a.size()));
}

Scene sheet(int resolution, double stiffness, const LargeStepVariant& v, int threads) {
  SheetParams p;
  p.resolution = resolution;
  p.stiffness = stiffness;
  Scene s = hanging_sheet(p, v.kind, kFrame);
  s.solver.dt_auto = v.dt_auto;
  s.solver.substeps = v.substeps;
  s.solver.iterations = v.iterations;
  s.solver.newton_iterations = v.newton;
  if (v.by_vbd) s.solver.bdf2_solver = StepSolver::vbd;
  s.solver.cg_tolerance = v.cg_tolerance;
  s.solver.chebyshev_rho = v.chebyshev_rho;
  s.solver.threads = threads;
  return s;
}

// Median wall time of one step over `steps` steps after `warmup` (ms).
double ms_per_step(const Scene& scene, int warmup, int steps) {
  auto solver = make_solver(scene);
  solver->step(warmup);
  std::vector<double> times;
  for (int k = 0; k < steps; ++k) {
    Stopwatch clock;
    solver->step(1);
    times.push_back(1e3 * clock.seconds());
  }
  return median(times);
}

Table frame_table(const SuiteOptions& o) {
  const int res = o.quick ? 32 : 256;
  Table t;
  t.name = "frame";
  t.title = "One frame (1/60 s) on the " + std::to_string(res) + "x" + std::to_string(res) +
            " sheet, k0 = 1e3, 2 threads, float";
  t.columns = {"method",          "dt (s)",       "ms per step",
               "steps per frame", "ms per frame", "x one explicit step"};
  const LargeStepVariant explicit_step{IntegratorKind::symplectic_euler, true};
  Scene se = sheet(res, 1e3, explicit_step, 2);
  se.solver.precision = Precision::f32;
  const double explicit_dt = make_solver(se)->dt();
  const double e_ms = ms_per_step(se, 5, o.quick ? 5 : 50);
  const double e_steps = std::ceil(kFrame / explicit_dt);
  using K = IntegratorKind;
  for (const LargeStepVariant& v :
       {LargeStepVariant{K::vbd}, LargeStepVariant{K::vbd, false, 1, 10}, LargeStepVariant{K::xpbd},
        LargeStepVariant{K::bdf2}}) {
    Scene sv = sheet(res, 1e3, v, 2);
    sv.solver.precision = Precision::f32;
    const double ms = ms_per_step(sv, 2, o.quick ? 3 : 5);
    t.add({v.label(), num(kFrame), fixed(ms, 3), "1", fixed(ms, 3), fixed(ms / e_ms, 1)});
    if (o.log) *o.log << "largestep: frame " << v.label() << " " << ms << " ms\n";
  }
  t.add({explicit_step.label(), num(explicit_dt), fixed(e_ms, 4), num(e_steps),
         fixed(e_ms * e_steps, 1), "1"});
  return t;
}

// PCG iterations a linear solve on the falling sheet (k0 = 1e3, 1/60 s, double): its linearised
// backward-Euler steps 5-8 (the first ones, from a flat sheet at rest, are nearly uncoupled),
// the same kind of system on every grid, with each preconditioner and tolerance. Issue 39's
// target is the multigrid's count within 1.5x from 32^2 to 256^2 (docs/solver.md, "Multigrid
// preconditioner"; tests/multigrid_test.cpp asserts the counts up to 128^2).
double solve_iterations(int side, LinearSolver ls, double tolerance, int threads) {
  Scene s = sheet(side, 1e3, {IntegratorKind::implicit_euler, false, 1, 0, 1}, threads);
  s.solver.linear_solver = ls;
  s.solver.cg_tolerance = tolerance;
  s.solver.cg_max_iterations = 10000;
  const auto solver = make_solver(s);
  solver->step(4);
  const long before = solver->solve_totals().iterations;
  solver->step(4);
  return double(solver->solve_totals().iterations - before) / 4.0;
}

Table solve_table(const SuiteOptions& o) {
  Table t;
  t.name = "solves";
  t.title =
      "PCG iterations a solve: the falling sheet's linearised steps 5-8 at 1/60 s, k0 = 1e3, "
      "double, 2 threads";
  t.columns = {"grid",
               "multigrid to 1e-2",
               "multigrid to 1e-6",
               "x the smallest grid's (1e-6)",
               "block Jacobi to 1e-2",
               "block Jacobi to 1e-6"};
  const std::vector<int> sides =
      o.quick ? std::vector<int>{16, 32} : std::vector<int>{32, 64, 128, 256};
  double first = 0.0;
  for (int side : sides) {
    double counts[4];
    int k = 0;
    for (LinearSolver ls : {LinearSolver::multigrid, LinearSolver::block_jacobi})
      for (double tol : {1e-2, 1e-6}) counts[k++] = solve_iterations(side, ls, tol, 2);
    if (first == 0.0) first = counts[1];
    t.add({std::to_string(side) + "x" + std::to_string(side), fixed(counts[0], 2),
           fixed(counts[1], 2), fixed(counts[1] / first, 2), fixed(counts[2], 2),
           fixed(counts[3], 2)});
    if (o.log) *o.log << "largestep: solves " << side << "^2 done\n";
  }
  return t;
}

struct LadderPoint {
  std::string label;
  double rms, cost;
};

// One method's ladder at stiffness k0 into `table` and `points`: rungs until the error is below
// 0.01 mm, the next rung would take more than `budget` wall seconds, or 6 rungs.
void run_step_ladder(const Ladder& l, double k0, int res, double horizon, double budget,
                     const Outcome& reference, int threads, Table& table,
                     std::vector<LadderPoint>& points, std::ostream* log) {
  LargeStepVariant v{l.kind, l.explicit_step};
  Scene base = sheet(res, k0, v, threads);
  const double start = make_solver(base)->dt();
  base.solver.dt_auto = false;
  double last_wall = 0.0;
  for (int rung = 0; rung < 6; ++rung) {
    if (rung > 0 && 2.0 * last_wall > budget) break;
    Scene s = base;
    const bool xpbd = l.kind == IntegratorKind::xpbd;
    s.solver.dt = xpbd ? kFrame : start / double(1 << rung);
    if (xpbd) s.solver.substeps = 10 << rung;
    const Outcome r = run(s, horizon);
    last_wall = r.cost * horizon;
    const double e = r.failure.empty() ? rms_distance(r.positions, reference.positions) : NAN;
    const std::string label = std::string(to_string(l.kind)) + " dt " + for_people(num(r.dt)) +
                              (xpbd ? " x" + std::to_string(r.substeps) : "");
    table.add({num(k0), to_string(l.kind), num(r.dt), std::to_string(r.substeps), num(e),
               num(r.cost), r.failure.empty() ? "ok" : "diverged: " + r.failure});
    if (log) *log << "largestep: ladder k0 " << k0 << " " << label << ": rms " << e << " m\n";
    if (!r.failure.empty()) continue;
    points.push_back({label, e, r.cost});
    if (e < 1e-5) break;
  }
}

}  // namespace

std::vector<Table> large_step_suite(const SuiteOptions& o) {
  const int res = o.quick ? 12 : 32;
  const double horizon = o.quick ? 0.1 : 0.5;
  const double reference_dt = o.quick ? 4e-5 : 1e-5;
  const std::vector<double> stiffnesses =
      o.quick ? std::vector<double>{1e3} : std::vector<double>{1e3, 1e4, 1e5};
  Table data;
  data.title = "Large steps: RMS distance at t = " + num(horizon) + " s from double RK4 (dt " +
               num(reference_dt) + " s), " + std::to_string(res) + "x" + std::to_string(res) +
               " sheet, double, " + std::to_string(o.threads) + " thread(s)";
  data.columns = {"k0 (N/m)", "method", "dt (s)", "substeps", "rms (m)", "cost (s/s)", "status"};
  Table ladder;
  ladder.name = "ladder";
  ladder.title =
      "Work-precision ladders: each method from its automatic step halving (xpbd: "
      "1/60 s, substeps doubling), same sheet and reference";
  ladder.columns = {"k0 (N/m)", "integrator", "dt (s)", "substeps",
                    "rms (m)",  "cost (s/s)", "status"};
  Table summary;
  summary.name = "summary";
  summary.title =
      "Cheapest run within each error level over every run below (1/60 s settings and the "
      "ladders; cost = wall s per simulated s), against symplectic Euler (SE) at its own step";
  summary.columns = {"k0 (N/m)",       "rms level (m)", "cheapest", "its rms (m)",
                     "its cost (s/s)", "SE cost (s/s)", "cost / SE"};
  for (double k0 : stiffnesses) {
    Scene rs = sheet(res, k0, {IntegratorKind::rk4}, o.threads);
    rs.solver.dt = reference_dt;
    const Outcome reference = run(rs, horizon);
    if (o.log) *o.log << "largestep: k0 " << k0 << " reference done\n";
    std::vector<LadderPoint> points;
    double explicit_cost = NAN;
    for (const LargeStepVariant& v : variants(o.quick)) {
      const Scene s = sheet(res, k0, v, o.threads);
      const Outcome r = run(s, horizon);
      const double e = r.failure.empty() ? rms_distance(r.positions, reference.positions) : NAN;
      data.add({num(k0), v.label(), num(r.dt), std::to_string(r.substeps), num(e), num(r.cost),
                r.failure.empty() ? "ok" : "diverged: " + r.failure});
      if (o.log) *o.log << "largestep: k0 " << k0 << " " << v.label() << ": rms " << e << " m\n";
      if (v.kind == IntegratorKind::symplectic_euler) {
        explicit_cost = r.cost;
      } else if (r.failure.empty()) {
        points.push_back({v.label(), e, r.cost});
      }
    }
    for (const Ladder& l : ladders())
      run_step_ladder(l, k0, res, horizon, o.quick ? 0.2 : 20.0, reference, o.threads, ladder,
                      points, o.log);
    for (double level : {0.06, 0.025, 0.01, 1e-3, 1e-4}) {
      const LadderPoint* best = nullptr;
      for (const LadderPoint& p : points)
        if (p.rms <= level && (!best || p.cost < best->cost)) best = &p;
      summary.add({num(k0), num(level), best ? best->label : "none", best ? num(best->rms) : "-",
                   best ? num(best->cost) : "-", num(explicit_cost),
                   best ? fixed(best->cost / explicit_cost, 3) : "-"});
    }
  }
  data.note = quick_note(o.quick,
                         "k0 = 1e4 and 1e5 (1e3 only), every method's other settings, xpbd and "
                         "local_global at 1/60 s (their ladders stay); a 12x12 sheet instead of "
                         "32x32, t = 0.1 s instead of 0.5 s, the reference at dt 4e-5 s instead "
                         "of 1e-5 s, each ladder stopped after 0.2 s of wall time instead of "
                         "20 s; the frame on 32x32 instead of 256x256; the solves on 16x16 and "
                         "32x32 instead of 32x32 to 256x256");
  return {data, ladder, summary, frame_table(o), solve_table(o)};
}

}  // namespace clothlab::bench
