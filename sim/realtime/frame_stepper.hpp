// Real time for an interactive view: each frame advances the solver by the wall-clock time since
// the previous frame, in whole fixed steps (the solver carries the remainder), so the motion is
// the same at 30 and at 144 frames per second. When the machine cannot keep up, a frame runs at
// most max_steps_per_frame steps and drops the rest of the time (reported, so the view can warn)
// instead of falling ever further behind.
#pragma once

#include <optional>

#include "sim/solver.hpp"

namespace clothlab {

struct FrameAdvance {
  long steps = 0;                // steps taken this frame
  bool capped = false;           // real time asked for more than the cap
  double dropped_seconds = 0.0;  // simulated time given up this frame
  std::optional<Divergence> divergence;
};

class FrameStepper {
 public:
  explicit FrameStepper(long max_steps_per_frame = 400) : max_steps_(max_steps_per_frame) {}

  // wall_seconds: time since the previous frame; time_scale: simulated seconds per real second
  // (slow motion below 1). A paused view passes paused = true and steps nothing.
  FrameAdvance advance(Solver& solver, double wall_seconds, double time_scale = 1.0,
                       bool paused = false) const {
    FrameAdvance out;
    if (paused || !(wall_seconds > 0.0)) return out;
    double request = wall_seconds * time_scale;
    const double cap = static_cast<double>(max_steps_) * solver.dt();
    if (request > cap) {
      out.capped = true;
      out.dropped_seconds = request - cap;
      request = cap;
    }
    const AdvanceResult r = solver.advance(request);
    out.steps = r.steps;
    out.divergence = r.divergence;
    return out;
  }

  long max_steps_per_frame() const { return max_steps_; }

 private:
  long max_steps_;
};

}  // namespace clothlab
