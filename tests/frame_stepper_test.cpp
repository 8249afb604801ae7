// Simulated time in a view follows real time, not the frame rate: frames at 30 and at 144 frames
// per second over the same two seconds of a fake clock take the same steps to the same state.
#include "sim/realtime/frame_stepper.hpp"

#include <gtest/gtest.h>

#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

Scene hanging() {
  Scene s = testing::sheet(12, 1.0, 0.3, 400.0, IntegratorKind::symplectic_euler, 5e-4);
  s.cloths[0].pins = {{0, 0}, {11, 0}};
  s.springs.damping = 0.02;
  s.solver.precision = Precision::f64;
  return s;
}

// Runs `seconds` of a fake clock at `fps` frames per second, with a little jitter in the frame
// times (as a real display has) that still adds up to the same total.
std::unique_ptr<Solver> run_at(double fps, double seconds) {
  auto solver = make_solver(hanging());
  const FrameStepper stepper;
  const int frames = static_cast<int>(seconds * fps + 0.5);
  double clock = 0.0, last = 0.0;
  for (int f = 1; f <= frames; ++f) {
    clock = f / fps + (f < frames ? 0.2 / fps * ((f % 3) - 1) : 0.0);
    const FrameAdvance a = stepper.advance(*solver, clock - last);
    EXPECT_FALSE(a.capped);
    last = clock;
  }
  return solver;
}

TEST(FrameStepper, ThirtyAndHundredFortyFourFramesPerSecondGiveTheSameMotion) {
  const auto slow = run_at(30.0, 2.0), fast = run_at(144.0, 2.0);
  EXPECT_EQ(slow->step_count(), 4000);
  EXPECT_EQ(fast->step_count(), slow->step_count());
  for (int v : {0, 60, 143}) EXPECT_EQ(fast->position(v), slow->position(v));
  EXPECT_NE(slow->position(143), hanging().cloths[0].origin);  // it did move
}

TEST(FrameStepper, SlowFramesAreCappedAndReportTheDroppedTime) {
  const auto owner = make_solver(hanging());
  Solver& solver = *owner;
  const FrameStepper stepper(100);
  const FrameAdvance a = stepper.advance(solver, 0.2);  // asks for 400 steps
  EXPECT_TRUE(a.capped);
  EXPECT_EQ(a.steps, 100);
  EXPECT_NEAR(a.dropped_seconds, 0.15, 1e-12);
  const FrameAdvance paused = stepper.advance(solver, 0.2, 1.0, true);
  EXPECT_EQ(paused.steps, 0);
  const FrameAdvance slow_motion = stepper.advance(solver, 0.02, 0.25);  // 5 ms simulated
  EXPECT_EQ(slow_motion.steps, 10);
}

}  // namespace
}  // namespace clothlab
