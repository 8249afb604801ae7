#include "vis/window/frame_stats.hpp"

namespace clothlab::vis {

void FrameStats::add(const FrameSample& s) {
  sum_.frame_seconds += s.frame_seconds;
  sum_.step_seconds += s.step_seconds;
  sum_.steps += s.steps;
  sum_.simulated += s.simulated;
  sum_.requested += s.requested;
  capped_ |= s.capped;
  ++frames_;
  if (sum_.frame_seconds < kWindowSeconds) return;

  frame_ms_ = 1e3 * sum_.frame_seconds / double(frames_);
  steps_per_frame_ = double(sum_.steps) / double(frames_);
  if (sum_.steps > 0) ms_per_step_ = 1e3 * sum_.step_seconds / double(sum_.steps);
  behind_ = capped_;
  real_time_percent_ = sum_.requested > 0.0 ? 100.0 * sum_.simulated / sum_.requested : 100.0;
  sum_ = FrameSample{};
  frames_ = 0;
  capped_ = false;
}

}  // namespace clothlab::vis
