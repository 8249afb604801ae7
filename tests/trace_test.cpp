// Traces: the documented header, numbers that read back equal to the solver's values, the same
// bytes for any thread count, and no file at all when a run diverges.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/solver.hpp"
#include "sim/trace/csv_trace.hpp"
#include "sim/trace/trace_run.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

namespace fs = std::filesystem;

std::string temp_file(const std::string& name) {
  return (fs::temp_directory_path() /
          ("clothlab_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
           name))
      .string();
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A sheet with everything that touches the force pass switched on, large enough (40 x 40 =
// 1600 vertices) to span several parallel blocks.
Scene busy_scene() {
  // dt below the stability limit 0.654 sqrt(m / k0) = 5.8e-4 s (docs/design.md).
  Scene s = testing::sheet(40, 2.0, 1.0, 800.0, IntegratorKind::symplectic_euler, 4e-4);
  s.cloths[0].pins = {{0, 0}, {39, 0}};
  s.springs.damping = 0.05;
  s.forces.drag = 0.01;
  s.forces.wind = {true, {3.0, 0.0, 1.0}, 0.5, 7, 1.0, 1.0};
  TraceSpec t;
  t.vertices = {{0, 20, 39}, {0, 3, 7}};
  t.every = 5;
  s.trace = t;
  return s;
}

TEST(Trace, HeaderIsTheDocumentedOne) {
  TraceSpec all;
  all.vertices = {{0, 1, 1}};
  const std::vector<std::string> expected = {
      "step", "time", "vertex_i", "vertex_j", "px",      "py",      "pz",      "vx",   "vy",
      "vz",   "fx",   "fy",       "fz",       "kinetic", "elastic", "gravity", "total"};
  EXPECT_EQ(trace_columns(all, false), expected);
  auto multi = trace_columns(all, true);
  EXPECT_EQ(multi[2], "cloth");
  TraceSpec energy_only = all;
  energy_only.vertices.clear();
  const std::vector<std::string> energy_cols = {"step",    "time",    "vertex_i", "vertex_j",
                                                "kinetic", "elastic", "gravity",  "total"};
  EXPECT_EQ(trace_columns(energy_only, false), energy_cols);
}

TEST(Trace, ReadsBackTheSolverValues) {
  const Scene scene = busy_scene();
  const auto s_owner = testing::solver<float>(scene);
  Solver& s = *s_owner;
  const std::string path = temp_file("readback.csv");
  const auto r = run_trace(s, *scene.trace, false, false, whole_steps(0.1, s.dt()), path);
  ASSERT_FALSE(r.divergence);
  EXPECT_EQ(r.steps, 250);
  const TraceTable t = read_trace_csv(path);
  EXPECT_EQ(t.columns, trace_columns(*scene.trace, false));
  ASSERT_EQ(t.rows.size(), 2u * 51u);            // steps 0, 5, ..., 250, two vertices each
  const auto& last = t.rows[t.rows.size() - 2];  // vertex (20, 39) at step 250
  EXPECT_EQ(last[t.column("step")], 250.0);
  EXPECT_NEAR(last[t.column("time")], 0.1, 1e-12);
  EXPECT_EQ(last[t.column("vertex_i")], 20.0);
  const int v = s.vertex_index({0, 20, 39});
  s.update_force_field();
  const Energy e = s.energy();
  // %.9g round-trips a float exactly.
  EXPECT_EQ(float(last[t.column("px")]), float(s.position(v)[0]));
  EXPECT_EQ(float(last[t.column("py")]), float(s.position(v)[1]));
  EXPECT_EQ(float(last[t.column("vz")]), float(s.velocity(v)[2]));
  EXPECT_EQ(float(last[t.column("fy")]), float(s.force(v)[1]));
  EXPECT_NEAR(last[t.column("total")], e.total(), 1e-9 * std::abs(e.total()));
  EXPECT_NEAR(last[t.column("kinetic")] + last[t.column("elastic")] + last[t.column("gravity")],
              last[t.column("total")], 1e-6 * std::abs(e.total()));
  fs::remove(path);
}

TEST(Trace, ThreadCountDoesNotChangeTheTraceByteForByte) {
  for (SpringKernel kernel : {SpringKernel::row_sweep, SpringKernel::neighbour_list}) {
    std::string contents[2];
    for (int threads : {1, 2}) {
      Scene scene = busy_scene();
      scene.solver.threads = threads;
      const auto s_owner = testing::solver<float>(scene, kernel);
      Solver& s = *s_owner;
      ASSERT_EQ(s.threads(), threads);
      const std::string path = temp_file("threads" + std::to_string(threads) + ".csv");
      ASSERT_FALSE(
          run_trace(s, *scene.trace, false, false, whole_steps(0.3, s.dt()), path).divergence);
      contents[threads - 1] = slurp(path);
      fs::remove(path);
    }
    ASSERT_GT(contents[0].size(), 1000u);
    EXPECT_TRUE(contents[0] == contents[1])
        << "1- and 2-thread traces differ (kernel " << int(kernel) << ")";
  }
}

TEST(Trace, DivergedRunLeavesNoFile) {
  Scene scene = busy_scene();
  scene.solver.integrator = IntegratorKind::explicit_euler;
  scene.forces.wind.enabled = false;
  scene.springs.damping = 0.0;
  const auto s_owner = testing::solver<float>(scene);
  Solver& s = *s_owner;
  const std::string path = temp_file("diverged.csv");
  const auto r = run_trace(s, *scene.trace, false, false, whole_steps(5.0, s.dt()), path);
  ASSERT_TRUE(r.divergence);
  EXPECT_FALSE(fs::exists(path));
  for (const auto& entry : fs::directory_iterator(fs::temp_directory_path()))
    EXPECT_EQ(entry.path().string().find(path + ".tmp"), std::string::npos);
}

}  // namespace
}  // namespace clothlab
