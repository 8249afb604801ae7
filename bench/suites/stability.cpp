#include "bench/suites/stability.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sim/solver.hpp"

namespace clothlab::bench {

namespace {

double edge_length(const Scene& scene) {
  double edge = INFINITY;
  for (const ClothSpec& c : scene.cloths)
    for (int a = 0; a < 2; ++a)
      if (c.resolution[a] > 1) edge = std::min(edge, c.size[a] / (c.resolution[a] - 1));
  return std::isfinite(edge) ? edge : 1.0;
}

double gravity_scale(const Scene& scene) {
  const auto& g = scene.forces.gravity;
  const double g_norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  double scale = 0.0;
  for (const ClothSpec& c : scene.cloths) scale += c.mass * g_norm * std::max(c.size[0], c.size[1]);
  return std::max(scale, 1e-9);
}

StabilityOutcome check_solver(const Scene& scene, const StabilityCheck& check) {
  const auto owner = make_solver(scene);
  Solver& s = *owner;
  // The same disturbance for every step size and method: a fixed seed.
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double amplitude = check.perturbation * edge_length(scene);
  std::vector<Vec3d> x(s.vertex_count()), v(s.vertex_count());
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = s.position(static_cast<int>(i));
    v[i] = s.velocity(static_cast<int>(i));
    if (s.pinned(static_cast<int>(i))) continue;
    for (int a = 0; a < 3; ++a) x[i][a] += amplitude * unit(rng);
  }
  s.set_state(x, v);
  const double start = s.energy().total();
  const double allowed = start + check.energy_tolerance * gravity_scale(scene);
  const long total = std::max(1L, std::lround(check.duration / s.dt()));
  constexpr long kEnergyEvery = 8;  // steps between energy checks
  StabilityOutcome out;
  for (long done = 0; done < total;) {
    const long count = std::min(kEnergyEvery, total - done);
    const AdvanceResult r = s.step(count);
    done += r.steps;
    out.steps = done;
    if (!r.ok()) {
      out.reason = "diverged: " + r.divergence->message();
      return out;
    }
    const double e = s.energy().total();
    if (!(e <= allowed)) {
      char text[160];
      std::snprintf(text, sizeof text, "energy grew from %.4g J to %.4g J by t = %.4g s", start, e,
                    s.time());
      out.reason = text;
      return out;
    }
  }
  out.stable = true;
  return out;
}

}  // namespace

StabilityOutcome check_stability(const Scene& scene, double dt, const StabilityCheck& check) {
  Scene s = scene;
  s.solver.dt = dt;
  s.solver.dt_auto = false;
  // The sweep is over one integrator step: automatic substeps would grow with dt.
  if (s.solver.substeps == 0) s.solver.substeps = 1;
  return check_solver(s, check);
}

LimitSearch largest_stable_dt(const Scene& scene, double guess, double ceiling,
                              double relative_tolerance, const StabilityCheck& check) {
  LimitSearch out;
  auto stable = [&](double dt) {
    ++out.runs;
    return check_stability(scene, dt, check).stable;
  };
  // Below this step a method is called unstable at any step (explicit Euler without damping
  // grows at every step, slowly enough for tiny steps to pass): at most 50000 steps a run.
  const double floor = check.duration / 50000.0;
  double lo = 0.0, hi = 0.0;  // stable, unstable
  double dt = std::min(guess, ceiling);
  if (stable(dt)) {
    lo = dt;
    while (true) {  // walk up by 2x until unstable or the ceiling holds
      if (lo >= ceiling) {
        out.dt = ceiling;
        out.at_ceiling = true;
        return out;
      }
      const double up = std::min(2.0 * lo, ceiling);
      if (!stable(up)) {
        hi = up;
        break;
      }
      lo = up;
    }
  } else {
    hi = dt;
    while (true) {  // walk down by 4x until stable
      const double down = 0.25 * hi;
      if (down < floor) return out;
      if (stable(down)) {
        lo = down;
        break;
      }
      hi = down;
    }
  }
  while (hi / lo > 1.0 + relative_tolerance) {
    const double mid = std::sqrt(lo * hi);
    (stable(mid) ? lo : hi) = mid;
  }
  out.dt = lo;
  return out;
}

}  // namespace clothlab::bench
