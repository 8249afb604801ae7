// Timing statistics of the window, averaged over half-second windows so the numbers in the panel
// and the title are readable rather than flickering every frame.
#pragma once

#include <string>

#include "sim/realtime/frame_stepper.hpp"

namespace clothlab::vis {

struct FrameSample {
  double frame_seconds = 0.0;  // wall time since the previous frame
  double step_seconds = 0.0;   // wall time spent inside the solver's advance
  long steps = 0;
  double simulated = 0.0;               // simulated seconds this frame
  double requested = 0.0;               // simulated seconds real time asked for (0 while paused)
  FrameLimit limit = FrameLimit::none;  // what capped this frame's steps (FrameStepper)
};

class FrameStats {
 public:
  static constexpr double kWindowSeconds = 0.5;
  // Below this share of real time over a window (percent) a capped solver is reported.
  static constexpr double kKeptPercent = 99.0;

  void add(const FrameSample& s);

  double frame_ms() const { return frame_ms_; }
  double fps() const { return frame_ms_ > 0.0 ? 1e3 / frame_ms_ : 0.0; }
  double ms_per_step() const { return ms_per_step_; }  // last measured; kept while paused
  double steps_per_frame() const { return steps_per_frame_; }
  // The solver held the last window's frames back (it is slower than its share of real time);
  // real_time_percent() is the share of real time it simulated.
  bool behind() const { return behind_; }
  double real_time_percent() const { return real_time_percent_; }
  // "the solver keeps 35 % of real time: 1.43 ms per step of 0.5 ms" (dt in s), or "".
  std::string behind_reason(double dt) const;

 private:
  FrameSample sum_;  // the window being accumulated
  long frames_ = 0;
  bool solver_bound_ = false;
  double frame_ms_ = 0.0, ms_per_step_ = 0.0, steps_per_frame_ = 0.0;
  double real_time_percent_ = 100.0;
  bool behind_ = false;
};

}  // namespace clothlab::vis
