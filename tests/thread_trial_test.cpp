// The window's automatic thread count (sim/realtime/thread_trial.hpp): a trial of both settings
// keeps the faster per step, by a margin for the parallel one, skips each side's warm-up frame
// and paused frames, and tries again after kRetrialSeconds.
#include <gtest/gtest.h>

#include "sim/realtime/thread_trial.hpp"

namespace clothlab {
namespace {

// Feeds frames of `steps` steps at `cost` seconds per step while the trial asks for `threads`,
// one frame per 1/60 s from `now`, until it asks for something else or `frames` have passed;
// returns the time reached.
double run_trial(ThreadTrial& trial, int threads, double cost, int frames, double now) {
  for (int f = 0; f < frames && trial.threads() == threads; ++f) {
    trial.record(10, 10 * cost, now);
    now += 1.0 / 60.0;
  }
  return now;
}

// Both sides' frames at the given costs until the trial decides.
double decide(ThreadTrial& trial, double serial, double parallel, double now) {
  for (int f = 0; f < 100 && trial.trying(); ++f) {
    trial.record(10, 10 * (trial.threads() == 1 ? serial : parallel), now);
    now += 1.0 / 60.0;
  }
  return now;
}

TEST(ThreadTrial, KeepsTheParallelStepWhereItIsFaster) {
  ThreadTrial trial(0);
  EXPECT_EQ(trial.threads(), 1);  // one thread first
  decide(trial, 1e-3, 0.5e-3, 0.0);
  EXPECT_FALSE(trial.trying());
  EXPECT_EQ(trial.threads(), 0);
  EXPECT_DOUBLE_EQ(trial.serial_cost(), 1e-3);
  EXPECT_DOUBLE_EQ(trial.parallel_cost(), 0.5e-3);
}

// A busy machine: the parallel step 20x slower (as measured beside another process) loses.
TEST(ThreadTrial, KeepsOneThreadWhereTheParallelStepIsSlower) {
  ThreadTrial trial(2);
  decide(trial, 0.14e-3, 2.8e-3, 0.0);
  EXPECT_EQ(trial.threads(), 1);
}

// Within the margin the serial step stays: the parallel one must be clearly faster.
TEST(ThreadTrial, TheParallelStepMustWinByTheMargin) {
  ThreadTrial just(0), clearly(0);
  decide(just, 1e-3, 1e-3 / 1.05, 0.0);
  decide(clearly, 1e-3, 1e-3 / 1.2, 0.0);
  EXPECT_EQ(just.threads(), 1);
  EXPECT_EQ(clearly.threads(), 0);
}

// The first frame after each switch (threads waking) and frames without steps are not counted.
TEST(ThreadTrial, SkipsWarmUpAndPausedFrames) {
  ThreadTrial trial(0);
  trial.record(10, 1.0, 0.0);  // serial warm-up: 0.1 s a step, ignored
  trial.record(0, 0.5, 0.0);   // paused
  for (int f = 0; f < ThreadTrial::kFramesPerSide; ++f) trial.record(10, 10e-3, 0.0);
  ASSERT_EQ(trial.threads(), 0);
  trial.record(10, 1.0, 0.0);  // parallel warm-up, ignored
  for (int f = 0; f < ThreadTrial::kFramesPerSide; ++f) trial.record(10, 5e-3, 0.0);
  EXPECT_FALSE(trial.trying());
  EXPECT_DOUBLE_EQ(trial.serial_cost(), 1e-3);
  EXPECT_DOUBLE_EQ(trial.parallel_cost(), 0.5e-3);
  EXPECT_EQ(trial.threads(), 0);
}

// A host that pauses the process for one frame of a side does not decide the trial: each side
// counts its fastest frame. large_sheet in the window: serial 16 ms a step, parallel 10 ms with
// one frame of four held up to 30 ms, whose mean (15 ms) would have kept one thread.
TEST(ThreadTrial, AFrameTheHostHeldUpDoesNotDecide) {
  ThreadTrial trial(0);
  trial.record(1, 20e-3, 0.0);  // serial warm-up
  for (int f = 0; f < ThreadTrial::kFramesPerSide; ++f) trial.record(2, 32e-3, 0.0);
  ASSERT_EQ(trial.threads(), 0);
  trial.record(2, 40e-3, 0.0);  // parallel warm-up
  for (double seconds : {20e-3, 20e-3, 60e-3, 20e-3}) trial.record(2, seconds, 0.0);
  EXPECT_FALSE(trial.trying());
  EXPECT_DOUBLE_EQ(trial.parallel_cost(), 10e-3);
  EXPECT_EQ(trial.threads(), 0);
  EXPECT_EQ(trial.retrial_seconds(), ThreadTrial::kRetrialSeconds);  // a first clear win
}

// The load changes: after kRetrialSeconds the trial runs again and follows the new costs.
TEST(ThreadTrial, TriesAgainWhenTheLoadMayHaveChanged) {
  ThreadTrial trial(0);
  double now = decide(trial, 1e-3, 0.5e-3, 0.0);
  ASSERT_EQ(trial.threads(), 0);
  now = run_trial(trial, 0, 0.5e-3, 60, now);  // a second later: still decided
  EXPECT_FALSE(trial.trying());
  now = run_trial(trial, 0, 0.5e-3, int(60 * ThreadTrial::kRetrialSeconds), now);
  EXPECT_TRUE(trial.trying());
  EXPECT_EQ(trial.threads(), 1);
  decide(trial, 1e-3, 5e-3, now);  // another process now holds a core
  EXPECT_EQ(trial.threads(), 1);
}

// A side that keeps winning clearly is tried again less often: the wait doubles with each clear
// win of the same side (10, 20, 40, 80 s, no more), and a close or changed outcome sets it back.
TEST(ThreadTrial, AClearWinnerIsTriedAgainLessOften) {
  ThreadTrial trial(0);
  double now = decide(trial, 1.6e-3, 1e-3, 0.0);  // large_sheet in the window: 16 against 10 ms
  EXPECT_EQ(trial.retrial_seconds(), ThreadTrial::kRetrialSeconds);
  for (double wait : {20.0, 40.0, 80.0, 80.0}) {
    now = run_trial(trial, 0, 1e-3, 100000, now);  // until the next trial starts
    EXPECT_EQ(trial.threads(), 1);
    now = decide(trial, 1.6e-3, 1e-3, now);
    EXPECT_EQ(trial.threads(), 0);
    EXPECT_EQ(trial.retrial_seconds(), wait);
  }
  // A close outcome (the parallel step only 1.2x faster) sets the wait back.
  now = run_trial(trial, 0, 1e-3, 100000, now);
  now = decide(trial, 1.2e-3, 1e-3, now);
  EXPECT_EQ(trial.threads(), 0);
  EXPECT_EQ(trial.retrial_seconds(), ThreadTrial::kRetrialSeconds);
  // So does a clear win of the other side.
  now = decide(trial, 1e-3, 2e-3, run_trial(trial, 0, 1e-3, 100000, now));
  now = decide(trial, 1e-3, 2e-3, run_trial(trial, 1, 1e-3, 100000, now));
  EXPECT_EQ(trial.threads(), 1);
  EXPECT_EQ(trial.retrial_seconds(), 2.0 * ThreadTrial::kRetrialSeconds);
}

}  // namespace
}  // namespace clothlab
