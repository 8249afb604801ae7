// `clothlab bench --suite accuracy`: run time against error. Every integrator runs a ladder of
// steps on the canonical scenes; its positions at fixed horizons are compared with a reference
// (double-precision RK4 at a small step, whose own convergence is checked by halving that step).
// docs/design.md, "Accuracy benchmark scenes", sets the scenes and the rules.
#include <algorithm>
#include <cmath>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "bench/suites/lab_scenes.hpp"
#include "bench/suites/suites.hpp"
#include "sim/solver.hpp"
#include "sim/stability/step_limit.hpp"

namespace clothlab::bench {

namespace {

using Positions = std::vector<Vec3d>;

struct Run {
  std::vector<Positions> at;  // positions at each horizon reached
  double wall = 0.0;          // s of wall time for the whole run
  double iterations = 0.0;    // mean solver iterations per substep
  std::string failure;        // divergence message, empty when the run finished
};

Run run_to_horizons(const Scene& scene, const std::vector<double>& horizons) {
  Run r;
  auto solver = make_solver(scene);
  Stopwatch clock;
  for (double h : horizons) {
    const long target = std::lround(h / solver->dt());
    const AdvanceResult a = solver->step(target - solver->step_count());
    if (!a.ok()) {
      r.failure = a.divergence->message();
      break;
    }
    Positions p(solver->vertex_count());
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = solver->position(static_cast<int>(i));
    r.at.push_back(std::move(p));
  }
  r.wall = clock.seconds();
  const SolveTotals& t = solver->solve_totals();
  r.iterations = t.substeps ? double(t.iterations) / double(t.substeps) : 0.0;
  return r;
}

struct Error {
  double rms = NAN, max = NAN;
};

Error difference(const Positions& a, const Positions& b) {
  Error e{0.0, 0.0};
  for (std::size_t i = 0; i < a.size(); ++i) {
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c) d2 += (a[i][c] - b[i][c]) * (a[i][c] - b[i][c]);
    e.rms += d2;
    e.max = std::max(e.max, std::sqrt(d2));
  }
  e.rms = std::sqrt(e.rms / double(a.size()));
  return e;
}

struct LabScene {
  std::string name;
  std::function<Scene(IntegratorKind, double)> make;
};

struct Method {
  IntegratorKind kind;
  Precision precision;
  std::string label() const {
    return std::string(to_string(kind)) + (precision == Precision::f32 ? " (float)" : "");
  }
};

// The ladder starts at the largest step worth trying (the explicit methods' stability limit, the
// display step for the large-step ones), rounded down so that it divides the first horizon.
double ladder_start(const Method& m, const Spectrum& sp, double first_horizon) {
  double dt = 1.0 / 60.0;
  if (is_explicit(m.kind)) {
    double limit = stable_step_limit(m.kind, sp.omega_max, sp.gamma_max);
    if (limit <= 0.0)
      limit = 0.1 * stable_step_limit(IntegratorKind::symplectic_euler, sp.omega_max, sp.gamma_max);
    dt = std::min(dt, 0.95 * limit);
  }
  return first_horizon / std::ceil(first_horizon / dt);
}

// What every part of the suite shares: the horizons, the reference step, the wall-time budget of
// a ladder's next rung, the thread count and the progress log.
struct Settings {
  std::vector<double> horizons;
  double reference_dt = 1e-5;
  double budget = 30.0;  // s of wall time the next ladder run may take
  int threads = 1;
  std::ostream* log = nullptr;
};

constexpr double kFinest = 1e-5;  // m: a ladder stops once its error is below
constexpr double kLevels[] = {1e-2, 1e-3, 1e-4};

// One finished ladder rung at the last horizon.
struct Point {
  std::string method;
  double dt, cost, rms;
};

std::vector<LabScene> accuracy_scenes(bool quick) {
  std::vector<LabScene> scenes;
  SheetParams sheet;
  if (quick) sheet.resolution = 12;
  scenes.push_back({"hanging_sheet",
                    [sheet](IntegratorKind k, double dt) { return hanging_sheet(sheet, k, dt); }});
  if (!quick) scenes.push_back({"steady_flag", steady_flag});
  scenes.push_back({"single_spring", single_spring});
  return scenes;
}

Table data_table(int threads) {
  Table data;
  data.title = "Accuracy: error against a double-precision RK4 reference, " +
               std::to_string(threads) + " solver thread(s)";
  data.columns = {"scene",           "integrator",    "precision",     "dt (s)",
                  "horizon (s)",     "rms error (m)", "max error (m)", "wall per simulated s (s)",
                  "iterations/step", "status"};
  return data;
}

Table reference_table() {
  Table reference;
  reference.name = "reference";
  reference.title = "References: RK4 in double; self-convergence = change when its dt is halved";
  reference.columns = {"scene", "dt (s)", "horizon (s)", "self-convergence rms (m)",
                       "self-convergence max (m)"};
  return reference;
}

Table summary_table() {
  Table summary;
  summary.name = "summary";
  summary.title =
      "Fastest integrator per error level (rms at the last horizon; cost = wall s per "
      "simulated s), against symplectic Euler (SE)";
  summary.columns = {"scene",      "horizon (s)",    "rms level (m)", "fastest",
                     "its dt (s)", "its cost (s/s)", "SE cost (s/s)", "speed-up vs SE"};
  return summary;
}

// The scene's reference run, its self-convergence (against half its step) per horizon into
// `reference`; returns the run, and the self-convergence at the last horizon in `last_self`.
Run reference_run(const LabScene& ls, const Settings& st, Table& reference, double& last_self) {
  const Run ref = run_to_horizons(ls.make(IntegratorKind::rk4, st.reference_dt), st.horizons);
  const Run half =
      run_to_horizons(ls.make(IntegratorKind::rk4, 0.5 * st.reference_dt), st.horizons);
  for (std::size_t h = 0; h < st.horizons.size(); ++h) {
    const Error e = difference(ref.at[h], half.at[h]);
    last_self = e.rms;
    reference.add({ls.name, num(st.reference_dt), num(st.horizons[h]), num(e.rms), num(e.max)});
  }
  if (st.log) *st.log << "accuracy: " << ls.name << " reference done (" << ref.wall << " s)\n";
  return ref;
}

// One method's ladder of halving steps on one scene: a row per rung and horizon into `data`, a
// point per finished rung into `points`; stops when the error is below kFinest or the next rung
// would exceed the budget.
void run_ladder(const LabScene& ls, const Method& m, const Spectrum& spectrum, const Run& ref,
                const Settings& st, Table& data, std::vector<Point>& points) {
  Scene base = ls.make(m.kind, 1e-3);
  base.solver.precision = m.precision;
  base.solver.threads = st.threads;
  const std::vector<double>& horizons = st.horizons;
  double dt = ladder_start(m, spectrum, horizons.front());
  double last_wall = 0.0;
  for (int rung = 0; rung < 14 && dt >= 1e-7; ++rung, dt *= 0.5) {
    if (rung > 0 && 2.0 * last_wall > st.budget) break;
    Scene s = base;
    s.solver.dt = dt;
    const Run r = run_to_horizons(s, horizons);
    last_wall = r.wall;
    const double simulated = horizons[r.at.size() ? r.at.size() - 1 : 0];
    const double cost = r.at.empty() ? NAN : r.wall / simulated;
    for (std::size_t h = 0; h < horizons.size(); ++h) {
      const bool reached = h < r.at.size();
      const Error e = reached ? difference(r.at[h], ref.at[h]) : Error{};
      data.add({ls.name, to_string(m.kind), m.precision == Precision::f32 ? "float" : "double",
                num(dt), num(horizons[h]), num(e.rms), num(e.max), num(cost), num(r.iterations),
                reached ? "ok" : "diverged: " + r.failure});
    }
    if (!r.failure.empty()) continue;
    const double rms = difference(r.at.back(), ref.at.back()).rms;
    points.push_back({m.label(), dt, cost, rms});
    if (st.log)
      *st.log << "accuracy: " << ls.name << " " << m.label() << " dt " << dt << ": rms " << rms
              << " m, " << cost << " s/s\n";
    if (rms < kFinest) break;
  }
}

// The fastest point within each error level, against symplectic Euler's fastest there; a level
// the reference itself does not resolve (self-convergence above a tenth of it) says so.
void add_summary_rows(const std::string& scene, const std::vector<Point>& points, double last_self,
                      double horizon, Table& summary) {
  for (double level : kLevels) {
    auto best_of = [&](const std::string& only) {
      const Point* best = nullptr;
      for (const Point& p : points)
        if (p.rms <= level && (only.empty() || p.method == only) && (!best || p.cost < best->cost))
          best = &p;
      return best;
    };
    const Point* best = best_of("");
    const Point* se = best_of("symplectic_euler");
    if (!(last_self < 0.1 * level)) {
      summary.add({scene, num(horizon), num(level),
                   "reference not converged (" + sci(last_self) + " m)", "-", "-", "-", "-"});
      continue;
    }
    summary.add({scene, num(horizon), num(level), best ? best->method : "none reached",
                 best ? num(best->dt) : "-", best ? num(best->cost) : "-",
                 se ? num(se->cost) : "not reached",
                 best && se ? num(se->cost / best->cost) : "-"});
  }
}

}  // namespace

std::vector<Table> accuracy_suite(const SuiteOptions& o) {
  Settings st;
  st.horizons = o.quick ? std::vector<double>{0.1, 0.25} : std::vector<double>{0.25, 0.5, 1.0};
  st.reference_dt = o.quick ? 2e-5 : 1e-5;
  st.budget = o.quick ? 0.5 : 30.0;
  st.threads = o.threads;
  st.log = o.log;
  std::vector<Method> methods;
  for (IntegratorKind k : kAllIntegrators) methods.push_back({k, Precision::f64});
  methods.push_back({IntegratorKind::symplectic_euler, Precision::f32});

  Table data = data_table(o.threads), reference = reference_table(), summary = summary_table();
  for (const LabScene& ls : accuracy_scenes(o.quick)) {
    double last_self = NAN;
    const Run ref = reference_run(ls, st, reference, last_self);
    std::vector<Point> points;  // at the last horizon
    // The scene's frequencies (the same for every method and precision) set the explicit ladders.
    const Spectrum spectrum =
        estimate_spectrum(build_model<double>(ls.make(IntegratorKind::rk4, 1e-3)));
    for (const Method& m : methods) run_ladder(ls, m, spectrum, ref, st, data, points);
    add_summary_rows(ls.name, points, last_self, st.horizons.back(), summary);
  }
  data.note = quick_note(o.quick,
                         "the steady flag scene and the 0.5 and 1 s horizons (0.1 and 0.25 s "
                         "instead); a 12x12 sheet instead of 32x32, the reference at dt 2e-5 s "
                         "instead of 1e-5 s, each ladder stopped after 0.5 s of wall time "
                         "instead of 30 s");
  return {data, summary, reference};
}

}  // namespace clothlab::bench
