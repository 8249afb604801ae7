// Deterministic OpenMP helpers. Work is cut into blocks of a fixed size that does not depend on
// the thread count, and every vertex is computed by the same code path in the same order, so a
// result is bit-identical for any number of threads (docs/design.md: "same trace, bit for bit").
#pragma once

#include <algorithm>
#include <cstddef>

namespace clothlab {

// Vertices per block: small enough that a block and its grid neighbours stay in L1/L2.
inline constexpr std::size_t kBlockSize = 512;

// solver.threads = 0 runs one thread on scenes with fewer vertices: below it a second thread
// gains at most 1.2-1.4x on an idle host and loses several times over beside one busy process
// (measured with the programs' short spin then passive wait; README "Threads", docs/design.md).
inline constexpr std::size_t kParallelMinVertices = 8192;

inline std::size_t block_count(std::size_t n) {
  return (n + kBlockSize - 1) / kBlockSize;
}

// Calls fn(begin, end) for each block of [0, n); blocks run in parallel on `threads` threads.
template <class Fn>
void for_each_block(std::size_t n, int threads, Fn&& fn) {
  const long blocks = static_cast<long>(block_count(n));
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1 && blocks > 1)
  for (long b = 0; b < blocks; ++b) {
    const std::size_t begin = static_cast<std::size_t>(b) * kBlockSize;
    fn(begin, std::min(n, begin + kBlockSize));
  }
}

// Calls fn(block, begin, end); used for reductions that write one partial result per block and
// are summed afterwards in block order (deterministic, unlike an OpenMP reduction clause).
template <class Fn>
void for_each_block_indexed(std::size_t n, int threads, Fn&& fn) {
  const long blocks = static_cast<long>(block_count(n));
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1 && blocks > 1)
  for (long b = 0; b < blocks; ++b) {
    const std::size_t begin = static_cast<std::size_t>(b) * kBlockSize;
    fn(static_cast<std::size_t>(b), begin, std::min(n, begin + kBlockSize));
  }
}

// Runs `phases` rounds of blocks in one parallel region, a barrier after each: fn(phase, begin,
// end) over the blocks of [0, size(phase)). For Gauss-Seidel colours, where a region per colour
// would cost a thread wake-up per colour (with a passive wait policy, tens of microseconds).
template <class SizeFn, class Fn>
void for_each_phase_block(int phases, SizeFn&& size, int threads, Fn&& fn) {
#pragma omp parallel num_threads(threads) if (threads > 1)
  for (int phase = 0; phase < phases; ++phase) {
    const std::size_t n = size(phase);
    const long blocks = static_cast<long>(block_count(n));
#pragma omp for schedule(static)
    for (long b = 0; b < blocks; ++b) {
      const std::size_t begin = static_cast<std::size_t>(b) * kBlockSize;
      fn(phase, begin, std::min(n, begin + kBlockSize));
    }
  }
}

// Calls first(k) for k in [0, count), then, after every first(k) has returned, then(k) for k in
// [1, count): two parallel loops in one parallel region (one thread wake-up, not two).
template <class First, class Then>
void for_each_index_then(int count, int threads, First&& first, Then&& then) {
#pragma omp parallel num_threads(threads) if (threads > 1 && count > 1)
  {
#pragma omp for schedule(static)
    for (int k = 0; k < count; ++k) first(k);
#pragma omp for schedule(static)
    for (int k = 1; k < count; ++k) then(k);
  }
}

// Calls fn(k) for k in [0, count) in parallel; for work items (grid rows) whose result does not
// depend on which thread runs them.
template <class Fn>
void for_each_index(int count, int threads, Fn&& fn) {
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1 && count > 1)
  for (int k = 0; k < count; ++k) fn(k);
}

}  // namespace clothlab
