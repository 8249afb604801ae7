// The row-sweep kernel (grid stencil, contiguous rows) and the neighbour-list kernel (per-vertex
// gather) describe the same springs: same count, same forces, same energy on any state.
#include <gtest/gtest.h>

#include <random>

#include "sim/solver_impl.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

Scene damped(Scene s) {
  s.springs.damping = 0.07;
  s.forces.drag = 0.01;
  return s;
}

Scene two_cloths() {
  Scene s = damped(testing::sheet(9, 1.0, 0.4, 600.0, IntegratorKind::symplectic_euler, 1e-4));
  ClothSpec second = s.cloths[0];
  second.resolution = {5, 12};
  second.size = {0.4, 1.3};  // anisotropic spacing: the stencil reaches further along u
  second.origin = {2.0, 0.0, 0.0};
  second.springs = SpringSpec{"seed", 300.0, 0.0};  // its own springs, undamped
  s.cloths.push_back(second);
  s.multi_cloth = true;
  return s;
}

std::vector<Scene> scenes() {
  Scene strip = damped(testing::sheet(1, 1.0, 0.1, 100.0, IntegratorKind::verlet, 1e-4));
  strip.cloths[0].resolution = {1, 7};
  return {damped(testing::sheet(12, 1.0, 0.5, 800.0, IntegratorKind::rk4, 1e-4)), strip,
          two_cloths()};
}

template <class T>
void perturb(SolverT<T>& s, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (std::size_t i = 0; i < s.model().n; ++i) {
    for (int a = 0; a < 3; ++a) {
      s.state().pos.axis(a)[i] += static_cast<T>(0.02 * normal(rng));
      s.state().vel.axis(a)[i] = static_cast<T>(0.5 * normal(rng));
    }
  }
  s.state_changed();
}

template <class T>
void expect_same_physics(const Scene& scene, double tolerance) {
  SolverT<T> sweep(scene, SpringKernel::row_sweep);
  SolverT<T> list(scene, SpringKernel::neighbour_list);
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
  for (const Scene& s : scenes()) expect_same_physics<double>(s, 1e-13);
}

TEST(SpringKernels, RowSweepEqualsNeighbourListInFloat) {
  for (const Scene& s : scenes()) expect_same_physics<float>(s, 1e-6);
}

TEST(SpringKernels, SpringCountOnFourByFourIs82) {
  Scene s = testing::sheet(4, 1.0, 0.1, 100.0, IntegratorKind::verlet, 1e-4);
  EXPECT_EQ(SolverT<float>(s, SpringKernel::row_sweep).spring_count(), 82u);
  EXPECT_EQ(SolverT<float>(s, SpringKernel::neighbour_list).spring_count(), 82u);
}

}  // namespace
}  // namespace clothlab
