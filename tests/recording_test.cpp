// The window's Record (SimSession, no GL): while recording, every step the session takes is
// written (every N-th with the trace's `every`), the file appears only when recording stops,
// complete, and a session that ends without stopping leaves no file behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "apps/view/sim_session.hpp"
#include "sim/trace/csv_trace.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

namespace fs = std::filesystem;

Scene small_sheet() {
  Scene s = testing::sheet(8, 1.0, 0.2, 200.0, IntegratorKind::symplectic_euler, 1e-3);
  s.cloths[0].pins = {{0, 0}, {7, 0}};
  return s;
}

std::string temp_path(const std::string& name) {
  return (fs::temp_directory_path() / ("clothlab_recording_test_" + name)).string();
}

TEST(Recording, WritesEveryStepTakenAndAppearsOnlyWhenStopped) {
  const std::string path = temp_path("every.csv");
  fs::remove(path);
  vis::SimSession session(small_sheet());
  TraceSpec spec;
  spec.vertices = {{0, 3, 7}, {0, 4, 7}};
  spec.every = 5;
  session.start_recording(path, spec);
  EXPECT_TRUE(session.recording());
  const FrameStepper stepper;
  long steps = 0;
  for (int frame = 0; frame < 10; ++frame) steps += session.advance(stepper, 1.0 / 60.0).steps;
  session.single_step();
  ++steps;
  EXPECT_EQ(steps, 167);  // 10 frames of 1/60 s at 1 ms (whole steps), one more by hand
  EXPECT_FALSE(fs::exists(path)) << "the file must not appear before it is complete";
  const std::string summary = session.stop_recording();
  EXPECT_FALSE(session.recording());
  ASSERT_TRUE(fs::exists(path));
  // The starting state and every 5th step after it, two vertex rows each.
  const long written = steps / 5 + 1;
  EXPECT_EQ(summary, "recorded " + std::to_string(2 * written) + " rows to " + path);
  const TraceTable t = read_trace_csv(path);
  ASSERT_EQ(static_cast<long>(t.rows.size()), 2 * written);
  const int step = t.column("step"), i = t.column("vertex_i"), time = t.column("time");
  ASSERT_GE(step, 0);
  for (long r = 0; r < written; ++r) {
    EXPECT_EQ(t.rows[2 * r][step], 5.0 * r);
    EXPECT_NEAR(t.rows[2 * r][time], 5e-3 * r, 1e-12);
    EXPECT_EQ(t.rows[2 * r][i], 3.0);
    EXPECT_EQ(t.rows[2 * r + 1][i], 4.0);
  }
  // The first rows hold the state recording started from: the built sheet, bottom row at -1 m.
  EXPECT_DOUBLE_EQ(t.rows[0][t.column("py")], -1.0);
  EXPECT_DOUBLE_EQ(t.rows[0][t.column("vy")], 0.0);
  fs::remove(path);
}

TEST(Recording, ASessionEndingWhileRecordingLeavesNoPartialFile) {
  const std::string path = temp_path("abandoned.csv");
  fs::remove(path);
  {
    vis::SimSession session(small_sheet());
    session.start_recording(path, TraceSpec{{{0, 3, 7}}, true, true, true, false, 1});
    const FrameStepper stepper;
    session.advance(stepper, 0.05);
  }
  EXPECT_FALSE(fs::exists(path));
  for (const auto& entry : fs::directory_iterator(fs::temp_directory_path()))
    EXPECT_EQ(entry.path().filename().string().find("clothlab_recording_test_abandoned"),
              std::string::npos)
        << "temporary file left behind: " << entry.path();
}

TEST(Recording, AnUnwritablePathIsAnError) {
  vis::SimSession session(small_sheet());
  EXPECT_THROW(session.start_recording("/nonexistent-dir/x.csv", TraceSpec{}), std::exception);
  EXPECT_FALSE(session.recording());
}

}  // namespace
}  // namespace clothlab
