// `clothlab bench --suite backends`: the CPU solver against the GPU compute backend
// (vis/gpu/gpu_cloth.hpp) on the benchmark sheet (bench/bench_scenes.hpp, without wind: the GPU
// backend has none yet), symplectic Euler in float, from 64x64 to 512x512 and with 1 to 16 copies
// of a 64x64 sheet side by side. Per step, the median of batches of about 20 ms; the GPU's
// batches end with glFinish, so its time is the work done, not the work queued. The renderer
// string is printed: on Mesa's llvmpipe the "GPU" is the CPU running shaders, and a machine with
// a real GPU shows what the backend gains there.
#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

#include "bench/bench_scenes.hpp"
#include "bench/suites/step_timing.hpp"
#include "bench/suites/suites.hpp"
#include "sim/solver_impl.hpp"
#include "vis/gl/headless_context.hpp"
#include "vis/gpu/gpu_cloth.hpp"

namespace clothlab::bench {
namespace {

// `copies` sheets of res x res, 2.2 m apart along x: the same cloth simulated side by side.
Scene sheets(int res, int copies, int threads) {
  Scene s = sheet_scene(res, threads, false);
  const ClothSpec one = s.cloths.front();
  s.cloths.clear();
  for (int k = 0; k < copies; ++k) {
    ClothSpec c = one;
    c.origin[0] += 2.2 * k;
    c.key = "cloth[" + std::to_string(k) + "]";
    s.cloths.push_back(c);
  }
  s.multi_cloth = copies > 1;
  return s;
}

}  // namespace

std::vector<Table> backends_suite(const SuiteOptions& o) {
  vis::HeadlessContext context;
  const double seconds = o.quick ? 0.05 : 0.5;
  Table t;
  t.title =
      "CPU and GPU backends: symplectic Euler, float, the benchmark sheet without wind; GPU: " +
      context.renderer();
  t.columns = {"backend",  "threads", "sheet",       "copies",
               "vertices", "springs", "ms per step", "ns per spring-step"};
  auto measure = [&](int res, int copies) {
    for (int threads : {1, 2}) {
      SolverT<float> cpu(sheets(res, copies, threads));
      const double s = seconds_per_step(cpu, seconds);
      t.add({"cpu", std::to_string(threads), std::to_string(res) + "x" + std::to_string(res),
             std::to_string(copies), std::to_string(cpu.vertex_count()),
             std::to_string(cpu.spring_count()), fixed(1e3 * s, 3),
             fixed(1e9 * s / double(cpu.spring_count()), 2)});
      if (o.log) *o.log << "  cpu " << res << "^2 x" << copies << ", " << threads << " thread(s)\n";
    }
    // The GPU gathers over the neighbour list: its model and initial state come from a CPU
    // solver built with that kernel (one step of dt, no substeps, in the benchmark sheet).
    SolverT<float> ref(sheets(res, copies, 1), SpringKernel::neighbour_list);
    vis::GpuCloth gpu(ref.model(), ref.state().pos, ref.state().vel);
    const auto h = static_cast<float>(ref.dt() / ref.substeps());
    const double s = median_seconds_per_step(
        [&](long steps) {
          gpu.step(static_cast<int>(steps), h, IntegratorKind::symplectic_euler);
          gpu.finish();  // the work done, not the work queued
        },
        seconds);
    t.add({"gpu", "-", std::to_string(res) + "x" + std::to_string(res), std::to_string(copies),
           std::to_string(ref.vertex_count()), std::to_string(ref.spring_count()),
           fixed(1e3 * s, 3), fixed(1e9 * s / double(ref.spring_count()), 2)});
    if (o.log) *o.log << "  gpu " << res << "^2 x" << copies << "\n";
  };
  const std::vector<int> sizes =
      o.quick ? std::vector<int>{32} : std::vector<int>{64, 128, 256, 512};
  for (int res : sizes) measure(res, 1);
  const std::vector<int> copies = o.quick ? std::vector<int>{2} : std::vector<int>{4, 16};
  for (int n : copies) measure(o.quick ? 32 : 64, n);
  return {t};
}

}  // namespace clothlab::bench
