// Vertex block descent's grid path (sim/integrators/descent/vbd_grid.hpp) against the
// neighbour-list path visiting the vertices in the same colours (vbd_grid_colours): on the band
// kernel's stencil edge cases, with pins, damping, drag, wind, two cloths and Chebyshev
// acceleration; the same bits on any thread count; and which models take it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "grid_path_compare.hpp"
#include "sim/integrators/descent/vbd_grid.hpp"

namespace clothlab {
namespace {

using testing::largest_difference;
using testing::Outcome;

// `steps` steps of h from disturbed(); grid: the row-sweep model's grid path, else the
// neighbour-list model's list path in the grid path's colours.
template <class T>
Outcome<T> run_vbd(const Scene& scene, bool grid, int threads, int steps, T h) {
  return testing::run_grid_or_list<T>(
      scene, grid, threads, steps, h,
      [&](const Model<T>& m) {
        EXPECT_TRUE(vbd_grid_applies(m));
        return make_vbd_grid(m, scene.solver);
      },
      [&](const Model<T>& m, const Model<T>& g) {
        return make_vbd_in_order(m, scene.solver, vbd_grid_colours(g));
      });
}

// Both paths do the same arithmetic per spring; a vertex sums its springs in another order
// (stencil order against the spring list's), so they agree to round-off. Three steps of 1/240 s
// with 12 iterations: Chebyshev from the fourth, the warm start from the second step.
template <class T>
void expect_same_as_list(Scene scene, double tolerance, double h = 1.0 / 240.0) {
  scene.solver.integrator = IntegratorKind::vbd;
  scene.solver.iterations = 12;
  const Outcome<T> grid = run_vbd<T>(scene, true, 2, 3, T(h)),
                   list = run_vbd<T>(scene, false, 1, 3, T(h));
  const auto& r = scene.cloths[0].resolution;
  EXPECT_GT(grid.moved, 1e-3) << r[0] << "x" << r[1];
  EXPECT_LT(largest_difference(grid.state, list.state, false), tolerance) << r[0] << "x" << r[1];
  EXPECT_LT(largest_difference(grid.state, list.state, true), tolerance / h) << r[0] << "x" << r[1];
}

// The 600 x 20 sheet is left out in float: its springs are 1.7 mm long at coordinates up to
// 0.5 m, where float resolves a spring's length to 2e-5 of itself, and the paths' different
// summation orders part by 0.1 mm there (double: 6e-13 m).
TEST(VbdGrid, SameAsTheListPathInFloat) {
  for (const Scene& s : testing::band_edge_cases())
    if (s.cloths[0].resolution[0] != 600) expect_same_as_list<float>(s, 4e-6);
}

TEST(VbdGrid, SameAsTheListPathInDouble) {
  for (const Scene& s : testing::band_edge_cases()) expect_same_as_list<double>(s, 2e-12);
}

TEST(VbdGrid, SameAsTheListPathWithWindAtALargeStep) {
  Scene s = testing::grid_sheet(33, 40);
  s.forces.wind = {true, {3.0, 0.0, 1.0}, 0.5, 7, 1.0, 1.0};
  expect_same_as_list<float>(s, 2e-5, 1.0 / 60.0);
  expect_same_as_list<double>(s, 1e-12, 1.0 / 60.0);
}

// Tubes and meshes have no grid: vbd_grid_applies is false and make_vbd takes the list path.
TEST(VbdGrid, NotForTubes) {
  Scene s = testing::grid_sheet(12, 8);
  s.cloths[0].shape = "tube";
  EXPECT_FALSE(vbd_grid_applies(build_model<float>(s, SpringKernel::row_sweep)));
}

// Several rows per colour and thread, so two and three threads really share the work.
TEST(VbdGrid, SameBitsOnOneTwoAndThreeThreads) {
  Scene s = testing::grid_sheet(70, 90);
  s.solver.integrator = IntegratorKind::vbd;
  s.solver.iterations = 8;
  const Outcome<float> one = run_vbd<float>(s, true, 1, 2, 1.0f / 60.0f);
  for (int threads : {2, 3}) {
    const Outcome<float> many = run_vbd<float>(s, true, threads, 2, 1.0f / 60.0f);
    EXPECT_EQ(largest_difference(one.state, many.state, false), 0.0) << threads << " threads";
    EXPECT_EQ(largest_difference(one.state, many.state, true), 0.0) << threads << " threads";
  }
}

}  // namespace
}  // namespace clothlab
