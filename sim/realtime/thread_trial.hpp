// The automatic thread count of an interactive run, measured rather than assumed. From
// kParallelMinVertices vertices up the parallel step is usually the faster one, but not on a
// machine whose cores are busy: beside another busy process the window's 8-copy default scene
// (8192 vertices) stepped in 2.3-2.8 ms on 2 threads against 0.14 ms on one. So the choice is a
// trial: a few frames on one thread, as many on the parallel setting, and the faster per step
// (each side by its fastest frame) is kept (the parallel one must win by kParallelMargin: it holds
// more cores); the trial runs again after kRetrialSeconds of wall time, since the machine's load
// changes. A trial costs the frames it steps on the slower side (large_sheet's 5 frames on one
// thread drop about 0.1 s of real time in the window): where the same side wins clearly (by
// kClearRatio) again, the wait before the next one doubles, up to kMaxRetrialSeconds; any other
// outcome sets it back. Only the choice is measured: the step itself is the same on any thread
// count (the solver's sums run in a fixed order), so the trial never changes the motion.
#pragma once

namespace clothlab {

class ThreadTrial {
 public:
  static constexpr int kFramesPerSide = 4;        // measured frames per setting, after a warm-up
  static constexpr double kParallelMargin = 0.1;  // parallel kept if it costs < 1 / 1.1 of serial
  static constexpr double kRetrialSeconds = 10.0;
  static constexpr double kClearRatio = 1.5;  // the slower side's cost over the faster one's
  static constexpr double kMaxRetrialSeconds = 80.0;

  // `parallel_threads`: the parallel setting (0: every core OpenMP offers).
  explicit ThreadTrial(int parallel_threads = 0) : parallel_(parallel_threads) {}

  // The threads the next frame steps with.
  int threads() const {
    const bool parallel =
        phase_ == Phase::parallel || (phase_ == Phase::decided && chose_parallel_);
    return parallel ? parallel_ : 1;
  }
  // Records the frame just stepped with threads(): `steps` steps in `seconds` of wall time,
  // ending at wall-clock time `now` (s). Frames without steps (paused) do not count.
  void record(long steps, double seconds, double now);
  // Starts over (a new solver): the next frames are a trial again.
  void restart() { *this = ThreadTrial(parallel_); }

  bool trying() const { return phase_ != Phase::decided; }
  // Wall seconds from the last decision to the next trial.
  double retrial_seconds() const { return retrial_; }
  // The last trial's seconds per step on one thread and on the parallel setting (0 before one).
  double serial_cost() const { return serial_.cost(); }
  double parallel_cost() const { return parallel_cost_.cost(); }

 private:
  enum class Phase { serial, parallel, decided };
  void decide(double now);  // from both sides' tallies, at wall time `now`
  // A side's cost is its fastest counted frame's seconds per step: a host that pauses the
  // process adds time to some frames and never takes any away, so the least is the step's own
  // cost (large_sheet in the window, eight trials by the mean: the parallel side at 9.9-12.0 ms
  // in six, 13.8 and 14.2 ms in two, short of the clear win over its 15-22 ms serial steps).
  struct Tally {
    int frames = 0;  // counted, after the warm-up frame
    double best = 0.0;
    bool warmed = false;  // the first frame after a switch wakes threads: not counted
    void add(long s, double t);
    double cost() const { return best; }
  };

  int parallel_;
  Phase phase_ = Phase::serial;
  bool chose_parallel_ = false;  // the last decision (kept through the next trial)
  bool clear_ = false;           // the last decision was won by kClearRatio
  double decided_at_ = 0.0;
  double retrial_ = kRetrialSeconds;
  Tally serial_, parallel_cost_;
};

}  // namespace clothlab
