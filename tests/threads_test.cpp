// solver.threads = 0 ("auto", sim/core/parallel.hpp): one thread below kParallelMinVertices,
// where a second thread costs more than it gives, and every core OpenMP offers above it; an
// explicit count is used as given. And the block loops of sim/core/parallel.hpp hand out every
// block once.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <vector>

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

// The balanced block loop (blocks taken one at a time as threads come free) hands out the blocks
// for_each_block_indexed does, each exactly once, for any count of items and threads: the
// colliders' response writes each block's results to the block's own slot, so the same blocks
// give the same sums in block order.
TEST(ParallelBlocks, BalancedLoopVisitsEveryBlockOnce) {
  for (const std::size_t n : {std::size_t(0), std::size_t(1), kBlockSize - 1, kBlockSize,
                              kBlockSize + 1, std::size_t(3200), 7 * kBlockSize + 13}) {
    for (const int threads : {1, 2, 3}) {
      const std::size_t blocks = block_count(n);
      std::vector<std::array<std::size_t, 3>> seen(blocks, {0, 0, 0});  // visits, begin, end
      std::vector<int> covered(n, 0);
      for_each_block_balanced(n, threads, [&](std::size_t b, std::size_t lo, std::size_t hi) {
        seen[b] = {seen[b][0] + 1, lo, hi};
        for (std::size_t i = lo; i < hi; ++i) ++covered[i];
      });
      for (std::size_t b = 0; b < blocks; ++b) {
        EXPECT_EQ(seen[b][0], 1u) << "n " << n << ", threads " << threads << ", block " << b;
        EXPECT_EQ(seen[b][1], b * kBlockSize);
        EXPECT_EQ(seen[b][2], std::min(n, (b + 1) * kBlockSize));
      }
      EXPECT_EQ(std::count(covered.begin(), covered.end(), 1), std::ptrdiff_t(n))
          << "n " << n << ", threads " << threads;
    }
  }
}

}  // namespace
}  // namespace clothlab
