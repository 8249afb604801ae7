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
// times (as a real display has) that still adds up to the same total; the solver's steps cost
// 10 us each (far below its share of any of these frames).
std::unique_ptr<Solver> run_at(double fps, double seconds) {
  auto solver = make_solver(hanging());
  const FrameStepper stepper;
  const int frames = static_cast<int>(seconds * fps + 0.5);
  double clock = 0.0, last = 0.0;
  for (int f = 1; f <= frames; ++f) {
    clock = f / fps + (f < frames ? 0.2 / fps * ((f % 3) - 1) : 0.0);
    const double wall = clock - last;
    const FrameAdvance a = stepper.advance(*solver, wall, stepper.cap(wall, 1e-5, solver->dt()));
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

// A frame of a whole second (a software renderer drawing slowly) still gets every step real
// time asks for when the solver is cheap: its speed never depends on the drawing's.
TEST(FrameStepper, ASlowFrameWithCheapStepsKeepsRealTime) {
  const auto owner = make_solver(hanging());  // dt = 0.5 ms
  const FrameStepper stepper;
  const FrameCap cap = stepper.cap(1.0, 1e-6, owner->dt());  // 1 us per step: 2 ms of work
  const FrameAdvance a = stepper.advance(*owner, 1.0, cap);
  EXPECT_FALSE(a.capped);
  EXPECT_EQ(a.steps, 2000);
  EXPECT_EQ(a.dropped_seconds, 0.0);
}

// A solver slower than its share of real time takes half the frame's wall time and no more,
// and the frame says that the solver held it back.
TEST(FrameStepper, ASolverSlowerThanRealTimeIsCappedAndSaysSo) {
  const auto owner = make_solver(hanging());
  Solver& solver = *owner;
  const FrameStepper stepper;
  // 1 ms per 0.5 ms step (half real time); a 0.1 s frame: 0.05 s of solver time, 50 steps.
  const FrameAdvance a = stepper.advance(solver, 0.1, stepper.cap(0.1, 1e-3, solver.dt()));
  EXPECT_TRUE(a.capped);
  EXPECT_EQ(a.limit, FrameLimit::solver);
  EXPECT_EQ(a.steps, 50);
  EXPECT_NEAR(a.dropped_seconds, 0.075, 1e-12);
  // A new solver's cost is not known: one step, to measure it.
  const FrameAdvance first = stepper.advance(solver, 0.1, stepper.cap(0.1, 0.0, solver.dt()));
  EXPECT_EQ(first.limit, FrameLimit::unknown);
  EXPECT_EQ(first.steps, 1);
  // After a stall of 10 s the frame makes up for 2 s, no more.
  const FrameAdvance stalled = stepper.advance(solver, 10.0, stepper.cap(10.0, 1e-6, solver.dt()));
  EXPECT_EQ(stalled.limit, FrameLimit::stall);
  EXPECT_EQ(stalled.steps, 4000);
  EXPECT_NEAR(stalled.dropped_seconds, 8.0, 1e-12);
}

// Where the drawing is quick, the solver may take more than half a frame as long as the frame
// stays within 1/20 s; where it is slow, half the frame still holds.
TEST(FrameStepper, TheSolverMayFillAFrameOfATwentiethOfASecond) {
  const FrameStepper stepper;
  const double dt = 1.0 / 60.0, step = 0.0098;  // large_sheet in the window on llvmpipe
  // A 49.4 ms frame that drew for 20 ms: 30 ms left of 50, three steps (half the frame: two).
  EXPECT_EQ(stepper.cap(0.0494, step, dt, 0.020).seconds, 3 * dt);
  EXPECT_EQ(stepper.cap(0.0494, step, dt).seconds, 2 * dt);
  // Drawing 40 ms leaves 10 ms of 50; half of a 60 ms frame is more: three steps.
  EXPECT_EQ(stepper.cap(0.060, step, dt, 0.040).seconds, 3 * dt);
  // Drawing 80 ms leaves nothing: half the frame, 9 steps of its 90 ms.
  EXPECT_EQ(stepper.cap(0.090, 0.005, dt, 0.080).seconds, 9 * dt);
  EXPECT_EQ(stepper.cap(0.090, 0.005, dt, 0.080).limit, FrameLimit::solver);
}

// What the solver's budget dropped the next frames ask for again, up to kMaxOwed, each a tenth
// of its own time at most; a stall's or a new solver's dropped time is not owed. A solver that
// catches up takes the owed steps within its budget: the frames together keep real time.
TEST(FrameStepper, TimeTheBudgetDroppedIsOwedToTheNextFrames) {
  const auto owner = make_solver(hanging());
  Solver& solver = *owner;
  const FrameStepper stepper;
  const double dt = solver.dt();
  // 1 ms a 0.5 ms step: a 0.2 s frame whose drawing took 0.19 s gets 100 steps (half of it),
  // 50 ms: 150 ms dropped and owed.
  const FrameAdvance short_of = stepper.advance(solver, 0.2, stepper.cap(0.2, 1e-3, dt, 0.19));
  EXPECT_NEAR(short_of.dropped_seconds, 0.15, 1e-12);
  double owed = FrameStepper::owed_after(0.0, 0.0, short_of);
  EXPECT_NEAR(owed, 0.15, 1e-12);
  // The next 20 ms frame asks for a tenth of its time beyond it: 2 ms of the 150.
  const double asked = FrameStepper::catch_up(owed, 0.02);
  EXPECT_NEAR(asked, 0.002, 1e-15);
  // It drew quickly (0.01 s) and the host ran the step at 0.2 ms again: 40 ms of budget, room
  // for its 22 ms; 148 ms still owed.
  const FrameAdvance next =
      stepper.advance(solver, 0.02 + asked, stepper.cap(0.02, 0.2e-3, dt, 0.01));
  EXPECT_EQ(next.steps, 44);
  EXPECT_FALSE(next.capped);
  owed = FrameStepper::owed_after(owed, asked, next);
  EXPECT_NEAR(owed, 0.148, 1e-12);
  // Frames with room pay it all back, a tenth of their time each: 74 frames of 20 ms.
  int frames = 0;
  while (owed > 0.0 && frames < 1000) {
    const double a = FrameStepper::catch_up(owed, 0.02);
    owed = FrameStepper::owed_after(
        owed, a, stepper.advance(solver, 0.02 + a, stepper.cap(0.02, 1e-6, dt, 0.001)));
    ++frames;
  }
  EXPECT_EQ(owed, 0.0);
  EXPECT_EQ(frames, 74);
  // The debt stops at kMaxOwed: a solver slower than real time owes that much for good.
  const FrameAdvance far_short = stepper.advance(solver, 5.0, stepper.cap(1.9, 1e-3, dt, 1.8));
  EXPECT_EQ(FrameStepper::owed_after(0.5, 0.0, far_short), FrameStepper::kMaxOwed);
  // A stall's dropped time is given up, and with it what was owed.
  const FrameAdvance stalled = stepper.advance(solver, 10.0, stepper.cap(10.0, 1e-6, dt));
  EXPECT_EQ(stalled.limit, FrameLimit::stall);
  EXPECT_EQ(FrameStepper::owed_after(0.5, 0.0, stalled), 0.0);
}

// A new solver's cost is timed on its first steps (probe_step_cost): the cold first step is left
// out, the probe stops at the frame's solver share or the step count asked, and a solver that
// fails (a divergence) stops it at once.
TEST(FrameStepper, ANewSolversCostIsTimedOnItsFirstSteps) {
  // 5 ms cold, then 0.1 ms a step: 8 steps within a 20 ms share, cost 0.1 ms.
  int calls = 0;
  StepCostProbe p =
      probe_step_cost(0.02, FrameStepper::kCostSteps, [&] { return calls++ == 0 ? 5e-3 : 1e-4; });
  EXPECT_EQ(p.steps, 8);
  EXPECT_NEAR(p.cost, 1e-4, 1e-15);
  EXPECT_NEAR(p.seconds, 5e-3 + 7e-4, 1e-15);
  // A step slower than the share: that one step, and it is the cost.
  p = probe_step_cost(0.02, FrameStepper::kCostSteps, [] { return 0.03; });
  EXPECT_EQ(p.steps, 1);
  EXPECT_EQ(p.cost, 0.03);
  // 8 ms a step: the share is spent after three.
  p = probe_step_cost(0.02, FrameStepper::kCostSteps, [] { return 8e-3; });
  EXPECT_EQ(p.steps, 3);
  // Fewer steps fit the frame's real time than kCostSteps; a failed step ends the probe.
  EXPECT_EQ(probe_step_cost(1.0, 2, [] { return 1e-4; }).steps, 2);
  calls = 0;
  EXPECT_EQ(probe_step_cost(1.0, 8, [&] { return calls++ < 3 ? 1e-4 : -1.0; }).steps, 3);
}

TEST(FrameStepper, PausedAndSlowMotion) {
  const auto owner = make_solver(hanging());
  Solver& solver = *owner;
  const FrameStepper stepper;
  const FrameCap cap = stepper.cap(0.2, 1e-6, solver.dt());
  EXPECT_EQ(stepper.advance(solver, 0.2, cap, true).steps, 0);
  EXPECT_EQ(stepper.advance(solver, 0.02 * 0.25, cap).steps, 10);  // 5 ms simulated
}

}  // namespace
}  // namespace clothlab
