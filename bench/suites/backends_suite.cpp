// `clothlab bench --suite backends`: the CPU solver against solver.backend = "gpu"
// (gpu/backend_solver.hpp) on the benchmark sheet (bench/bench_scenes.hpp, no wind), symplectic
// Euler in float, from 64x64 to 512x512 and with 1 to 16 copies of a 64x64 sheet side by side
// (sim/cloth/scene_copies.hpp, as the window's ]). Per step, the median of batches of about 20 ms;
// a GPU batch is one step() call, which ends with the read-back its divergence check needs, so its
// time is the work done, not the work queued. The renderer string and llvmpipe's thread count
// (LP_NUM_THREADS; unset: one per core) are printed: on Mesa's llvmpipe the "GPU" is the CPU
// running shaders, and a machine with a real GPU shows what the backend gains there.
#include <algorithm>
#include <cstdlib>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_scenes.hpp"
#include "bench/suites/step_timing.hpp"
#include "bench/suites/suites.hpp"
#include "gl/headless_context.hpp"
#include "gpu/backend_solver.hpp"
#include "sim/cloth/scene_copies.hpp"
#include "sim/solver.hpp"

namespace clothlab::bench {
namespace {

// `copies` sheets of res x res, 2.2 m apart: the same cloth simulated side by side.
Scene sheets(int res, int copies, int threads) {
  return with_copies(sheet_scene(res, threads, false), copies, 2.2);
}

}  // namespace

std::vector<Table> backends_suite(const SuiteOptions& o) {
  vis::HeadlessContext context;
  const double seconds = o.quick ? 0.05 : 0.5;
  Table t;
  const char* lp_threads = std::getenv("LP_NUM_THREADS");
  const bool llvmpipe = context.renderer().find("llvmpipe") != std::string::npos;
  const std::string gpu_threads = !llvmpipe ? "-" : lp_threads ? lp_threads : "cores";
  t.title =
      "CPU and GPU backends: symplectic Euler, float, the benchmark sheet without wind; GPU: " +
      context.renderer() + (llvmpipe ? ", LP_NUM_THREADS=" + gpu_threads : std::string());
  t.columns = {"backend",  "threads", "sheet",       "copies",
               "vertices", "springs", "ms per step", "ns per spring-step"};
  auto measure = [&](int res, int copies) {
    for (int threads : {1, 2}) {
      const auto cpu_owner = make_solver(sheets(res, copies, threads));
      Solver& cpu = *cpu_owner;
      const double s = seconds_per_step(cpu, seconds);
      t.add({"cpu", std::to_string(threads), std::to_string(res) + "x" + std::to_string(res),
             std::to_string(copies), std::to_string(cpu.vertex_count()),
             std::to_string(cpu.spring_count()), fixed(1e3 * s, 3),
             fixed(1e9 * s / double(cpu.spring_count()), 2)});
      if (o.log) *o.log << "  cpu " << res << "^2 x" << copies << ", " << threads << " thread(s)\n";
    }
    Scene scene = sheets(res, copies, 1);
    scene.solver.backend = Backend::gpu;
    const auto gpu_solver = gpu::make_gpu_solver(scene);
    Solver& gpu = *gpu_solver;
    const double s = median_seconds_per_step(
        [&](long steps) {
          if (!gpu.step(steps).ok()) throw std::runtime_error("the GPU backend diverged");
        },
        seconds);
    t.add({"gpu", gpu_threads, std::to_string(res) + "x" + std::to_string(res),
           std::to_string(copies), std::to_string(gpu.vertex_count()),
           std::to_string(gpu.spring_count()), fixed(1e3 * s, 3),
           fixed(1e9 * s / double(gpu.spring_count()), 2)});
    if (o.log) *o.log << "  gpu " << res << "^2 x" << copies << "\n";
  };
  const std::vector<int> sizes =
      o.quick ? std::vector<int>{32} : std::vector<int>{64, 128, 256, 512};
  for (int res : sizes) measure(res, 1);
  const std::vector<int> copies = o.quick ? std::vector<int>{2} : std::vector<int>{4, 16};
  for (int n : copies) measure(o.quick ? 32 : 64, n);
  t.note = quick_note(o.quick,
                      "sheets of 64 to 512 (32x32 only), 4 and 16 copies of 64x64 (2 of "
                      "32x32); 0.05 s per measurement instead of 0.5 s");
  return {t};
}

}  // namespace clothlab::bench
