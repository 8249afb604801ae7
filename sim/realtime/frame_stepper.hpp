// Real time for an interactive view: each frame advances the solver by the wall-clock time since
// the previous frame, in whole fixed steps (the solver carries the remainder), so the motion is
// the same at 30 and at 144 frames per second, and on a machine that draws a frame a second it
// is still real time. A frame may give the solver a share of its wall time (kSolverShare; the rest
// is the drawing's), or more where the frame still stays within kFrameBudget: whatever the drawing
// leaves of 1/20 s. Only a solver slower than that slows the simulation down, and the frame then
// says so (FrameLimit::solver). A frame that comes after a stall (longer than kMaxFrameSeconds:
// the window moved, a debugger paused it) makes up for no more than that. What a frame's cap
// dropped, up to kMaxOwed, the next frames ask for again (catch_up, owed_after), a tenth of their
// own time at most: a host that holds the solver up for a few frames, or the thread trial's
// frames on one thread, cost no real time where the following frames have room, and the motion
// runs at most 10 % fast while they make it up.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "sim/solver.hpp"

namespace clothlab {

// What held a frame's simulation back.
enum class FrameLimit {
  none,     // every step real time asked for was taken
  solver,   // the solver is slower than its share of real time: it took its share, no more
  unknown,  // the solver's cost is not known yet (a new solver): one step, to measure it
  stall,    // the frame came after a stall: the time beyond kMaxFrameSeconds is dropped
};

// The most simulated time a frame may advance, and what sets that bound.
struct FrameCap {
  double seconds = std::numeric_limits<double>::infinity();
  FrameLimit limit = FrameLimit::none;
  static FrameCap unlimited() { return {}; }
};

struct FrameAdvance {
  long steps = 0;                       // steps taken this frame
  bool capped = false;                  // real time asked for more than the cap
  FrameLimit limit = FrameLimit::none;  // what capped it
  double dropped_seconds = 0.0;         // simulated time given up this frame
  std::optional<Divergence> divergence;
};

// What the timed first steps of a new solver measured (probe_step_cost).
struct StepCostProbe {
  long steps = 0;
  double seconds = 0.0;  // wall time of those steps
  double cost = 0.0;     // seconds per step: what the frame's cap is then computed from
};

// A new solver's cost per step is unknown (FrameLimit::unknown). Rather than one step for the
// whole frame (a frame of real time dropped each time the solver is rebuilt: 9 % of a 30-frame
// run), the window steps it one step at a time, timed by `step_once` (which takes one step and
// returns its wall seconds, or a negative number when it could not: a divergence), while the
// steps stay within `budget_seconds` (the frame's solver share) and `max_steps`; then the rest of
// the frame is capped by the measured cost. The first step is cold (caches, pages touched for
// the first time) and left out of the cost when later ones ran.
template <class StepOnce>
StepCostProbe probe_step_cost(double budget_seconds, long max_steps, StepOnce&& step_once) {
  StepCostProbe p;
  double later = 0.0;
  while (p.steps < max_steps && p.seconds < budget_seconds) {
    const double s = step_once();
    if (s < 0.0) break;
    ++p.steps;
    p.seconds += s;
    if (p.steps > 1) later += s;
  }
  p.cost = p.steps > 1 ? later / double(p.steps - 1) : p.seconds;
  return p;
}

class FrameStepper {
 public:
  static constexpr double kSolverShare = 0.5;  // of a frame's wall time
  // A frame the solver may fill up to: 20 frames a second, where the eye still sees motion and
  // a drag still follows the mouse. A software renderer drawing a large sheet in 20 ms leaves the
  // solver 30 ms, three of its 10 ms steps: real time, where half of a 50 ms frame is two.
  static constexpr double kFrameBudget = 0.05;
  static constexpr double kMaxFrameSeconds = 2.0;  // of wall time one frame makes up for
  static constexpr long kCostSteps = 8;            // steps a new solver's cost is timed on
  // Simulated time the frames may owe. A solver slower than real time owes it for good.
  static constexpr double kMaxOwed = 1.0;
  // The most a frame asks for of what is owed, as a share of its own wall time: the motion runs
  // at most 10 % fast while the frames catch up, and the catching up never exceeds a frame's
  // solver budget (the cap).
  static constexpr double kCatchUpRate = 0.1;

  // What a frame of wall_seconds asks for beyond its own time, of `owed`.
  static double catch_up(double owed, double wall_seconds) {
    return std::min(owed, kCatchUpRate * std::max(0.0, wall_seconds));
  }
  // What the frames owe after one that asked for `asked` of `owed` beyond its own time and
  // advanced as `a`: the rest of the debt and whatever its solver budget dropped, up to kMaxOwed.
  // A stall gives everything up, and so does a new solver's first frame (its cost unknown).
  static double owed_after(double owed, double asked, const FrameAdvance& a) {
    if (a.limit == FrameLimit::stall || a.limit == FrameLimit::unknown) return 0.0;
    const double dropped = a.limit == FrameLimit::solver ? a.dropped_seconds : 0.0;
    return std::min(kMaxOwed, std::max(0.0, owed - asked) + dropped);
  }

  explicit FrameStepper(double solver_share = kSolverShare,
                        double max_frame_seconds = kMaxFrameSeconds)
      : share_(solver_share), max_frame_(max_frame_seconds) {}

  // The cap for a frame that came wall_seconds after the previous one, for a solver whose step
  // of dt seconds costs seconds_per_step of wall time (0: not known yet). other_seconds: the part
  // of that previous frame spent outside the solver (drawing, events), where known.
  FrameCap cap(double wall_seconds, double seconds_per_step, double dt,
               std::optional<double> other_seconds = {}) const {
    const double wall = wall_seconds < max_frame_ ? wall_seconds : max_frame_;
    double budget = share_ * wall;
    if (other_seconds) budget = std::max(budget, kFrameBudget - *other_seconds);
    double steps = 1.0;
    if (seconds_per_step > 0.0) steps = std::max(1.0, std::floor(budget / seconds_per_step));
    const double by_solver = steps * dt;
    if (by_solver < max_frame_)
      return {by_solver, seconds_per_step > 0.0 ? FrameLimit::solver : FrameLimit::unknown};
    return {max_frame_, FrameLimit::stall};
  }

  // Advances by `request` simulated seconds (wall time times the time scale, or what the music
  // asks for), at most cap.seconds. A paused view passes paused = true and steps nothing.
  FrameAdvance advance(Solver& solver, double request, const FrameCap& cap,
                       bool paused = false) const {
    FrameAdvance out;
    if (paused || !(request > 0.0)) return out;
    if (request > cap.seconds) {
      out.capped = true;
      out.limit = cap.limit;
      out.dropped_seconds = request - cap.seconds;
      request = cap.seconds;
    }
    const AdvanceResult r = solver.advance(request);
    out.steps = r.steps;
    out.divergence = r.divergence;
    return out;
  }

  double solver_share() const { return share_; }

 private:
  double share_, max_frame_;
};

}  // namespace clothlab
