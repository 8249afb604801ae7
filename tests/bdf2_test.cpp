// BDF2 (sim/integrators/newton/bdf2.cpp): second order on the single spring with either step
// solver, and its numerical damping over one period equal to the closed-form amplification factor
// of its principal root. large_step_test.cpp runs the shared large-step checks for it too.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <memory>

#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

using testing::kGravity, testing::kSpringAmplitude, testing::kSpringMass;
using testing::kSpringOmega, testing::kSpringRest, testing::kSpringStiffness;
using testing::spring_exact_y;

// The single spring released at its rest length: y(t) = -L - A (1 - cos(w t)).
Scene spring(double dt, StepSolver solver) {
  Scene scene =
      testing::single_spring(kSpringMass, kSpringStiffness, kSpringRest, IntegratorKind::bdf2, dt);
  scene.solver.bdf2_solver = solver;
  scene.solver.iterations = 50;        // vbd: converged
  scene.solver.newton_iterations = 2;  // newton: the force is linear, one iteration solves it
  scene.solver.cg_tolerance = 1e-14;
  return scene;
}

double bdf2_error_over_half_second(long steps, StepSolver solver) {
  std::unique_ptr<Solver> s = make_solver(spring(0.5 / double(steps), solver));
  double worst = 0.0;
  for (long k = 0; k < steps; ++k) {
    EXPECT_TRUE(s->step(1).ok());
    worst = std::max(worst, std::abs(s->position(1)[1] - spring_exact_y(s->time())));
  }
  return worst;
}

class Bdf2Order : public ::testing::TestWithParam<StepSolver> {};

TEST_P(Bdf2Order, SingleSpringIsSecondOrder) {
  const StepSolver solver = GetParam();
  const double e1 = bdf2_error_over_half_second(250, solver);
  const double e2 = bdf2_error_over_half_second(500, solver);
  const double e3 = bdf2_error_over_half_second(1000, solver);
  std::printf("[ measured ] bdf2 errors %.4g %.4g %.4g, orders %.4f %.4f\n", e1, e2, e3,
              std::log2(e1 / e2), std::log2(e2 / e3));
  EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.2) << "errors " << e1 << " and " << e2;
  EXPECT_NEAR(std::log2(e2 / e3), 2.0, 0.2) << "errors " << e2 << " and " << e3;
}

INSTANTIATE_TEST_SUITE_P(Bdf2, Bdf2Order, ::testing::Values(StepSolver::newton, StepSolver::vbd),
                         [](const auto& p) {
                           return std::string(p.param == StepSolver::vbd ? "vbd" : "newton");
                         });

// Oscillation energy about the equilibrium y = -L - A: 1/2 m v^2 + 1/2 k (y + L + A)^2.
double oscillation_energy(const Solver& s) {
  const double y = s.position(1)[1], v = s.velocity(1)[1];
  return 0.5 * kSpringMass * v * v +
         0.5 * kSpringStiffness * std::pow(y + kSpringRest + kSpringAmplitude, 2);
}

// The spring's motion about its equilibrium is the linear oscillator, on which BDF2 multiplies
// the energy of its principal mode by |r|^2 per step, r the larger root of
// (3/2 - i h w) r^2 - 2 r + 1/2 = 0 (the energy norm makes the oscillator's eigenvectors
// orthogonal, so the energy of that mode alone decays exactly so). After one period the
// parasitic root (|r| near 1/3) and the backward-Euler start are gone; over the next period the
// energy falls by |r|^(2N), N steps per period, within 1 % of the decay.
TEST(Bdf2, EnergyDecayOverOnePeriodMatchesItsAmplificationFactor) {
  constexpr int kSteps = 20;  // per period: h w = 0.31
  const double period = 2.0 * M_PI / kSpringOmega, h = period / kSteps;
  const std::complex<double> z(0.0, h * kSpringOmega);
  const std::complex<double> a = 1.5 - z, disc = std::sqrt(4.0 - 2.0 * a);
  const double r = std::max(std::abs((2.0 + disc) / (2.0 * a)), std::abs((2.0 - disc) / (2.0 * a)));
  const double expected = std::pow(r, 2 * kSteps);
  std::unique_ptr<Solver> s = make_solver(spring(h, StepSolver::newton));
  ASSERT_TRUE(s->step(kSteps).ok());
  const double e1 = oscillation_energy(*s);
  ASSERT_TRUE(s->step(kSteps).ok());
  const double measured = oscillation_energy(*s) / e1;
  // Backward Euler over the same period: (1 + (h w)^2)^-N, far more damping.
  const double backward_euler = std::pow(1.0 + std::pow(h * kSpringOmega, 2), -kSteps);
  std::printf("[ measured ] energy over one period: %.6f (closed form %.6f; backward Euler %.4f)\n",
              measured, expected, backward_euler);
  EXPECT_NEAR(1.0 - measured, 1.0 - expected, 0.01 * (1.0 - expected));
  EXPECT_LT(1.0 - measured, 0.1 * (1.0 - backward_euler));
}

}  // namespace
}  // namespace clothlab
