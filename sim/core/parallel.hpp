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
// (measured with the programs' short spin then passive wait; docs/results.md "Threads",
// docs/design.md).
inline constexpr std::size_t kParallelMinVertices = 8192;
// With triangle contact (solver.cloth_contact) a second thread pays from about two thousand
// vertices: the 48 x 48 pile's frame (2304) takes 0.61x the one-thread time on two, the 47 x 47
// tent's 0.94x, but the 32 x 32 default sheet's small explicit steps 1.5x (0.090 ms a step
// against 0.058).
inline constexpr std::size_t kParallelMinContactVertices = 2048;

// The threads for a loop over n cheap items: one below min_items, where waking a second thread
// costs more than it saves (a wake-up is tens of microseconds with a passive wait policy).
inline int threads_for(std::size_t n, int threads, std::size_t min_items = kParallelMinVertices) {
  return n >= min_items ? threads : 1;
}

// The threads for triangle contact's loops over vertices, triangles, pairs or patches
// (sim/contact/): a second thread pays from far fewer items there, and a loop run on one thread
// between parallel ones lets the other fall asleep (waking it costs tens of microseconds, several
// times a substep).
inline int contact_threads(std::size_t n, int threads) {
  return threads_for(n, threads, kParallelMinContactVertices);
}

inline std::size_t block_count(std::size_t n) {
  return (n + kBlockSize - 1) / kBlockSize;
}

// Every helper below calls its work directly when it runs on one thread instead of entering a
// parallel region with a false `if` clause: libgomp still builds and tears down a team of one
// for such a region, 0.4 us each (measured: a million empty regions in 0.39-0.44 s), which was
// 5 % of a 32x32 step (two regions a step). Outside a parallel region the `omp for` and
// `omp barrier` inside a body bind to a team of one: the loops run whole, the barriers return.
template <class Body>
void run_team(int threads, Body&& body) {
  if (threads <= 1) {
    body();
    return;
  }
#pragma omp parallel num_threads(threads)
  body();
}

// Calls fn(block, begin, end) for each block of [0, n) as an orphaned `omp for`: inside a
// parallel region every thread of its team must call it and the blocks are shared among them
// (a barrier at the end); outside one it runs the whole loop. For several loops in one region.
template <class Fn>
void team_blocks(std::size_t n, Fn&& fn) {
  const long blocks = static_cast<long>(block_count(n));
#pragma omp for schedule(static)
  for (long b = 0; b < blocks; ++b) {
    const std::size_t begin = static_cast<std::size_t>(b) * kBlockSize;
    fn(static_cast<std::size_t>(b), begin, std::min(n, begin + kBlockSize));
  }
}

// Calls fn(begin, end) for each block of [0, n); blocks run in parallel on `threads` threads.
template <class Fn>
void for_each_block(std::size_t n, int threads, Fn&& fn) {
  const long blocks = static_cast<long>(block_count(n));
  run_team(blocks > 1 ? threads : 1, [&] {
#pragma omp for schedule(static)
    for (long b = 0; b < blocks; ++b) {
      const std::size_t begin = static_cast<std::size_t>(b) * kBlockSize;
      fn(begin, std::min(n, begin + kBlockSize));
    }
  });
}

// Calls fn(block, begin, end); used for reductions that write one partial result per block and
// are summed afterwards in block order (deterministic, unlike an OpenMP reduction clause).
template <class Fn>
void for_each_block_indexed(std::size_t n, int threads, Fn&& fn) {
  const long blocks = static_cast<long>(block_count(n));
  run_team(blocks > 1 ? threads : 1, [&] {
#pragma omp for schedule(static)
    for (long b = 0; b < blocks; ++b) {
      const std::size_t begin = static_cast<std::size_t>(b) * kBlockSize;
      fn(static_cast<std::size_t>(b), begin, std::min(n, begin + kBlockSize));
    }
  });
}

// for_each_block_indexed for blocks whose cost differs widely (the vertices resting on a collider
// against those far from it): each thread takes the next block when done with its last, so
// neither waits on the other's share. fn must write only its own block's results.
template <class Fn>
void for_each_block_balanced(std::size_t n, int threads, Fn&& fn) {
  const long blocks = static_cast<long>(block_count(n));
  run_team(blocks > 1 ? threads : 1, [&] {
#pragma omp for schedule(dynamic, 1)
    for (long b = 0; b < blocks; ++b) {
      const std::size_t begin = static_cast<std::size_t>(b) * kBlockSize;
      fn(static_cast<std::size_t>(b), begin, std::min(n, begin + kBlockSize));
    }
  });
}

// Runs `phases` rounds of blocks in one parallel region, a barrier after each: fn(phase, begin,
// end) over the blocks of [0, size(phase)). For Gauss-Seidel colours, where a region per colour
// would cost a thread wake-up per colour (with a passive wait policy, tens of microseconds).
template <class SizeFn, class Fn>
void for_each_phase_block(int phases, SizeFn&& size, int threads, Fn&& fn) {
  run_team(threads, [&] {
    for (int phase = 0; phase < phases; ++phase) {
      const std::size_t n = size(phase);
      const long blocks = static_cast<long>(block_count(n));
#pragma omp for schedule(static)
      for (long b = 0; b < blocks; ++b) {
        const std::size_t begin = static_cast<std::size_t>(b) * kBlockSize;
        fn(phase, begin, std::min(n, begin + kBlockSize));
      }
    }
  });
}

// Calls first(k) for k in [0, count), then, after every first(k) has returned, then(k) for k in
// [1, count): two parallel loops in one parallel region (one thread wake-up, not two).
template <class First, class Then>
void for_each_index_then(int count, int threads, First&& first, Then&& then) {
  run_team(count > 1 ? threads : 1, [&] {
#pragma omp for schedule(static)
    for (int k = 0; k < count; ++k) first(k);
#pragma omp for schedule(static)
    for (int k = 1; k < count; ++k) then(k);
  });
}

// Calls fn(k) for k in [0, count) in parallel; for work items (grid rows) whose result does not
// depend on which thread runs them.
template <class Fn>
void for_each_index(int count, int threads, Fn&& fn) {
  run_team(count > 1 ? threads : 1, [&] {
#pragma omp for schedule(static)
    for (int k = 0; k < count; ++k) fn(k);
  });
}

}  // namespace clothlab
