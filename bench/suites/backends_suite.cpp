// `clothlab bench --suite backends`: the CPU solver against solver.backend = "gpu" (compute
// shaders) and "transform_feedback" (a vertex shader, gpu/tf_cloth.hpp) on the benchmark sheet
// (bench/bench_scenes.hpp, no wind), symplectic Euler in float, from 64x64 to 512x512 and with 1 to
// 16 copies of a 64x64 sheet side by side (sim/cloth/scene_copies.hpp, as the window's ]). Per
// step, the median of batches of about 20 ms; a GPU batch is one step() call, which ends with the
// read-back its divergence check needs, so its time is the work done, not the work queued. Per
// 1/60 s frame, the frame's substeps at that cost plus a step() call's own cost (the read-back and
// the CPU's checks: the median of single-step calls less the batched step); "substeps share" is
// the substeps' part of the frame. The renderer string and llvmpipe's thread count
// (LP_NUM_THREADS; unset: one per core) are printed: on Mesa's llvmpipe the "GPU" is the CPU
// running shaders, and a machine with a real GPU shows what the backend gains there.
#include <algorithm>
#include <cmath>
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

// One backend's figures on one scene: per substep, the median of batches of about 20 ms; per
// 1/60 s frame, the frame's substeps at that cost plus what one step() call costs beyond its
// substep (on the GPU the read-back of the state for the CPU's checks), the median of single
// step() calls less the batched substep.
struct BackendTiming {
  double step = 0.0, frame = 0.0;  // s
  long steps_per_frame = 0;
};

BackendTiming time_backend(Solver& solver, double seconds) {
  BackendTiming t;
  const auto run = [&](long steps) {
    if (!solver.step(steps).ok()) throw std::runtime_error("the run diverged");
  };
  t.step = median_seconds_per_step(run, seconds);
  const double call = median_seconds_per_step(
      [&](long calls) {
        for (long c = 0; c < calls; ++c) run(1);
      },
      seconds);
  t.steps_per_frame = std::max(1L, std::lround(std::ceil(1.0 / 60.0 / solver.dt() - 1e-9)));
  t.frame = double(t.steps_per_frame) * t.step + std::max(0.0, call - t.step);
  return t;
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
      "CPU, GPU compute and GPU transform-feedback backends: symplectic Euler, float, the "
      "benchmark sheet without wind; GPU: " +
      context.renderer() + (llvmpipe ? ", LP_NUM_THREADS=" + gpu_threads : std::string());
  t.columns = {"backend",     "threads",      "sheet",         "copies",
               "vertices",    "springs",      "ms per step",   "ns per spring-step",
               "steps per s", "ms per frame", "substeps share"};
  auto add = [&](const std::string& name, const std::string& threads, int res, int copies,
                 Solver& solver) {
    const BackendTiming m = time_backend(solver, seconds);
    const double substeps = double(m.steps_per_frame) * m.step;
    t.add({name, threads, std::to_string(res) + "x" + std::to_string(res), std::to_string(copies),
           std::to_string(solver.vertex_count()), std::to_string(solver.spring_count()),
           fixed(1e3 * m.step, 3), fixed(1e9 * m.step / double(solver.spring_count()), 2),
           fixed(1.0 / m.step, 0), fixed(1e3 * m.frame, 2),
           fixed(std::min(1.0, substeps / m.frame), 2)});
    if (o.log) *o.log << "  " << name << " " << res << "^2 x" << copies << "\n";
  };
  auto measure = [&](int res, int copies) {
    for (int threads : {1, 2}) {
      const auto cpu = make_solver(sheets(res, copies, threads));
      add("cpu", std::to_string(threads), res, copies, *cpu);
    }
    for (Backend b : {Backend::gpu, Backend::transform_feedback}) {
      Scene scene = sheets(res, copies, 1);
      scene.solver.backend = b;
      const auto solver = gpu::make_gpu_solver(scene);
      add(to_string(b), gpu_threads, res, copies, *solver);
    }
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
