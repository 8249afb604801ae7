#include "bench/suites/machine_limits.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "bench/suites/report.hpp"
#include "sim/core/vec3_array.hpp"

namespace clothlab::bench {

namespace {

constexpr int kRepeats = 5;  // best of: the limit is what the machine can do when undisturbed

double copy_rate(int threads) {
  const std::size_t n = std::size_t(1) << 24;  // 64 MiB per array: far beyond the caches
  AlignedVector<float> a(n, 1.0f), b(n, 0.0f);
  const long count = static_cast<long>(n);
  double best = INFINITY;
  for (int r = 0; r < kRepeats; ++r) {
    Stopwatch clock;
#pragma omp parallel for simd num_threads(threads) schedule(static)
    for (long i = 0; i < count; ++i)
      b[static_cast<std::size_t>(i)] = a[static_cast<std::size_t>(i)];
    best = std::min(best, clock.seconds());
  }
  volatile float sink = b[n / 2];
  (void)sink;
  return 2.0 * sizeof(float) * double(n) / best;
}

// 16 independent vectors of 16 floats: enough chains to hide the FMA latency on any x86 core.
double fma_rate(int threads) {
  constexpr int kChains = 16, kWidth = 16;
  constexpr long kIterations = 2'000'000;
  double best = INFINITY;
  float total = 0.0f;
  for (int r = 0; r < kRepeats; ++r) {
    Stopwatch clock;
#pragma omp parallel num_threads(threads) reduction(+ : total)
    {
      alignas(64) float acc[kChains][kWidth];
      for (int c = 0; c < kChains; ++c)
        for (int l = 0; l < kWidth; ++l) acc[c][l] = 0.001f * float(c + l);
      const float mul = 0.999999f, add = 1e-7f;
      for (long it = 0; it < kIterations; ++it)
        for (int c = 0; c < kChains; ++c)
#pragma omp simd
          for (int l = 0; l < kWidth; ++l) acc[c][l] = acc[c][l] * mul + add;
      for (int c = 0; c < kChains; ++c)
        for (int l = 0; l < kWidth; ++l) total += acc[c][l];
    }
    best = std::min(best, clock.seconds());
  }
  volatile float sink = total;
  (void)sink;
  return 2.0 * kChains * kWidth * double(kIterations) * threads / best;
}

// The spring kernel's costly pair on L1-resident data: len = sqrt(d2); inv = 1 / len.
double sqrt_div_rate(int threads) {
  constexpr int kLength = 1024;
  constexpr int kPasses = 20000;
  double best = INFINITY;
  float total = 0.0f;
  for (int r = 0; r < kRepeats; ++r) {
    Stopwatch clock;
#pragma omp parallel num_threads(threads) reduction(+ : total)
    {
      alignas(64) float in[kLength], out[kLength];
      for (int i = 0; i < kLength; ++i) in[i] = 1.0f + 0.001f * float(i);
      for (int p = 0; p < kPasses; ++p) {
#pragma omp simd
        for (int i = 0; i < kLength; ++i) {
          const float len = std::sqrt(in[i]);
          out[i] = len > 0.0f ? 1.0f / len : 0.0f;
        }
        in[p % kLength] += out[(p * 7) % kLength] * 1e-9f;  // keeps the passes dependent
      }
      total += out[kLength / 2];
    }
    best = std::min(best, clock.seconds());
  }
  volatile float sink = total;
  (void)sink;
  return double(kLength) * kPasses * threads / best;
}

}  // namespace

MachineLimits measure_machine_limits(int threads) {
  return {copy_rate(threads), fma_rate(threads), sqrt_div_rate(threads)};
}

}  // namespace clothlab::bench
