#include "tune/ladder.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "sim/stability/step_limit.hpp"

namespace clothlab::tune {

namespace {

std::string frame_text() {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", kFrame);
  return text;
}

// The --set lines of `integrator` in `precision` at `substeps` a frame (0: "auto").
std::vector<std::string> base(const char* integrator, const char* precision, int substeps) {
  return {std::string("solver.integrator=") + integrator,
          std::string("solver.precision=") + precision, "solver.dt=" + frame_text(),
          "solver.substeps=" + (substeps > 0 ? std::to_string(substeps) : std::string("auto"))};
}

// The limit of an explicit method, or a tenth of symplectic Euler's where the method has none
// (as the accuracy suite does).
double limit_of(IntegratorKind kind, const Spectrum& sp) {
  const double limit = stable_step_limit(kind, sp.omega_max, sp.gamma_max);
  if (limit > 0.0) return limit;
  return 0.1 * stable_step_limit(IntegratorKind::symplectic_euler, sp.omega_max, sp.gamma_max);
}

Setting explicit_setting(const char* integrator, const char* precision, int substeps) {
  return {
      "explicit",
      std::string(integrator) + " (" + precision + "), " + std::to_string(substeps) + " substeps",
      base(integrator, precision, substeps)};
}

void add_explicit(const Spectrum& sp, std::vector<Setting>& out) {
  const int se = substeps_for(0.9 * limit_of(IntegratorKind::symplectic_euler, sp));
  out.push_back(explicit_setting("symplectic_euler", "float", se));
  out.push_back(explicit_setting("symplectic_euler", "float", 2 * se));
  out.push_back(explicit_setting("symplectic_euler", "double", se));
  out.push_back(explicit_setting("verlet", "float",
                                 substeps_for(0.9 * limit_of(IntegratorKind::verlet, sp))));
  out.push_back(
      explicit_setting("rk4", "float", substeps_for(0.9 * limit_of(IntegratorKind::rk4, sp))));
}

Setting with_iterations(const char* family, const char* integrator, int substeps, int iterations) {
  Setting s{family,
            std::string(integrator) + ", " +
                (substeps > 0 ? std::to_string(substeps) : std::string("auto")) + " substeps x " +
                std::to_string(iterations) + " iterations",
            base(integrator, "float", substeps)};
  s.overrides.push_back("solver.iterations=" + std::to_string(iterations));
  return s;
}

}  // namespace

int substeps_for(double step) {
  if (!(step > 0.0)) return 1;
  return std::max(1, int(std::ceil(kFrame / step * (1.0 - 1e-12))));
}

int reference_substeps(const Spectrum& spectrum, double fraction, bool halved) {
  const int n = substeps_for(fraction * limit_of(IntegratorKind::rk4, spectrum));
  return halved ? 2 * n : n;
}

Setting reference_setting(const Spectrum& spectrum, double fraction, bool halved) {
  const int n = reference_substeps(spectrum, fraction, halved);
  return {"reference", std::string("rk4 (double), ") + std::to_string(n) + " substeps",
          base("rk4", "double", n)};
}

std::vector<Setting> ladder(const Spectrum& spectrum) {
  std::vector<Setting> out;
  add_explicit(spectrum, out);
  for (int n : {1, 2, 4})
    out.push_back({"implicit", "implicit_euler, " + std::to_string(n) + " substeps",
                   base("implicit_euler", "float", n)});
  for (int n : {1, 2})
    out.push_back(
        {"implicit", "bdf2, " + std::to_string(n) + " substeps", base("bdf2", "float", n)});
  for (int n : {0, 5, 10, 20, 40, 80}) out.push_back(with_iterations("constraints", "xpbd", n, 1));
  for (int n : {10, 20}) out.push_back(with_iterations("constraints", "xpbd", n, 2));
  for (int it : {10, 30, 100}) out.push_back(with_iterations("descent", "vbd", 1, it));
  for (int it : {10, 30}) out.push_back(with_iterations("descent", "local_global", 1, it));
  return out;
}

}  // namespace clothlab::tune
