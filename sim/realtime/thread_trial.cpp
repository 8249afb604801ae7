#include "sim/realtime/thread_trial.hpp"

namespace clothlab {

void ThreadTrial::Tally::add(long s, double t) {
  if (!warmed) {
    warmed = true;
    return;
  }
  ++frames;
  steps += s;
  seconds += t;
}

void ThreadTrial::record(long steps, double seconds, double now) {
  if (steps <= 0 || !(seconds >= 0.0)) return;
  switch (phase_) {
    case Phase::serial:
      serial_.add(steps, seconds);
      if (serial_.frames >= kFramesPerSide) phase_ = Phase::parallel;
      return;
    case Phase::parallel:
      parallel_cost_.add(steps, seconds);
      if (parallel_cost_.frames < kFramesPerSide) return;
      chose_parallel_ = parallel_cost_.cost() * (1.0 + kParallelMargin) < serial_.cost();
      phase_ = Phase::decided;
      decided_at_ = now;
      return;
    case Phase::decided:
      if (now - decided_at_ < kRetrialSeconds) return;
      serial_ = parallel_cost_ = Tally{};
      chose_parallel_ = false;
      phase_ = Phase::serial;
      return;
  }
}

}  // namespace clothlab
