// The row-sweep kernel (grid stencil in bands of contiguous rows, each spring once) and the
// neighbour-list kernel (per-vertex gather, each spring from both ends) describe the same
// springs: same count, same forces, same energy on any state. They add in different orders, so
// forces agree to round-off: 1e-13 (double) and 1e-6 (float) of the largest force component.
#include <gtest/gtest.h>

#include <random>

#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

void perturb(Solver& s, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Vec3d> x = testing::positions_of(s), v(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      x[i][a] += 0.02 * normal(rng);
      v[i][a] = 0.5 * normal(rng);
    }
  }
  s.set_state(x, v);
}

template <class T>
void expect_same_physics(const Scene& scene, double tolerance) {
  const auto sweep_owner = testing::solver<T>(scene, SpringKernel::row_sweep);
  const auto list_owner = testing::solver<T>(scene, SpringKernel::neighbour_list);
  Solver &sweep = *sweep_owner, &list = *list_owner;
  ASSERT_EQ(sweep.spring_count(), list.spring_count());
  perturb(sweep, 5);
  perturb(list, 5);
  sweep.update_force_field();
  list.update_force_field();
  double largest = 0.0;
  for (std::size_t i = 0; i < sweep.vertex_count(); ++i)
    for (double c : list.force(static_cast<int>(i))) largest = std::max(largest, std::abs(c));
  ASSERT_GT(largest, 0.1);  // the perturbation really loads the springs
  for (std::size_t i = 0; i < sweep.vertex_count(); ++i) {
    const Vec3d a = sweep.force(static_cast<int>(i)), b = list.force(static_cast<int>(i));
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(a[c], b[c], tolerance * largest) << "vertex " << i;
  }
  const Energy ea = sweep.energy(), eb = list.energy();
  EXPECT_GT(ea.elastic, 0.0);
  EXPECT_NEAR(ea.elastic, eb.elastic, 1e-9 * ea.elastic);
  EXPECT_EQ(ea.kinetic, eb.kinetic);
}

TEST(SpringKernels, RowSweepEqualsNeighbourListInDouble) {
  for (const Scene& s : testing::band_edge_cases()) expect_same_physics<double>(s, 1e-13);
}

TEST(SpringKernels, RowSweepEqualsNeighbourListInFloat) {
  for (const Scene& s : testing::band_edge_cases()) expect_same_physics<float>(s, 1e-6);
}

// The bands of a grid are fixed by its size, never by the thread count, and each vertex sums its
// forces in one order: 1 and 2 threads give the same bits, on a grid of 8 bands.
TEST(SpringKernels, BandsGiveTheSameBitsOnOneAndTwoThreads) {
  Scene scene = testing::grid_sheet(64, 64);
  scene.solver.integrator = IntegratorKind::symplectic_euler;
  const auto one_owner = testing::solver<float>(scene), two_owner = testing::solver<float>(scene);
  Solver &one = *one_owner, &two = *two_owner;
  two.set_threads(2);
  ASSERT_EQ(two.threads(), 2);
  perturb(one, 9);
  perturb(two, 9);
  ASSERT_TRUE(one.step(40).ok());
  ASSERT_TRUE(two.step(40).ok());
  EXPECT_EQ(testing::positions_of(one), testing::positions_of(two));
  EXPECT_EQ(testing::velocities_of(one), testing::velocities_of(two));
}

TEST(SpringKernels, SpringCountOnFourByFourIs82) {
  Scene s = testing::sheet(4, 1.0, 0.1, 100.0, IntegratorKind::verlet, 1e-4);
  EXPECT_EQ(testing::solver<float>(s, SpringKernel::row_sweep)->spring_count(), 82u);
  EXPECT_EQ(testing::solver<float>(s, SpringKernel::neighbour_list)->spring_count(), 82u);
}

}  // namespace
}  // namespace clothlab
