#include "music/music_clock.hpp"

#include <algorithm>
#include <cmath>

namespace clothlab {

MusicPlan MusicClock::plan(const MusicReading& r, double wall_seconds, double max_advance) {
  MusicPlan out;
  // The first plan counts as a new solver: the playback starts where the simulation is.
  const bool new_solver = !generation_ || *generation_ != r.generation;
  const bool resumed = r.running && !was_running_;
  generation_ = r.generation;
  was_running_ = r.running;

  double audio = r.audio;
  if (new_solver || resumed) {
    audio = std::clamp(r.solver, 0.0, duration_);
    out.seek = audio;
    smooth_ = audio;  // the position the playback starts from, before it reports any
  } else {
    audio = follow(r.audio, wall_seconds);
  }
  // The reported position reaches the end before the smoothed one (after a seek it is stale).
  const double reported = out.seek ? *out.seek : r.audio;
  const bool before_end = r.solver < duration_ && std::max(audio, reported) < duration_;
  out.play = r.running && before_end;
  if (!out.play) smooth_.reset();
  if (!r.running) return out;
  if (!before_end) {
    out.advance = std::max(0.0, wall_seconds);
    return out;
  }
  // The solver may lead by less than one step: it carries the remainder of the last request.
  const double gap = std::max(0.0, audio - r.solver);
  if (gap - max_advance > max_lag_) {
    out.seek = std::min(r.solver + max_advance, duration_);
    smooth_ = out.seek;
  }
  out.advance = gap;
  out.on_audio = true;
  return out;
}

double MusicClock::follow(double reported, double wall_seconds) {
  if (!smooth_) return reported;
  const double predicted = *smooth_ + std::max(0.0, wall_seconds);
  const double error = reported - predicted;
  smooth_ = std::abs(error) > kSnapSeconds ? reported : predicted + kPull * error;
  return *smooth_;
}

}  // namespace clothlab
