// The step loop allocates nothing: global operator new is counted across many steps of every
// integrator, with every force (springs with damping, drag, gusty wind) on and two threads.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "allocation_counter.hpp"
#include "sim/solver_impl.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

template <class T>
void expect_no_allocation(IntegratorKind kind) {
  Scene scene = testing::sheet(24, 1.0, 0.5, 400.0, kind, 2e-4);
  scene.cloths[0].pins = {{0, 0}, {23, 0}};
  scene.springs.damping = 0.02;
  scene.forces.drag = 0.001;
  scene.forces.wind = {true, {3.0, 0.0, 1.0}, 0.5, 7, 1.0, 1.0};
  scene.solver.threads = 2;
  SolverT<T> s(scene);
  ASSERT_TRUE(s.step(3).ok());  // warm-up: starts the OpenMP thread pool
  const long before = g_allocations.load();
  ASSERT_TRUE(s.step(200).ok());
  ASSERT_TRUE(s.advance(0.01).ok());
  EXPECT_EQ(g_allocations.load() - before, 0) << "allocations in the step loop";
}

class StepLoop : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(StepLoop, AllocatesNothingInFloat) {
  expect_no_allocation<float>(GetParam());
}
TEST_P(StepLoop, AllocatesNothingInDouble) {
  expect_no_allocation<double>(GetParam());
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, StepLoop, ::testing::ValuesIn(kAllIntegrators),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

TEST(StepLoop, CounterSeesAllocations) {
  // The counter works: building a solver does allocate.
  const long before = g_allocations.load();
  SolverT<float> s(testing::sheet(4, 1.0, 0.1, 100.0, IntegratorKind::verlet, 1e-4));
  EXPECT_GT(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace clothlab
