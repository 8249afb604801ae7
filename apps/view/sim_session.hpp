// The live simulation behind the window: the scene as parsed, the scene the running solver was
// built from, and the panel's draft of the next one. Edits go to the draft; values that keep the
// topology apply at once (a new solver takes over the motion with load_state), structural ones
// (resolution) on reset. Every edit passes validate_scene first; a bad value is reported, not
// applied. The solver itself comes from a factory (the window's makes the GPU backend's when
// solver.backend = "gpu"); no GL here.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "sim/core/parallel.hpp"
#include "sim/realtime/frame_stepper.hpp"
#include "sim/realtime/thread_trial.hpp"
#include "sim/scene/scene.hpp"
#include "sim/solver.hpp"
#include "sim/trace/csv_trace.hpp"

namespace clothlab::vis {

// Makes the solver for a validated scene; sets `note` to one line when it could not give the
// backend the scene asks for (and gave the CPU's), else leaves it empty.
using SolverFactory = std::function<std::unique_ptr<Solver>(const Scene&, std::string& note)>;

class SimSession {
 public:
  // Builds the solver (with make_solver when `factory` is empty); throws SceneError when the
  // scene cannot be built.
  explicit SimSession(Scene scene, SolverFactory factory = {});

  Solver& solver() { return *solver_; }
  const Solver& solver() const { return *solver_; }
  // What the solver was built from: the applied scene with its copies (every cloth and collider
  // the renderer draws).
  const Scene& scene() const { return built_; }
  Scene& draft() { return draft_; }  // what the panel edits
  // Counts rebuilds from scratch: when it changes, the cloth's topology may have changed and
  // the renderer needs set_cloth.
  long generation() const { return generation_; }
  // Counts every solver built, a parameter edit that keeps the motion included (its cost per
  // step may differ from the last one's).
  long builds() const { return builds_; }

  // Applies the draft's integrator, dt, springs, drag and wind to the running motion. On a bad
  // value sets error() and leaves the solver alone.
  void apply_dynamics();
  // Checks the draft's structure (resolution, pins) after a panel edit; sets structure_error().
  void check_structure();
  // Rebuilds from the draft at t = 0 (R, the Reset button): applies pending structural edits and
  // clears a divergence. On a bad draft sets an error and keeps the running solver.
  void reset();
  // The panel's scene picker: runs `scene` from t = 0 instead (its own view, colliders and
  // look; recording stops). Throws SceneError when it cannot be built (the running one stays).
  void load(Scene scene);
  // ] / [: scales the draft's resolution by factor and resets.
  void scale_resolution(double factor);
  // [ and ]: the number of copies of the scene's cloths (and the colliders under them) side by
  // side, 1..kMaxCopies, each simulated (sim/cloth/scene_copies.hpp); the run restarts at t = 0.
  // Returns a one-line reason when the scene cannot be copied (nothing changes then).
  std::string set_copies(int copies);
  int copies() const { return copies_; }
  static constexpr int kMaxCopies = 64;
  // Why the running solver is not the backend the scene asks for (empty when it is).
  const std::string& backend_note() const { return backend_note_; }
  void toggle_wind();
  // M: all cores <-> one thread. Until M is pressed the session chooses: one thread below
  // kParallelMinVertices vertices, as the solver's threads = 0 does (sim/core/parallel.hpp), but
  // also when the scene names a count (waking the passively waiting threads costs more than a
  // small cloth's step: at 32x32, 2 threads took 0.26 ms per symplectic Euler step against
  // 0.04 ms on one, and 18 ms against 1.6 ms per implicit Euler step); from that size up,
  // whichever of one thread and the scene's threads setting measured faster per step in the
  // frames the window reports (measured_frame; sim/realtime/thread_trial.hpp), as for a smaller
  // cloth with cloth contact on, whose pair work is worth threads.
  void toggle_parallel();
  // A frame's steps and their wall seconds, ending at wall-clock time `now` (s): the automatic
  // choice's measurement.
  void measured_frame(long steps, double seconds, double now);
  // The automatic choice's trial, while it decides the thread count (null otherwise).
  const ThreadTrial* thread_trial() const { return trial_active_ ? &trial_ : nullptr; }
  static constexpr std::size_t kParallelVertices = kParallelMinVertices;
  bool parallel() const { return applied_.solver.threads != 1; }

  // P: momentum `impulse` (N*s) into the free vertices around the cloth's centre.
  void push(const Vec3d& impulse);

  // One frame: `request` simulated seconds (real time, or the music's advance) within `cap`
  // (FrameStepper::cap); nothing while paused or diverged.
  FrameAdvance advance(const FrameStepper& stepper, double request,
                       const FrameCap& cap = FrameCap::unlimited());
  void single_step();  // `.` while paused
  bool paused = false;

  // Recording (the panel's Record): from now on every step the session takes is written as CSV
  // trace rows of `spec` (docs/design.md "CSV trace"), its `every` counted from the step recording
  // began, into a temporary file beside `path` that stop_recording() renames to `path`: the
  // file is complete or absent. Reset, a resolution change and the session's end stop it.
  // Throws std::runtime_error when the file cannot be opened.
  void start_recording(const std::string& path, const TraceSpec& spec);
  // Finishes the file; returns a one-line summary ("recorded N rows to PATH"), empty if none.
  std::string stop_recording();
  bool recording() const { return recorder_ != nullptr; }
  long recorded_rows() const { return recorded_rows_; }
  const std::string& recording_path() const { return record_path_; }

  const std::optional<Divergence>& divergence() const { return divergence_; }
  const std::string& error() const { return error_; }                      // last rejected edit
  const std::string& structure_error() const { return structure_error_; }  // pending resize
  bool structure_pending() const;  // the draft's resolution differs from the running one

 private:
  // Validates `scene` and builds the solver for it with copies_ copies.
  std::unique_ptr<Solver> build(const Scene& scene);
  void rebuilt();         // after applied_ or copies_ changed: the built scene follows
  void choose_threads();  // while the user has not pressed M
  FrameAdvance advance_recording(double request, const FrameCap& cap);
  void record_step();

  void use_threads(int threads);
  bool parallel_chosen_ = false;  // M was pressed: keep the user's choice
  bool trial_active_ = false;     // the measured choice decides (large cloth, no M, no count 1)
  ThreadTrial trial_;
  SolverFactory factory_;
  int copies_ = 1;
  double spacing_ = 0.0;  // m between copies, from the original's extent
  std::string backend_note_;
  Scene base_, applied_, draft_, built_;
  std::unique_ptr<Solver> solver_;
  std::optional<Divergence> divergence_;
  std::string error_, structure_error_;
  long generation_ = 0;
  long builds_ = 0;

  std::unique_ptr<TraceWriter> recorder_;
  TraceSpec record_spec_;
  std::string record_path_;
  long recorded_rows_ = 0, record_start_step_ = 0;
  double record_clock_ = 0.0;  // simulated time the recorded stepping has reached, s
};

}  // namespace clothlab::vis
