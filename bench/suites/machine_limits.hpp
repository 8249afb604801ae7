// What this machine can do at best, measured by the same command that measures the solver, so a
// table can say how far a kernel is from the limit: a STREAM-like copy (McCalpin's "copy" kernel:
// bytes read + bytes written per second), a fused multiply-add loop with enough independent
// accumulators to fill the vector pipes, and the square root + division pair every spring needs.
#pragma once

namespace clothlab::bench {

struct MachineLimits {
  double copy_bytes_per_s = 0.0;  // B/s, arrays far larger than the caches
  double flops_per_s = 0.0;       // single-precision FMA = 2 flops
  double sqrt_div_per_s = 0.0;    // (sqrt, divide) pairs per second, single precision
};

MachineLimits measure_machine_limits(int threads);

}  // namespace clothlab::bench
