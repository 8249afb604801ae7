// The audio clock as the master of an interactive view with music (docs/contact.md section 4): each
// frame the simulation catches up to the playback position in fixed steps (FrameStepper), so the
// dance lands on the beat you hear whatever the frame rate. This is the rule alone, free of any
// audio library, so it is tested without a device; apps/view/music_sync.hpp applies its plans
// to an OpenAL playback.
//
// The rule, per frame, from the playback position `audio`, the solver's time and whether the
// simulation runs (not paused, not stopped on divergence):
//  - a new solver (reset, another scene: its generation changed) or a run resuming after a pause
//    seeks the audio to the solver's time (a single step while paused moved the solver alone);
//  - running, before the track's end: advance by audio - solver (never negative), where `audio`
//    is the playback position smoothed as below;
//  - more than max_lag behind even after this frame's capped steps (the machine cannot keep up):
//    the music jumps back to where this frame's steps end, rather than the dance drifting ever
//    further off the beat;
//  - after the track's end: advance by the frame's wall time, as a view without music does;
//  - paused or diverged: advance nothing, and the audio pauses too.
//
// Smoothing: OpenAL Soft moves a source's offset once per mixing period (1024 samples, 23 ms at
// 44.1 kHz by default), so at 60 frames per second the raw position gives steps of 0, 23, 0, 23
// ms: visible judder. The clock instead runs on the frames' wall time and is pulled a fraction
// kPull of the way to the reported position each frame (the error then decays within ~10 frames,
// while the period's sawtooth is averaged out), and jumps to it where they differ by more than
// kSnapSeconds (a stall, a device whose clock differs). A reported position that moves with the
// wall clock is followed exactly.
#pragma once

#include <optional>

namespace clothlab {

struct MusicReading {
  double audio = 0.0;    // s, the playback position (the track's length once it has ended)
  double solver = 0.0;   // s, Solver::time()
  long generation = 0;   // counts solver rebuilds from t = 0 (SimSession::generation)
  bool running = false;  // neither paused nor stopped on divergence
};

struct MusicPlan {
  std::optional<double> seek;  // s: move the playback here before this frame's steps
  bool play = false;           // the playback should be playing after this frame
  double advance = 0.0;        // s of simulated time to ask the FrameStepper for
  bool on_audio = false;       // the advance follows the audio (false: wall time or nothing)
};

class MusicClock {
 public:
  static constexpr double kMaxLagSeconds = 0.25;  // audible as "off the beat" beyond this
  static constexpr double kPull = 0.1;            // of the smoothed clock's error, per frame
  static constexpr double kSnapSeconds = 0.1;     // a larger error is a jump, not jitter

  // duration: the track's length in seconds.
  explicit MusicClock(double duration, double max_lag = kMaxLagSeconds)
      : duration_(duration), max_lag_(max_lag) {}

  // One frame's plan. wall_seconds: time since the previous frame; max_advance: the most
  // simulated time the FrameStepper takes in this frame (FrameStepper::cap), to decide
  // whether the music must wait for the simulation. The advance itself is not capped here: the
  // stepper caps it and reports the frame as capped (the panel's "can't keep up").
  MusicPlan plan(const MusicReading& reading, double wall_seconds, double max_advance);

  double duration() const { return duration_; }

 private:
  double follow(double reported, double wall_seconds);  // the smoothed playback position

  double duration_, max_lag_;
  std::optional<long> generation_;  // of the previous plan; none before the first
  bool was_running_ = false;
  std::optional<double> smooth_;  // s, the smoothed position while playing; none otherwise
};

}  // namespace clothlab
