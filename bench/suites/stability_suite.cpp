// `clothlab bench --suite stability`: the largest stable step of every integrator over a sweep of
// stiffness, mass and damping, next to the theoretical limit of the explicit methods, and stress
// scenes run at the display step 1/60 s.
#include <cmath>
#include <cstdio>
#include <ostream>

#include "bench/suites/lab_scenes.hpp"
#include "bench/suites/stability.hpp"
#include "bench/suites/suites.hpp"
#include "sim/solver.hpp"
#include "sim/stability/step_limit.hpp"

namespace clothlab::bench {

namespace {

constexpr double kCeiling = 1.0 / 30.0;  // s: the largest step the sweep tries

Spectrum spectrum_of(const Scene& scene) {
  return estimate_spectrum(build_model<double>(scene));
}

struct Stress {
  const char* name;
  const char* what;
};

constexpr Stress kStresses[] = {
    {"stiff", "stiffness 1e5 N/m (100x)"},
    {"heavy", "gravity x100"},
    {"hurricane", "wind 60 m/s, gusts 100 %"},
    {"push", "impulse 2 N*s up at the centre"},
};

// substeps: 0 = the automatic count for xpbd (sim/stability/step_limit.hpp), else that many.
Scene stress_scene(const Stress& stress, IntegratorKind kind, int resolution, int substeps) {
  SheetParams p;
  p.resolution = resolution;
  Scene s = hanging_sheet(p, kind, kFrame);
  const std::string name = stress.name;
  if (name == "stiff") s.springs.stiffness = 1e5;
  if (name == "heavy") s.forces.gravity = {0.0, -981.0, 0.0};
  if (name == "hurricane") {
    s.forces.wind.enabled = true;
    s.forces.wind.velocity = {0.0, 20.0, 56.6};  // 60 m/s, mostly across the sheet
    s.forces.wind.gust = 1.0;
    s.forces.wind.seed = 3;
  }
  s.solver.substeps = substeps;
  return s;
}

// Runs a stress scene; returns "stable" or how the divergence was caught.
std::string run_stress(const Stress& stress, const Scene& scene, double duration, bool& caught) {
  auto solver = make_solver(scene);
  if (std::string(stress.name) == "push") solver->apply_impulse({0.0, 0.0, 0.5}, 0.3, {0, 2, 0});
  const AdvanceResult r = solver->step(std::lround(duration / scene.solver.dt));
  caught = !r.ok();
  if (caught) {
    const Divergence& d = *r.divergence;
    char text[128];
    std::snprintf(text, sizeof text, "caught at step %ld (t = %.4g s), vertex (%d, %d)", d.step,
                  d.time, d.vertex.i, d.vertex.j);
    return text;
  }
  for (std::size_t i = 0; i < solver->vertex_count(); ++i)
    for (double c : solver->position(static_cast<int>(i)))
      if (!std::isfinite(c)) return "NON-FINITE (not caught)";
  return "stable";
}

// The largest stable step of every integrator on one sheet (stiffness, mass, damping), against
// the theory of step_limit.hpp, into `sweep`.
void add_sweep_rows(const SheetParams& p, const StabilityCheck& check, double tolerance,
                    Table& sweep, std::ostream* log) {
  const Spectrum sp = spectrum_of(hanging_sheet(p, IntegratorKind::symplectic_euler, 1e-3));
  const double symplectic_limit =
      stable_step_limit(IntegratorKind::symplectic_euler, sp.omega_max, sp.gamma_max);
  for (IntegratorKind kind : kAllIntegrators) {
    const Scene scene = hanging_sheet(p, kind, 1e-3);
    const double theory =
        is_explicit(kind) ? stable_step_limit(kind, sp.omega_max, sp.gamma_max) : INFINITY;
    const double guess =
        is_explicit(kind) ? (theory > 0 ? theory : 0.1 * symplectic_limit) : kCeiling;
    const LimitSearch found = largest_stable_dt(scene, guess, kCeiling, tolerance, check);
    const bool has_theory = is_explicit(kind) && theory > 0;
    sweep.add({num(p.stiffness), num(p.mass), num(p.damping), to_string(kind), num(sp.omega_max),
               num(sp.omega_gershgorin), num(sp.gamma_max),
               !is_explicit(kind) ? "inf"
               : theory > 0       ? num(theory)
                                  : "0 (none)",
               num(2.0 / sp.omega_max), found.at_ceiling ? ">=" + num(found.dt) : num(found.dt),
               has_theory ? num(found.dt / theory) : "-", std::to_string(found.runs)});
    if (log)
      *log << "stability: k " << p.stiffness << " m " << p.mass << " c " << p.damping << " "
           << to_string(kind) << ": " << sweep.rows.back()[9] << " s\n";
  }
}

// One stress scene for every integrator (xpbd in its automatic substeps and, for information,
// in one), into `stress`: large-step methods must stay stable, explicit ones must be caught.
void add_stress_rows(const Stress& st, int resolution, double duration, Table& stress,
                     std::ostream* log) {
  for (IntegratorKind kind : kAllIntegrators) {
    // XPBD is a small-steps method: it runs the frame step in its automatic substeps (and, for
    // information, in one substep, which a hurricane can tear apart: see docs/results.md,
    // "Stability").
    const bool xpbd = kind == IntegratorKind::xpbd;
    for (int substeps : xpbd ? std::vector<int>{0, 1} : std::vector<int>{1}) {
      bool caught = false;
      const Scene scene = stress_scene(st, kind, resolution, substeps);
      const std::string outcome = run_stress(st, scene, duration, caught);
      const bool informational = xpbd && substeps == 1;
      const bool expect_stable = !is_explicit(kind);
      const bool ok = expect_stable ? outcome == "stable" : caught;
      std::string label = to_string(kind);
      if (xpbd) {
        const int n = make_solver(scene)->substeps();
        label += " (" + std::to_string(n) + (n == 1 ? " substep)" : " substeps)");
      }
      stress.add({std::string(st.name) + " (" + st.what + ")", label,
                  informational ? "-" : (expect_stable ? "stable" : "caught"), outcome,
                  informational ? "info" : (ok ? "ok" : "FAIL")});
      if (log) *log << "stability: stress " << st.name << " " << label << ": " << outcome << "\n";
    }
  }
}

}  // namespace

std::vector<Table> stability_suite(const SuiteOptions& o) {
  const int resolution = o.quick ? 10 : 16;
  StabilityCheck check;
  check.duration = o.quick ? 0.25 : 0.5;
  const double tolerance = o.quick ? 0.03 : 0.01;
  const std::vector<double> stiffnesses =
      o.quick ? std::vector<double>{1000} : std::vector<double>{250, 1000, 4000};
  const std::vector<double> masses =
      o.quick ? std::vector<double>{0.2} : std::vector<double>{0.2, 0.8};
  const std::vector<double> dampings =
      o.quick ? std::vector<double>{0.0} : std::vector<double>{0.0, 0.05};

  Table sweep;
  sweep.title = "Largest stable dt: " + std::to_string(resolution) + "x" +
                std::to_string(resolution) + " hanging sheet, " + fixed(check.duration, 2) +
                " s from a disturbed start, bracket " + pct(tolerance) +
                " (theory: spectral radius <= 1 on the highest mode)";
  sweep.columns = {"stiffness (N/m)", "mass (kg)",         "damping (N*s/m)",
                   "integrator",      "omega_max (rad/s)", "Gershgorin bound (rad/s)",
                   "gamma (1/s)",     "theory dt (s)",     "2/omega (s)",
                   "measured dt (s)", "measured/theory",   "runs"};
  for (double k : stiffnesses)
    for (double mass : masses)
      for (double c : dampings)
        add_sweep_rows(SheetParams{resolution, 1.0, mass, k, c}, check, tolerance, sweep, o.log);

  Table stress;
  stress.name = "stress";
  const double duration = o.quick ? 0.5 : 2.0;
  const int stress_resolution = o.quick ? 16 : 32;
  stress.title = "Stress scenes at dt = 1/60 s for " + fixed(duration, 1) + " s (" +
                 std::to_string(stress_resolution) + "x" + std::to_string(stress_resolution) +
                 " sheet): large-step methods must stay stable, explicit ones must be caught by "
                 "the divergence monitor";
  stress.columns = {"scene", "integrator", "expected", "outcome", "verdict"};
  for (const Stress& st : kStresses)
    add_stress_rows(st, stress_resolution, duration, stress, o.log);
  sweep.note = quick_note(o.quick,
                          "stiffnesses 250 and 4000 N/m (1000 only), mass 0.8 kg, damping 0.05; "
                          "a 10x10 sheet instead of 16x16 over 0.25 s instead of 0.5 s, the "
                          "bracket at 3 % instead of 1 %; stress scenes on 16x16 for 0.5 s "
                          "instead of 32x32 for 2 s");
  return {sweep, stress};
}

}  // namespace clothlab::bench
