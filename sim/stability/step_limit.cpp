#include "sim/stability/step_limit.hpp"

#include <algorithm>
#include <cmath>
// GCC 12 reports a false "may be used uninitialized" inside its own AVX-512 intrinsics when it
// inlines Eigen's 3x3 eigenvalue solver; the warning is about the header, not this file's code.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <Eigen/Eigenvalues>

namespace clothlab {
namespace {

struct Oscillator {
  double w2, gamma;
  double accel(double x, double v) const { return -w2 * x - gamma * v; }
};

// One step of each explicit rule, as written in sim/integrators/, on the scalar oscillator. The
// state is (x, v, a): `a` is the acceleration velocity Verlet caches from the end of its previous
// step (evaluated there at the predicted velocity, so with damping it is not a(x, v)); the other
// methods ignore it.
void step_once(IntegratorKind kind, const Oscillator& o, double h, double& x, double& v,
               double& cached) {
  switch (kind) {
    case IntegratorKind::explicit_euler: {
      const double a = o.accel(x, v);
      x += h * v;
      v += h * a;
      return;
    }
    case IntegratorKind::symplectic_euler:
      v += h * o.accel(x, v);
      x += h * v;
      return;
    case IntegratorKind::seed_hack: {
      const double a = o.accel(x, v);
      x += (v + a * h) * h + 0.5 * a * h * h;
      v += a * h;
      return;
    }
    case IntegratorKind::verlet: {  // kick-drift-kick, end force at the predicted velocity
      const double kick = 0.5 * h * cached;
      v += kick;
      x += h * v;
      cached = o.accel(x, v + kick);
      v += 0.5 * h * cached;
      return;
    }
    case IntegratorKind::rk4: {
      const double k1x = v, k1v = o.accel(x, v);
      const double k2x = v + 0.5 * h * k1v, k2v = o.accel(x + 0.5 * h * k1x, k2x);
      const double k3x = v + 0.5 * h * k2v, k3v = o.accel(x + 0.5 * h * k2x, k3x);
      const double k4x = v + h * k3v, k4v = o.accel(x + h * k3x, k4x);
      x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
      v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
      return;
    }
    default:
      return;
  }
}

// Two significant digits, rounded down (5.0083e-4 -> 5.0e-4): a step people can read and type,
// at most 10 % below the value it comes from.
double round_down_2_digits(double x) {
  if (!(x > 0.0)) return x;
  // Divide by an exact power of ten (not multiply by an inexact 1e-5) so 50 x 1e-5 is 0.0005.
  const double exponent = 1.0 - std::floor(std::log10(x));
  const double scale = std::pow(10.0, std::abs(exponent));
  const double digits =
      exponent >= 0 ? std::floor(x * scale * (1.0 + 1e-12)) : std::floor(x / scale * (1.0 + 1e-12));
  return exponent >= 0 ? digits / scale : digits * scale;
}

}  // namespace

double amplification(IntegratorKind kind, double h, double omega, double gamma) {
  // In units of the fastest rate, so the matrix is well scaled (entries of order omega^2 would
  // put rounding of 1e-9 into the eigenvalues).
  const double rate = std::max(omega, gamma);
  if (rate <= 0.0) return 1.0;
  const Oscillator o{(omega / rate) * (omega / rate), gamma / rate};
  h *= rate;
  // The step is linear in (x, v, a): its matrix from the images of the unit vectors. Methods
  // without a cached acceleration map a to nothing; their matrix has a zero eigenvalue there.
  Eigen::Matrix3d step;
  for (int c = 0; c < 3; ++c) {
    double state[3] = {c == 0 ? 1.0 : 0.0, c == 1 ? 1.0 : 0.0, c == 2 ? 1.0 : 0.0};
    if (kind != IntegratorKind::verlet) state[2] = 0.0;
    step_once(kind, o, h, state[0], state[1], state[2]);
    if (kind != IntegratorKind::verlet) state[2] = 0.0;
    step.col(c) << state[0], state[1], state[2];
  }
  return step.eigenvalues().cwiseAbs().maxCoeff();
}

double stable_step_limit(IntegratorKind kind, double omega, double gamma) {
  if (!is_explicit(kind)) return INFINITY;
  const double rate = std::max(omega, gamma);
  if (rate <= 0.0) return INFINITY;
  if (kind == IntegratorKind::explicit_euler) {
    // Closed form: its eigenvalues are 1 + h lambda for the roots of lambda^2 + g lambda + w^2.
    // Underdamped: |1 + h lambda|^2 = 1 - h g + h^2 w^2 <= 1 needs h <= g / w^2 (0 without
    // damping: unstable at any step). Overdamped: h <= 2 / |lambda| for the larger root.
    if (gamma < 2.0 * omega) return gamma / (omega * omega);
    return 2.0 / (0.5 * (gamma + std::sqrt(gamma * gamma - 4.0 * omega * omega)));
  }
  // Stable steps form an interval (0, h*] for the others; find h* by bisection on [0, 4/rate]
  // (rk4's limit is 2 sqrt(2)/omega undamped, the others' 2/omega or less).
  constexpr double kTolerance = 1e-10;
  auto stable = [&](double h) { return amplification(kind, h, omega, gamma) <= 1.0 + kTolerance; };
  double hi = 4.0 / rate, lo = 1e-6 * hi;
  if (!stable(lo)) return 0.0;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo;
}

// s: the display rate's step, which the large-step methods take and xpbd's substeps divide.
constexpr double kDisplayStep = 1.0 / 60.0;

StepChoice choose_step(IntegratorKind kind, const Spectrum& spectrum) {
  StepChoice c;
  c.spectrum = spectrum;
  const double omega = spectrum.omega_max, gamma = spectrum.gamma_max;
  c.limit = stable_step_limit(IntegratorKind::symplectic_euler, omega, gamma);
  if (!std::isfinite(c.limit)) {  // no springs: any step is stable; take the display step
    c.dt = kDisplayStep;
    return c;
  }
  if (is_explicit(kind)) {
    double limit = stable_step_limit(kind, omega, gamma);
    if (limit <= 0.0) limit = 0.1 * c.limit;  // explicit Euler, undamped
    c.dt = std::min(kDisplayStep, round_down_2_digits(kAutoSafety * limit));
    return c;
  }
  switch (kind) {
    case IntegratorKind::xpbd:  // small steps: substeps by auto_substeps
    case IntegratorKind::vbd:
    case IntegratorKind::bdf2:
      // Vertex block descent is built for one display-rate step per frame (Chen et al. 2024);
      // BDF2 is second order, so it keeps its accuracy at that step too.
      c.dt = kDisplayStep;
      return c;
    default:  // implicit_euler, local_global: unconditionally stable; two steps per frame
      c.dt = kImplicitStep;
      return c;
  }
}

int auto_substeps(IntegratorKind kind, double dt, int longest_side) {
  if (kind != IntegratorKind::xpbd) return 1;
  const double per_frame =
      std::max<double>(kXpbdMinSubsteps, std::ceil(double(longest_side) / kXpbdSideVertices));
  // In double and clamped before the conversion: dt may be any positive number. A step written
  // with a few digits (0.0166667) is 1/60 s: 1e-4 of slack before rounding up, else it took 11.
  return static_cast<int>(std::clamp(std::ceil(dt / kDisplayStep * per_frame * (1.0 - 1e-4)), 1.0,
                                     double(kXpbdMaxSubsteps)));
}

}  // namespace clothlab

#pragma GCC diagnostic pop
