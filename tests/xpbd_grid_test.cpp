// XPBD's grid path (sim/integrators/constraints/xpbd_grid.hpp) against the neighbour-list path
// sweeping the same springs in the same order (xpbd_grid_colours): on every stencil edge case of
// the band kernel, with pins, damping, drag and wind, one and several sweeps; and the same bits on
// any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "grid_path_compare.hpp"
#include "sim/integrators/constraints/xpbd_grid.hpp"

namespace clothlab {
namespace {

using testing::largest_difference;
using testing::Outcome;

// `steps` substeps of h from disturbed(); grid: the row-sweep model's grid path, else the
// neighbour-list model's list path in the grid path's order.
template <class T>
Outcome<T> run_xpbd(const Scene& scene, bool grid, int threads, int steps, T h) {
  return testing::run_grid_or_list<T>(
      scene, grid, threads, steps, h,
      [&](const Model<T>& m) {
        EXPECT_TRUE(xpbd_grid_applies(m));
        return make_xpbd_grid(m, scene.solver);
      },
      [&](const Model<T>& m, const Model<T>& g) {
        const std::vector<int> colours = xpbd_grid_colours(g, spring_list(m).ends);
        EXPECT_EQ(std::count(colours.begin(), colours.end(), -1), 0) << "a spring without a batch";
        return make_xpbd_in_order(m, scene.solver, colours);
      });
}

// Both paths do the same arithmetic per spring in the same order; only the prediction's gravity
// term is formed differently (m g against f + drag v), so they agree to round-off.
template <class T>
void expect_xpbd_same_as_list(Scene scene, int sweeps, double tolerance) {
  scene.solver.integrator = IntegratorKind::xpbd;
  scene.solver.iterations = sweeps;
  // The list path has neither (tests/small_steps_test.cpp has them).
  scene.solver.tethers = false;
  scene.solver.coarse_stretch = false;
  const T h = T(1.0 / 600.0);
  const Outcome<T> grid = run_xpbd<T>(scene, true, 2, 3, h),
                   list = run_xpbd<T>(scene, false, 1, 3, h);
  EXPECT_GT(grid.moved, 1e-3);
  EXPECT_LT(largest_difference(grid.state, list.state, false), tolerance)
      << scene.cloths[0].resolution[0] << "x" << scene.cloths[0].resolution[1] << ", " << sweeps
      << " sweeps";
  EXPECT_LT(largest_difference(grid.state, list.state, true), tolerance / double(h))
      << scene.cloths[0].resolution[0] << "x" << scene.cloths[0].resolution[1];
}

TEST(XpbdGrid, SameAsTheListPathInFloat) {
  for (const Scene& s : testing::band_edge_cases()) {
    expect_xpbd_same_as_list<float>(s, 1, 2e-6);
    expect_xpbd_same_as_list<float>(s, 3, 2e-6);
  }
}

TEST(XpbdGrid, SameAsTheListPathInDouble) {
  for (const Scene& s : testing::band_edge_cases()) {
    expect_xpbd_same_as_list<double>(s, 1, 1e-13);
    expect_xpbd_same_as_list<double>(s, 3, 1e-13);
  }
}

TEST(XpbdGrid, SameAsTheListPathWithWind) {
  Scene s = testing::grid_sheet(33, 40);
  s.forces.wind = {true, {3.0, 0.0, 1.0}, 0.5, 7, 1.0, 1.0};
  expect_xpbd_same_as_list<float>(s, 2, 2e-6);
  expect_xpbd_same_as_list<double>(s, 2, 1e-13);
}

// Several bands in each phase, so two and three threads really share the work.
TEST(XpbdGrid, SameBitsOnOneTwoAndThreeThreads) {
  Scene s = testing::grid_sheet(96, 300);
  s.solver.integrator = IntegratorKind::xpbd;
  for (int sweeps : {1, 2}) {
    s.solver.iterations = sweeps;
    const Outcome<float> one = run_xpbd<float>(s, true, 1, 2, 1e-3f);
    for (int threads : {2, 3}) {
      const Outcome<float> many = run_xpbd<float>(s, true, threads, 2, 1e-3f);
      EXPECT_EQ(largest_difference(one.state, many.state, false), 0.0) << threads << " threads";
      EXPECT_EQ(largest_difference(one.state, many.state, true), 0.0) << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace clothlab
