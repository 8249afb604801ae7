// solver.threads = 0 ("auto", sim/core/parallel.hpp): one thread below kParallelMinVertices,
// where a second thread costs more than it gives, and every core OpenMP offers above it; an
// explicit count is used as given.
#include <gtest/gtest.h>
#include <omp.h>

#include "sim/core/parallel.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

Scene square(int res, int threads) {
  Scene s = testing::sheet(res, 1.0, 0.2, 100.0, IntegratorKind::symplectic_euler, 1e-4);
  s.solver.threads = threads;
  return s;
}

TEST(AutoThreads, SmallGridRunsOnOneThread) {
  static_assert(32 * 32 < kParallelMinVertices);
  EXPECT_EQ(make_solver(square(32, 0))->threads(), 1);
  const auto solver = make_solver(square(32, 2));
  EXPECT_EQ(solver->threads(), 2);  // asked for: given
  solver->set_threads(0);
  EXPECT_EQ(solver->threads(), 1);
}

TEST(AutoThreads, LargeGridUsesEveryCore) {
  static_assert(128 * 128 >= kParallelMinVertices);
  const auto solver = make_solver(square(128, 0));
  EXPECT_EQ(solver->threads(), omp_get_max_threads());
  solver->set_threads(1);
  EXPECT_EQ(solver->threads(), 1);
  solver->set_threads(0);
  EXPECT_EQ(solver->threads(), omp_get_max_threads());
}

}  // namespace
}  // namespace clothlab
