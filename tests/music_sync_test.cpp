// The audio clock as master of a view with music (music/music_clock.hpp): the simulation
// catches up to the playback position while the music plays, stands still while paused, follows
// the wall clock after the track's end, restarts the music with a new solver, and a machine that
// cannot keep up makes the music wait rather than the dance drift off the beat. No audio device:
// the playback positions are made up, as OpenAL would report them.
#include "music/music_clock.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/realtime/frame_stepper.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

constexpr double kTrack = 40.0;        // s
constexpr double kFrame = 1.0 / 60.0;  // s of wall time per frame
constexpr double kCap = 0.2;           // s, the stepper's cap (400 steps of 0.5 ms)

MusicReading at(double audio, double solver, long generation = 0, bool running = true) {
  return MusicReading{audio, solver, generation, running};
}

// A clock past its first plan (which seeks the music to the solver: the playback starts there).
MusicClock started() {
  MusicClock clock(kTrack);
  const MusicPlan first = clock.plan(at(0.0, 0.0), kFrame, kCap);
  EXPECT_EQ(first.seek, 0.0);
  EXPECT_TRUE(first.play);
  EXPECT_EQ(first.advance, 0.0);
  return clock;
}

TEST(MusicClock, WhilePlayingTheSimulationAdvancesByAudioMinusSolverTime) {
  MusicClock clock = started();
  // A playback that keeps time with the frames: each frame asks for exactly the audio's lead.
  for (int f = 1; f <= 120; ++f) {
    const double audio = f * kFrame, solver = audio - 0.004 * (f % 3);
    const MusicPlan p = clock.plan(at(audio, solver), kFrame, kCap);
    EXPECT_NEAR(p.advance, audio - solver, 1e-12) << "frame " << f;
    EXPECT_TRUE(p.on_audio);
    EXPECT_TRUE(p.play);
    EXPECT_FALSE(p.seek);
  }
  // A solver a fraction of a step ahead (the remainder it carries) asks for nothing, not less.
  EXPECT_EQ(clock.plan(at(121 * kFrame, 121 * kFrame + 2e-4), kFrame, kCap).advance, 0.0);
  // A jump of the playback (a stall of the device) is followed at once, not smoothed.
  EXPECT_NEAR(clock.plan(at(5.0, 2.0), kFrame, kCap).advance, 3.0, 1e-12);
}

// OpenAL Soft reports the position once per mixing period (1024 samples at 44.1 kHz): raw, that
// makes frames of 0 and 23 ms at 60 frames per second. The smoothed clock gives every frame
// close to its wall time and keeps the simulation within a period of the music.
TEST(MusicClock, APositionReportedInMixingPeriodsStillAdvancesEveryFrameEvenly) {
  MusicClock clock = started();
  const double period = 1024.0 / 44100.0;
  double solver = 0.0;
  for (int f = 1; f <= 600; ++f) {
    const double now = f * kFrame;
    const double reported = std::floor(now / period) * period;
    const MusicPlan p = clock.plan(at(reported, solver), kFrame, kCap);
    solver += p.advance;
    if (f > 30) {
      EXPECT_NEAR(p.advance, kFrame, 0.004) << "frame " << f;
      EXPECT_NEAR(solver, now - 0.5 * period, period) << "frame " << f;
    }
  }
}

TEST(MusicClock, PausedAdvancesNothingAndStopsTheMusic) {
  MusicClock clock = started();
  const MusicPlan p = clock.plan(at(3.0, 2.9, 0, false), kFrame, kCap);
  EXPECT_EQ(p.advance, 0.0);
  EXPECT_FALSE(p.play);
  EXPECT_FALSE(p.seek);
  // Single steps while paused move the solver alone: resuming brings the music to the solver.
  const MusicPlan resumed = clock.plan(at(3.0, 3.1), kFrame, kCap);
  EXPECT_EQ(resumed.seek, 3.1);
  EXPECT_TRUE(resumed.play);
  EXPECT_EQ(resumed.advance, 0.0);
}

TEST(MusicClock, AfterTheTrackEndsTheSimulationFollowsWallTime) {
  MusicClock clock = started();
  // OpenAL reports the track's length once it has played to the end.
  const MusicPlan p = clock.plan(at(kTrack, kTrack + 0.3), 0.02, kCap);
  EXPECT_EQ(p.advance, 0.02);
  EXPECT_FALSE(p.on_audio);
  EXPECT_FALSE(p.play);
  EXPECT_FALSE(p.seek);
  EXPECT_EQ(clock.plan(at(kTrack, kTrack + 0.32, 0, false), 0.02, kCap).advance, 0.0);  // paused
}

TEST(MusicClock, AResetSeeksTheMusicBackToTheNewSolversTime) {
  MusicClock clock = started();
  clock.plan(at(12.0, 12.0), kFrame, kCap);
  // R: a new solver at t = 0 (its generation counts up) while the music is at 12 s.
  const MusicPlan p = clock.plan(at(12.02, 0.0, 1), kFrame, kCap);
  EXPECT_EQ(p.seek, 0.0);
  EXPECT_TRUE(p.play);
  EXPECT_EQ(p.advance, 0.0);  // not 12 s of catching up
  // The next frames are in step again.
  EXPECT_NEAR(clock.plan(at(kFrame, 0.0, 1), kFrame, kCap).advance, kFrame, 1e-12);
  // A reset after the track's end starts the music again, and a reset while paused seeks it
  // without playing.
  clock.plan(at(kTrack, kTrack + 5.0, 1), kFrame, kCap);
  EXPECT_TRUE(clock.plan(at(kTrack, 0.0, 2), kFrame, kCap).play);
  const MusicPlan paused = clock.plan(at(3.0, 0.0, 3, false), kFrame, kCap);
  EXPECT_EQ(paused.seek, 0.0);
  EXPECT_FALSE(paused.play);
}

TEST(MusicClock, ALargeGapIsCappedByTheStepperAndTheMusicWaitsForTheSimulation) {
  MusicClock clock = started();
  // A gap within the cap plus the tolerated lag is caught up without touching the music.
  const MusicPlan small = clock.plan(at(5.0 + kCap + 0.2, 5.0), kFrame, kCap);
  EXPECT_FALSE(small.seek);
  // 2 s behind: the stepper takes its cap, and the music jumps back to where those steps end.
  const MusicPlan p = clock.plan(at(7.0, 5.0), kFrame, kCap);
  EXPECT_NEAR(p.advance, 2.0, 1e-12);
  ASSERT_TRUE(p.seek);
  EXPECT_NEAR(*p.seek, 5.0 + kCap, 1e-12);
  EXPECT_TRUE(p.play);

  // The FrameStepper given that advance takes exactly its cap (400 steps of 0.5 ms = kCap) and
  // reports the frame as capped, so the solver ends where the music was sought to.
  Scene scene = testing::sheet(6, 1.0, 0.3, 400.0, IntegratorKind::symplectic_euler, 5e-4);
  scene.cloths[0].pins = {{0, 0}, {5, 0}};
  const auto solver_owner = testing::solver<double>(scene);
  Solver& solver = *solver_owner;
  const FrameStepper stepper;
  const FrameCap cap{400 * solver.dt(), FrameLimit::solver};
  MusicClock live = started();
  const MusicPlan big = live.plan(at(2.0, solver.time()), kFrame, cap.seconds);
  const FrameAdvance a = stepper.advance(solver, big.advance, cap);
  EXPECT_TRUE(a.capped);
  EXPECT_EQ(a.steps, 400);
  ASSERT_TRUE(big.seek);
  EXPECT_NEAR(solver.time(), *big.seek, 1e-9);
  // The next frame, the music a frame further on, is in step: no seek, a frame's advance.
  const MusicPlan next = live.plan(at(*big.seek + kFrame, solver.time()), kFrame, kCap);
  EXPECT_FALSE(next.seek);
  EXPECT_NEAR(next.advance, kFrame, 1e-9);
}

}  // namespace
}  // namespace clothlab
