// The live simulation behind the window: the scene as parsed, the scene the running solver was
// built from, and the panel's draft of the next one. Edits go to the draft; values that keep the
// topology apply at once (a new solver takes over the motion with load_state), structural ones
// (resolution) on reset. Every edit passes validate_scene first; a bad value is reported, not
// applied. No GL here.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "sim/realtime/frame_stepper.hpp"
#include "sim/scene/scene.hpp"
#include "sim/solver.hpp"

namespace clothlab::vis {

class SimSession {
 public:
  // Builds the solver; throws SceneError when the scene cannot be built.
  explicit SimSession(Scene scene);

  Solver& solver() { return *solver_; }
  const Solver& solver() const { return *solver_; }
  const Scene& scene() const { return applied_; }  // what the solver was built from
  Scene& draft() { return draft_; }                // what the panel edits
  // Counts rebuilds from scratch: when it changes, the cloth's topology may have changed and
  // the renderer needs set_cloth.
  long generation() const { return generation_; }

  // Applies the draft's integrator, dt, springs, drag and wind to the running motion. On a bad
  // value sets error() and leaves the solver alone.
  void apply_dynamics();
  // Checks the draft's structure (resolution, pins) after a panel edit; sets structure_error().
  void check_structure();
  // Rebuilds from the draft at t = 0 (R, the Reset button): applies pending structural edits and
  // clears a divergence. On a bad draft sets an error and keeps the running solver.
  void reset();
  // + / -: scales the draft's resolution by factor and resets.
  void scale_resolution(double factor);
  void toggle_wind();
  // M: all cores <-> one thread. Until M is pressed the session chooses: all cores (the scene's
  // threads setting) from kParallelVertices vertices up, one thread below. The window's OpenMP
  // threads wait passively (they share the cores with the GL driver), and waking them costs
  // more than a small cloth's step: at 32x32, 2 threads took 0.26 ms per symplectic Euler step
  // against 0.04 ms on one, and 18 ms against 1.6 ms per implicit Euler step.
  void toggle_parallel();
  static constexpr std::size_t kParallelVertices = 8192;
  bool parallel() const { return applied_.solver.threads != 1; }

  // P: momentum `impulse` (N*s) into the free vertices around the cloth's centre.
  void push(const Vec3d& impulse);

  // One frame of real time (FrameStepper); nothing while paused or diverged.
  FrameAdvance advance(const FrameStepper& stepper, double wall_seconds);
  void single_step();  // `.` while paused
  bool paused = false;

  const std::optional<Divergence>& divergence() const { return divergence_; }
  const std::string& error() const { return error_; }                      // last rejected edit
  const std::string& structure_error() const { return structure_error_; }  // pending resize
  bool structure_pending() const;  // the draft's resolution differs from the running one

 private:
  std::unique_ptr<Solver> build(const Scene& scene) const;
  void choose_threads();  // while the user has not pressed M

  bool parallel_chosen_ = false;  // M was pressed: keep the user's choice
  Scene base_, applied_, draft_;
  std::unique_ptr<Solver> solver_;
  std::optional<Divergence> divergence_;
  std::string error_, structure_error_;
  long generation_ = 0;
};

}  // namespace clothlab::vis
