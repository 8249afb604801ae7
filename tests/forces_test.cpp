// Closed-form checks of the body forces: wind pressure on a flat sheet, the gust field's
// determinism and travel, and linear drag against the exact terminal-velocity curve.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/forces/wind.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

// A 1.5 m x 0.8 m sheet in the x-y plane (normal along z), no gravity, at rest.
Scene windy_sheet(WindSpec wind) {
  Scene s = testing::sheet(7, 1.0, 0.3, 500.0, IntegratorKind::symplectic_euler, 1e-4);
  s.cloths[0].size = {1.5, 0.8};
  s.forces.gravity = {0.0, 0.0, 0.0};
  s.forces.wind = wind;
  s.solver.precision = Precision::f64;
  return s;
}

TEST(Wind, TotalForceOnAFlatSheetIsCoefficientTimesAreaTimesNormalSpeed) {
  // No gust: w = (3, 1, 2) everywhere; only the normal component (2 m/s along z) pushes.
  const auto s = testing::solver<double>(windy_sheet({true, {3.0, 1.0, 2.0}, 0.0, 0, 1.0, 0.7}));
  s->update_force_field();
  Vec3d total{0, 0, 0};
  for (std::size_t i = 0; i < s->vertex_count(); ++i)
    for (int a = 0; a < 3; ++a) total[a] += s->force(static_cast<int>(i))[a];
  const double area = 1.5 * 0.8;
  EXPECT_NEAR(total[2], 0.7 * area * 2.0, 1e-12);  // springs at rest add nothing
  EXPECT_NEAR(total[0], 0.0, 1e-12);
  EXPECT_NEAR(total[1], 0.0, 1e-12);
}

TEST(Wind, MovingWithTheWindCancelsThePressure) {
  const auto s = testing::solver<double>(windy_sheet({true, {0.0, 0.0, 2.0}, 0.0, 0, 1.0, 1.0}));
  std::vector<Vec3d> v = testing::velocities_of(*s);
  for (Vec3d& vi : v) vi[2] = 2.0;
  s->set_state(testing::positions_of(*s), v);
  s->update_force_field();
  for (std::size_t i = 0; i < s->vertex_count(); ++i)
    EXPECT_NEAR(s->force(static_cast<int>(i))[2], 0.0, 1e-12);
}

TEST(Wind, GustsAreSeededBoundedAndTravelWithTheWind) {
  const WindSpec spec{true, {3.0, 0.0, 4.0}, 0.5, 7, 0.8, 1.0};  // |W| = 5 m/s
  const WindField a(spec), same(spec);
  WindSpec other_seed = spec;
  other_seed.seed = 8;
  const WindField b(other_seed);
  double lo = INFINITY, hi = -INFINITY, differs = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const double t = 0.01 * k;
    const Vec3d w = a.velocity(t, {0.1, 0.2, 0.3});
    EXPECT_EQ(w[0], same.velocity(t, {0.1, 0.2, 0.3})[0]);  // same seed, same gusts
    differs = std::max(differs, std::abs(w[0] - b.velocity(t, {0.1, 0.2, 0.3})[0]));
    const double factor = w[0] / 3.0;
    lo = std::min(lo, factor), hi = std::max(hi, factor);
    // A gust seen at x at time t is seen d metres downwind d / |W| seconds later.
    const double d = 0.9;
    const Vec3d later = a.velocity(t + d / 5.0, {0.1 + d * 0.6, 0.2, 0.3 + d * 0.8});
    EXPECT_NEAR(later[0], w[0], 1e-9);
  }
  EXPECT_GE(lo, 0.5);  // 1 +- gust
  EXPECT_LE(hi, 1.5);
  EXPECT_GT(hi - lo, 0.3);  // and it really varies
  EXPECT_GT(differs, 0.1);  // another seed gives other gusts
}

TEST(Drag, LoneVertexFollowsTheTerminalVelocityCurve) {
  // One free vertex (a 1 x 1 grid has no springs): m dv/dt = m g - c v, so
  // v(t) = -(m g / c) (1 - exp(-c t / m)).
  const double m = 0.2, c = 0.5, g = 9.81;
  Scene scene = testing::sheet(1, 1.0, m, 100.0, IntegratorKind::rk4, 1e-3);
  scene.forces.drag = c;
  scene.solver.precision = Precision::f64;
  const auto s = testing::solver<double>(scene);
  ASSERT_EQ(s->spring_count(), 0u);
  ASSERT_TRUE(s->advance(2.0).ok());
  const double expected = -(m * g / c) * (1.0 - std::exp(-c * 2.0 / m));
  EXPECT_NEAR(s->velocity(0)[1], expected, 1e-9);
  EXPECT_NEAR(s->velocity(0)[1], -m * g / c, 0.01 * m * g / c);  // close to terminal by t = 2 s
}

}  // namespace
}  // namespace clothlab
