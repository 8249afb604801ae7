// The single spring under gravity (two vertices, the top one pinned): the closed form is
//   y(t) = -L - A (1 - cos(w t)),  A = m g / k,  w = sqrt(k / m),  T = 2 pi / w,
// for a vertex released at rest at the spring's rest length. Checks period, amplitude,
// equilibrium stretch, energy behaviour and the measured order of every integrator.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

using testing::kGravity, testing::kSpringAmplitude, testing::kSpringMass;
using testing::kSpringOmega, testing::kSpringRest, testing::kSpringStiffness;
using testing::spring_exact_y;
const double kPeriod = 2.0 * std::numbers::pi / kSpringOmega;

struct Trajectory {
  std::vector<double> t, y, energy;
};

Trajectory simulate(IntegratorKind kind, double dt, long steps, bool with_energy = false) {
  const auto s_owner = testing::solver<double>(
      testing::single_spring(kSpringMass, kSpringStiffness, kSpringRest, kind, dt));
  Solver& s = *s_owner;
  Trajectory r;
  for (long k = 0; k <= steps; ++k) {
    if (k > 0) {
      EXPECT_TRUE(s.step(1).ok());
    }
    r.t.push_back(s.time());
    r.y.push_back(s.position(1)[1]);
    if (with_energy) r.energy.push_back(s.energy().total());
  }
  return r;
}

// Mean period from the upward crossings of the equilibrium, linearly interpolated.
double measured_period(const Trajectory& r) {
  const double eq = -kSpringRest - kSpringAmplitude;
  std::vector<double> crossings;
  for (std::size_t k = 1; k < r.y.size(); ++k) {
    const double a = r.y[k - 1] - eq, b = r.y[k] - eq;
    if (a < 0.0 && b >= 0.0) crossings.push_back(r.t[k - 1] + (r.t[k] - r.t[k - 1]) * a / (a - b));
  }
  EXPECT_GE(crossings.size(), 3u);
  return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

double measured_amplitude(const Trajectory& r) {
  double lo = INFINITY, hi = -INFINITY;
  for (double y : r.y) lo = std::min(lo, y), hi = std::max(hi, y);
  return 0.5 * (hi - lo);
}

class SecondOrderOrBetter : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(SecondOrderOrBetter, PeriodAndAmplitudeMatchClosedFormWithinATenthOfAPercent) {
  const double dt = kPeriod / 1000.0;
  const Trajectory r = simulate(GetParam(), dt, 10 * 1000);
  EXPECT_NEAR(measured_period(r) / kPeriod, 1.0, 1e-3);
  EXPECT_NEAR(measured_amplitude(r) / kSpringAmplitude, 1.0, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(SingleSpring, SecondOrderOrBetter,
                         ::testing::Values(IntegratorKind::verlet, IntegratorKind::rk4),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

// Mean total energy over one period, starting at step `from`.
double period_mean(const std::vector<double>& e, std::size_t from, std::size_t per_period) {
  double sum = 0.0;
  for (std::size_t k = from; k < from + per_period; ++k) sum += e[k];
  return sum / double(per_period);
}

TEST(SingleSpring, SymplecticEulerEnergyStaysBoundedOverAHundredPeriods) {
  const std::size_t per_period = 1000;
  const Trajectory r =
      simulate(IntegratorKind::symplectic_euler, kPeriod / per_period, 100 * per_period, true);
  const double oscillation_energy = 0.5 * kSpringStiffness * kSpringAmplitude * kSpringAmplitude;
  const double first = period_mean(r.energy, 0, per_period);
  const double last = period_mean(r.energy, r.energy.size() - 1 - per_period, per_period);
  // No drift: the period-mean energy moves by less than 0.1 % of the oscillation energy.
  EXPECT_LT(std::abs(last - first), 1e-3 * oscillation_energy);
  // Bounded: every sample within 2 % of the oscillation energy (the O(w dt) wobble).
  for (double e : r.energy) ASSERT_LT(std::abs(e - r.energy[0]), 2e-2 * oscillation_energy);
}

TEST(SingleSpring, ExplicitEulerEnergyGrows) {
  const std::size_t per_period = 1000;
  const Trajectory r =
      simulate(IntegratorKind::explicit_euler, kPeriod / per_period, 100 * per_period, true);
  const double oscillation_energy = 0.5 * kSpringStiffness * kSpringAmplitude * kSpringAmplitude;
  // |1 + i w dt|^2 per step: (1 + (2 pi / 1000)^2)^100000 = e^3.95 = 52x the oscillation energy.
  const double gained = r.energy.back() - r.energy.front();
  EXPECT_GT(gained, 20.0 * oscillation_energy);
  EXPECT_GT(period_mean(r.energy, r.energy.size() - 1 - per_period, per_period),
            period_mean(r.energy, 50 * per_period, per_period));
}

TEST(SingleSpring, DampedSpringSettlesAtTheEquilibriumStretch) {
  Scene scene = testing::single_spring(kSpringMass, kSpringStiffness, kSpringRest,
                                       IntegratorKind::symplectic_euler, 1e-4);
  scene.springs.damping = 2.0;  // damping ratio 0.32: decays as e^(-10 t)
  const auto s_owner = testing::solver<double>(scene);
  Solver& s = *s_owner;
  ASSERT_TRUE(s.advance(3.0).ok());
  EXPECT_NEAR(s.position(1)[1], -kSpringRest - kSpringAmplitude, 1e-9);  // stretch m g / k
  EXPECT_NEAR(s.velocity(1)[1], 0.0, 1e-8);
}

// Largest position error over [0, 0.5 s] against the closed form. (The error at one instant is
// a poor measure: its curve crosses zero, which makes the ratio of two runs erratic.)
double max_error_over_half_second(IntegratorKind kind, long steps) {
  const auto s_owner = testing::solver<double>(testing::single_spring(
      kSpringMass, kSpringStiffness, kSpringRest, kind, 0.5 / double(steps)));
  Solver& s = *s_owner;
  double worst = 0.0;
  for (long k = 0; k < steps; ++k) {
    EXPECT_TRUE(s.step(1).ok());
    worst = std::max(worst, std::abs(s.position(1)[1] - spring_exact_y(s.time())));
  }
  return worst;
}

struct OrderCase {
  IntegratorKind kind;
  long steps;  // the coarser of the two runs
  double order;
};

class ConvergenceOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(ConvergenceOrder, HalvingTheStepDividesTheErrorByTwoToTheOrder) {
  const OrderCase c = GetParam();
  const double coarse = max_error_over_half_second(c.kind, c.steps);
  const double fine = max_error_over_half_second(c.kind, 2 * c.steps);
  const double order = std::log2(coarse / fine);
  EXPECT_NEAR(order, c.order, 0.15) << "errors " << coarse << " and " << fine;
}

INSTANTIATE_TEST_SUITE_P(SingleSpring, ConvergenceOrder,
                         ::testing::Values(OrderCase{IntegratorKind::explicit_euler, 20000, 1.0},
                                           OrderCase{IntegratorKind::symplectic_euler, 20000, 1.0},
                                           OrderCase{IntegratorKind::seed_hack, 20000, 1.0},
                                           OrderCase{IntegratorKind::verlet, 2000, 2.0},
                                           OrderCase{IntegratorKind::rk4, 200, 4.0}),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param.kind));
                         });

}  // namespace
}  // namespace clothlab
