// The window's error view (docs/tuning.md, "The error in the window"): a reference run of the
// shown scene steps on a thread of its own beside the shown run, and each time the shown run
// hands over its state the reference steps to the same simulated time and measures the distance
// of every vertex. The reference is `clothlab tune`'s coarser one (RK4 in double at half its
// stability limit, tune/ladder.hpp), stepped one substep at a time so that a state lies every
// step; between two of its steps it is read by cubic Hermite interpolation of its positions and
// velocities, whose error, h^4 |x''''| / 384, is far below the reference's own.
#pragma once

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "sim/scene/scene.hpp"
#include "tune/sampled_run.hpp"

namespace clothlab {
class Solver;
}

namespace clothlab::tune {

// The reference of a scene that is shown: the same cloths, colliders, forces and contact, with
// the solver replaced by RK4 in double at `fraction` of its stability limit (a step that divides
// a frame, taken as a step of its own), on the CPU, on one thread (the shown run has the
// others). Throws SceneError when the scene cannot be built.
Scene live_reference_scene(const Scene& shown, double fraction = 0.5);

// The shown run against the reference at one time.
struct LiveComparison {
  double time = 0.0;              // s: the shown run's clock
  Distance distance;              // m: RMS and largest over the vertices
  std::vector<float> per_vertex;  // m
};

class LiveReference {
 public:
  // Builds the reference solver for `reference` (live_reference_scene) and starts its thread.
  // Throws SceneError when the scene cannot be built.
  explicit LiveReference(const Scene& reference);
  ~LiveReference();  // stops the thread (a running request is abandoned)
  LiveReference(const LiveReference&) = delete;
  LiveReference& operator=(const LiveReference&) = delete;

  // "rk4 (double), step 0.52 ms"
  const std::string& label() const { return label_; }
  double step() const { return step_; }  // s

  // A new comparison from `shown`'s state now: its positions, velocities and time, its pins let
  // go when shown's are. Abandons a running request first. The vertex counts must agree.
  void restart(const Solver& shown);
  // Hands `shown`'s positions at its time to the reference, which steps there and measures.
  // False, and nothing handed over, while the previous request runs.
  bool submit(const Solver& shown);
  bool busy() const;
  void wait() const;  // until no request runs
  // Moves the newest comparison finished since the last call into `out`; false when none.
  bool take(LiveComparison& out);
  // s of wall time per simulated second over the reference's steps so far (0 before any).
  double cost() const;
  // Why the reference stopped (its divergence); empty while it runs.
  std::string failure() const;

 private:
  void work();
  void run_request();
  bool advance_to(double target);  // in the reference's own clock; false when stopped
  bool timed_steps(long count);

  std::unique_ptr<Solver> solver_;
  std::string label_;
  double step_ = 0.0;
  double offset_ = 0.0;  // s: the reference's clock less the shown run's (its step's rounding)

  // The request and its result, guarded by mutex_; the solver and the buffers below belong to
  // the thread while a request runs, to the caller otherwise.
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  bool pending_ = false, running_ = false, quit_ = false, fresh_ = false;
  std::atomic<bool> cancel_{false};
  double request_time_ = 0.0;
  Positions shown_;              // the request's positions
  Positions before_, velocity_;  // the reference's state one step before the request's time
  Positions after_, velocity1_;  // and one after
  Positions reference_;          // the reference read at the request's time
  std::vector<float> work_;      // the thread's distances, swapped into result_
  LiveComparison result_;
  std::string failure_;
  double wall_ = 0.0, simulated_ = 0.0;
  std::thread thread_;
};

}  // namespace clothlab::tune
