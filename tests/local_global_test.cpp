// Chebyshev acceleration of local_global (sim/integrators/descent/local_global.cpp, chebyshev.hpp):
// it reaches the same fixed point as the plain iteration, and gets much closer to it in the same
// number of iterations. large_step_test.cpp runs the shared large-step checks for local_global.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sim/integrators/descent/chebyshev.hpp"
#include "sim/integrators/integrator.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

constexpr double kStepH = 1.0 / 60.0;

// The hanging sheet (8 x 8, k0 = 1e3) four display steps after it was released (the first step
// from rest is almost free fall). 8 x 8 keeps the plain iteration's own convergence within reach:
// at 16 x 16, 20000 plain iterations still leave 1e-6 m (docs/solver.md).
State<double> fifth_step_start(const Model<double>& m, const System<double>& sys, SolverSpec spec) {
  State<double> s{m.rest_positions, {}};
  s.vel.resize(m.n);
  spec.iterations = 2000;
  auto integrator = make_integrator<double>(m, spec);
  for (int k = 0; k < 4; ++k) integrator->step(sys, s, k * kStepH, kStepH);
  return s;
}

double rms_distance(const Vec3Array<double>& a, const Vec3Array<double>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c) sum += std::pow(a.axis(c)[i] - b.axis(c)[i], 2);
  return std::sqrt(sum / double(a.size()));
}

struct LocalGlobalFixture {
  Scene scene = testing::falling_sheet(8, IntegratorKind::local_global, kStepH);
  Model<double> model = build_model<double>(scene);
  ForceWorkspace<double> ws;
  System<double> sys{model, ws, 1};
  State<double> start;
  LocalGlobalFixture() {
    ws.resize(model);
    SolverSpec spec = scene.solver;
    spec.chebyshev_rho = kChebyshevOff;
    start = fifth_step_start(model, sys, spec);
  }
  // Positions after one step of `iterations` with Chebyshev's rho.
  Vec3Array<double> step(int iterations, double rho) {
    SolverSpec spec = scene.solver;
    spec.iterations = iterations;
    spec.chebyshev_rho = rho;
    auto integrator = make_integrator<double>(model, spec);
    State<double> s = start;
    integrator->step(sys, s, 4 * kStepH, kStepH);
    return s.pos;
  }
};

TEST(LocalGlobalChebyshev, ReachesThePlainFixedPoint) {
  LocalGlobalFixture f;
  const Vec3Array<double> converged = f.step(20000, kChebyshevOff);
  const double d = rms_distance(f.step(6000, 0.0), converged);  // 0: the default rho, 0.97
  std::printf("[ measured ] accelerated 6000 iterations: %.3g m from 20000 plain ones\n", d);
  EXPECT_LT(d, 1e-9);
}

// The gain grows with the iterations (Chebyshev's error bound falls like its polynomial's, Wang
// 2015 Sec. 4). Measured on this sheet: 30 / 100 iterations leave 1.19 / 0.82 mm plain and
// 0.74 / 0.33 mm accelerated with the default rho 0.97 (1.6x / 2.5x closer; with 0.99 2.2x /
// 5.1x). On the 32 x 32 sheet the whole 0.5 s run lands 635 mm from RK4 plain and 382 mm
// accelerated at 10 iterations, 406 and 139 mm at 30.
TEST(LocalGlobalChebyshev, GetsCloserInTheSameIterations) {
  LocalGlobalFixture f;
  const Vec3Array<double> converged = f.step(20000, kChebyshevOff);
  const struct {
    int iterations;
    double gain;
  } cases[] = {{30, 1.4}, {100, 2.0}};
  for (const auto& c : cases) {
    const double plain = rms_distance(f.step(c.iterations, kChebyshevOff), converged);
    const double fast = rms_distance(f.step(c.iterations, 0.0), converged);
    std::printf("[ measured ] %d iterations: %.3g m plain, %.3g m accelerated\n", c.iterations,
                plain, fast);
    EXPECT_GT(plain, 5e-4) << "the plain iteration is far from converged: the test has teeth";
    EXPECT_LT(fast * c.gain, plain) << c.iterations;
  }
}

}  // namespace
}  // namespace clothlab
