#include "apps/view/sim_session.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "apps/view/scene_edit.hpp"
#include "sim/cloth/scene_copies.hpp"
#include "sim/push_region.hpp"
#include "sim/scene/scene_error.hpp"
#include "sim/scene/validate.hpp"

namespace clothlab::vis {
namespace {

// A panel edit has no place in the scene file, so its message names the key, not a line.
std::string edit_message(const SceneError& e) {
  return e.key.empty() ? e.detail : e.key + ": " + e.detail;
}

}  // namespace

SimSession::SimSession(Scene scene, SolverFactory factory)
    : factory_(std::move(factory)), base_(scene), applied_(scene), draft_(std::move(scene)) {
  solver_ = build(applied_);
  rebuilt();
  choose_threads();
}

void SimSession::rebuilt() {
  built_ = with_copies(applied_, copies_, spacing_);
  ++builds_;
}

void SimSession::choose_threads() {
  trial_active_ = false;
  if (parallel_chosen_ || base_.solver.threads == 1) return;
  // Cloth contact's pair work is worth threads on a small cloth too (the stack on the ball: 14 ms
  // a frame on 2 threads, 19 on one): the trial measures it.
  if (solver_->vertex_count() < kParallelVertices && !applied_.solver.cloth_contact)
    return use_threads(1);
  trial_active_ = true;
  trial_ = ThreadTrial(base_.solver.threads);
  use_threads(trial_.threads());
}

void SimSession::use_threads(int threads) {
  if (threads == applied_.solver.threads) return;
  applied_.solver.threads = draft_.solver.threads = threads;
  solver_->set_threads(threads);
}

void SimSession::measured_frame(long steps, double seconds, double now) {
  if (!trial_active_) return;
  trial_.record(steps, seconds, now);
  use_threads(trial_.threads());
}

std::unique_ptr<Solver> SimSession::build(const Scene& scene) {
  validate_scene(scene);
  const Scene copied = with_copies(scene, copies_, spacing_);
  std::string note;
  std::unique_ptr<Solver> solver = factory_ ? factory_(copied, note) : make_solver(copied);
  backend_note_ = note;
  return solver;
}

void SimSession::apply_dynamics() {
  Scene candidate = applied_;
  copy_dynamics(draft_, candidate);
  std::unique_ptr<Solver> next;
  try {
    next = build(candidate);
  } catch (const SceneError& e) {
    error_ = edit_message(e);
    return;
  }
  error_.clear();
  applied_ = std::move(candidate);
  rebuilt();
  // A diverged state is not worth carrying over: the new values wait for R.
  if (divergence_) return;
  next->load_state(*solver_);
  if (solver_->pins_released()) next->release_pins();  // a dropped cloth stays dropped (D)
  solver_ = std::move(next);
}

void SimSession::check_structure() {
  remap_grid_indices(draft_, base_);
  try {
    validate_scene(draft_);
    structure_error_.clear();
  } catch (const SceneError& e) {
    structure_error_ = edit_message(e);
  }
}

void SimSession::reset() {
  remap_grid_indices(draft_, base_);
  try {
    solver_ = build(draft_);
  } catch (const SceneError& e) {
    structure_error_ = edit_message(e);
    return;
  }
  applied_ = draft_;
  rebuilt();
  error_.clear();
  structure_error_.clear();
  divergence_.reset();
  ++generation_;
  choose_threads();  // ] / [ may have crossed kParallelVertices
}

void SimSession::load(Scene scene) {
  const int copies = copies_;
  copies_ = 1;  // a new scene starts as one
  std::unique_ptr<Solver> next;
  try {
    next = build(scene);
  } catch (...) {
    copies_ = copies;  // the running scene stays
    throw;
  }
  if (recording()) stop_recording();
  solver_ = std::move(next);
  base_ = applied_ = draft_ = std::move(scene);
  rebuilt();
  error_.clear();
  structure_error_.clear();
  divergence_.reset();
  parallel_chosen_ = false;
  ++generation_;
  choose_threads();
}

void SimSession::scale_resolution(double factor) {
  if (vis::scale_resolution(draft_, factor)) reset();
}

std::string SimSession::set_copies(int copies) {
  copies = std::clamp(copies, 1, kMaxCopies);
  if (copies == copies_) return {};
  if (std::string why = copies_unsupported_reason(applied_); !why.empty()) return why;
  if (copies_ == 1) {
    spacing_ = copy_spacing(applied_);
  }
  const int before = copies_;
  copies_ = copies;
  std::unique_ptr<Solver> next;
  try {
    next = build(applied_);
  } catch (const SceneError& e) {
    copies_ = before;
    return edit_message(e);
  }
  if (recording()) stop_recording();
  solver_ = std::move(next);
  rebuilt();
  divergence_.reset();
  ++generation_;
  choose_threads();
  return {};
}

void SimSession::toggle_wind() {
  draft_.forces.wind.enabled = !draft_.forces.wind.enabled;
  apply_dynamics();
}

void SimSession::toggle_parallel() {
  parallel_chosen_ = true;
  trial_active_ = false;
  const int threads = parallel() ? 1 : 0;
  applied_.solver.threads = draft_.solver.threads = threads;
  solver_->set_threads(threads);
}

void SimSession::push(const Vec3d& impulse) {
  if (divergence_) return;
  const PushRegion region = default_push_region(*solver_);
  solver_->apply_impulse(region.center, region.radius, impulse);
}

FrameAdvance SimSession::advance(const FrameStepper& stepper, double request, const FrameCap& cap) {
  if (recorder_) return advance_recording(request, cap);
  const FrameAdvance r = stepper.advance(*solver_, request, cap, paused || divergence_.has_value());
  if (r.divergence) divergence_ = r.divergence;
  return r;
}

void SimSession::single_step() {
  if (divergence_) return;
  const AdvanceResult r = solver_->step(1);
  if (r.divergence) divergence_ = r.divergence;
  if (recorder_ && !divergence_) record_step();
}

// The same real-time rule as FrameStepper (the cap included), one step at a time so that each
// step can be written: the steps whose end lies within the simulated time asked for so far.
FrameAdvance SimSession::advance_recording(double request, const FrameCap& cap) {
  FrameAdvance out;
  if (paused || divergence_ || !(request > 0.0)) return out;
  const double dt = solver_->dt();
  if (request > cap.seconds) {
    out.capped = true;
    out.limit = cap.limit;
    out.dropped_seconds = request - cap.seconds;
    request = cap.seconds;
  }
  record_clock_ += request;
  // Whole steps only, as Solver::advance takes them (the remainder waits for the next frame).
  const auto target = static_cast<long>(std::floor(record_clock_ / dt * (1.0 + 1e-12)));
  while (solver_->step_count() < target) {
    const AdvanceResult r = solver_->step(1);
    out.steps += r.steps;
    if (r.divergence) {
      divergence_ = out.divergence = r.divergence;
      break;
    }
    record_step();
  }
  return out;
}

void SimSession::record_step() {
  if ((solver_->step_count() - record_start_step_) % record_spec_.every != 0) return;
  recorder_->write_step(*solver_);
  recorded_rows_ += std::max<long>(1, static_cast<long>(record_spec_.vertices.size()));
}

void SimSession::start_recording(const std::string& path, const TraceSpec& spec) {
  stop_recording();
  recorder_ = std::make_unique<TraceWriter>(path, spec, applied_.multi_cloth,
                                            applied_.solver.precision == Precision::f64);
  record_spec_ = spec;
  record_path_ = path;
  recorded_rows_ = 0;
  record_start_step_ = solver_->step_count();
  record_clock_ = solver_->time();
  if (!divergence_) record_step();  // the state recording starts from
}

std::string SimSession::stop_recording() {
  if (!recorder_) return {};
  recorder_->commit();
  recorder_.reset();
  return "recorded " + std::to_string(recorded_rows_) + " rows to " + record_path_;
}

bool SimSession::structure_pending() const {
  for (std::size_t c = 0; c < draft_.cloths.size(); ++c)
    if (draft_.cloths[c].resolution != applied_.cloths[c].resolution) return true;
  return false;
}

}  // namespace clothlab::vis
