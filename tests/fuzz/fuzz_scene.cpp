// Scene text through the parser, the validator, the load step, the solver and the trace writer.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "load/scene_load.hpp"
#include "sim/model/memory_estimate.hpp"
#include "sim/scene/scene_error.hpp"
#include "sim/solver.hpp"
#include "sim/trace/csv_trace.hpp"
#include "sim/trace/trace_run.hpp"
#include "tests/fuzz/fuzz_targets.hpp"

namespace clothlab::fuzz {
namespace {

// Scenes beyond these are parsed and validated only (a fuzzer's -rss_limit and timeout): a
// 4000 x 4000 cloth is a valid input that takes gigabytes and seconds to build.
constexpr double kMaxVertices = 4096;
constexpr std::uint64_t kMaxBytes = 64u << 20;
constexpr long kSteps = 4;

void check_finite_state(Solver& solver, const char* when) {
  for (std::size_t v = 0; v < solver.vertex_count(); ++v) {
    const Vec3d p = solver.position(int(v)), u = solver.velocity(int(v));
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(p[a]) || !std::isfinite(u[a]))
        finding(std::string("vertex ") + std::to_string(v) + " is not finite " + when +
                " and no divergence was reported");
  }
}

// A trace that was written holds finite numbers only.
void check_trace(Solver& solver, const Scene& scene) {
  const std::string path = context().scratch_dir + "/fuzz_trace.csv";
  std::filesystem::remove(path);
  const TraceSpec spec = scene.trace ? *scene.trace : default_trace(scene);
  const TraceRunResult r = run_trace(solver, spec, scene.multi_cloth, false, kSteps, path);
  if (r.divergence) {
    if (std::filesystem::exists(path)) finding("a diverged trace was written");
    return;
  }
  for (const auto& row : read_trace_csv(path).rows)
    for (double x : row)
      if (!std::isfinite(x)) finding("the written trace holds a non-finite number");
  check_finite_state(solver, "after the trace");
}

}  // namespace

int fuzz_scene(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Scene scene;
  try {
    scene = read_scene_string(text, context().scene_dir + "/fuzz.toml");
  } catch (const SceneError&) {
    return 0;  // refused with its location: what bad input must get
  }
  if (scene_vertices(scene) > kMaxVertices || estimated_solver_bytes(scene) > kMaxBytes) return 0;
  if (scene.solver.backend != Backend::cpu) scene.solver.backend = Backend::cpu;
  std::unique_ptr<Solver> solver;
  try {
    solver = make_solver(scene);
  } catch (const SceneError&) {
    return 0;  // a built state the solver cannot hold, refused
  }
  check_trace(*solver, scene);
  return 0;
}

}  // namespace clothlab::fuzz
