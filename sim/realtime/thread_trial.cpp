#include "sim/realtime/thread_trial.hpp"

#include <algorithm>

namespace clothlab {

void ThreadTrial::Tally::add(long s, double t) {
  if (!warmed) {
    warmed = true;
    return;
  }
  const double cost = t / double(s);
  best = frames == 0 ? cost : std::min(best, cost);
  ++frames;
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
      if (parallel_cost_.frames >= kFramesPerSide) decide(now);
      return;
    case Phase::decided:
      if (now - decided_at_ < retrial_) return;
      serial_ = parallel_cost_ = Tally{};
      phase_ = Phase::serial;
      return;
  }
}

void ThreadTrial::decide(double now) {
  const double serial = serial_.cost(), parallel = parallel_cost_.cost();
  const bool was_clear = clear_, was_parallel = chose_parallel_;
  chose_parallel_ = parallel * (1.0 + kParallelMargin) < serial;
  clear_ = std::max(serial, parallel) >= kClearRatio * std::min(serial, parallel);
  const bool again = clear_ && was_clear && chose_parallel_ == was_parallel;
  retrial_ = again ? std::min(2.0 * retrial_, kMaxRetrialSeconds) : kRetrialSeconds;
  phase_ = Phase::decided;
  decided_at_ = now;
}

}  // namespace clothlab
