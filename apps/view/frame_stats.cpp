#include "apps/view/frame_stats.hpp"

#include <cstdio>

namespace clothlab::vis {

void FrameStats::add(const FrameSample& s) {
  sum_.frame_seconds += s.frame_seconds;
  sum_.step_seconds += s.step_seconds;
  sum_.steps += s.steps;
  sum_.simulated += s.simulated;
  sum_.requested += s.requested;
  solver_bound_ |= s.limit == FrameLimit::solver;
  ++frames_;
  if (sum_.frame_seconds < kWindowSeconds) return;

  frame_ms_ = 1e3 * sum_.frame_seconds / double(frames_);
  steps_per_frame_ = double(sum_.steps) / double(frames_);
  if (sum_.steps > 0) ms_per_step_ = 1e3 * sum_.step_seconds / double(sum_.steps);
  // Only the solver slows the simulation for long: a stall's or a new solver's first frame
  // drops time once and is not worth a warning, nor a cap whose time later frames made up for
  // (FrameStepper::owed_after).
  real_time_percent_ = sum_.requested > 0.0 ? 100.0 * sum_.simulated / sum_.requested : 100.0;
  behind_ = solver_bound_ && real_time_percent_ < kKeptPercent;
  sum_ = FrameSample{};
  frames_ = 0;
  solver_bound_ = false;
}

std::string FrameStats::behind_reason(double dt) const {
  if (!behind_) return "";
  char text[128];
  std::snprintf(text, sizeof text,
                "the solver keeps %.0f %% of real time: %.3g ms per step of %.3g ms",
                real_time_percent_, ms_per_step_, 1e3 * dt);
  return text;
}

}  // namespace clothlab::vis
