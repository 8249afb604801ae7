#include "vis/window/sim_session.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "sim/scene/scene_error.hpp"
#include "sim/scene/validate.hpp"
#include "vis/window/scene_edit.hpp"

namespace clothlab::vis {
namespace {

// A panel edit has no place in the scene file, so its message names the key, not a line.
std::string edit_message(const SceneError& e) {
  return e.key.empty() ? e.detail : e.key + ": " + e.detail;
}

}  // namespace

SimSession::SimSession(Scene scene)
    : base_(scene), applied_(scene), draft_(std::move(scene)), solver_(build(applied_)) {
  choose_threads();
}

void SimSession::choose_threads() {
  if (parallel_chosen_ || base_.solver.threads == 1) return;
  const int threads = solver_->vertex_count() >= kParallelVertices ? base_.solver.threads : 1;
  applied_.solver.threads = draft_.solver.threads = threads;
  solver_->set_threads(threads);
}

std::unique_ptr<Solver> SimSession::build(const Scene& scene) const {
  validate_scene(scene);
  return make_solver(scene);
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
  // A diverged state is not worth carrying over: the new values wait for R.
  if (divergence_) return;
  next->load_state(*solver_);
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
  error_.clear();
  structure_error_.clear();
  divergence_.reset();
  ++generation_;
  choose_threads();  // + / - may have crossed kParallelVertices
}

void SimSession::scale_resolution(double factor) {
  if (vis::scale_resolution(draft_, factor)) reset();
}

void SimSession::toggle_wind() {
  draft_.forces.wind.enabled = !draft_.forces.wind.enabled;
  apply_dynamics();
}

void SimSession::toggle_parallel() {
  parallel_chosen_ = true;
  const int threads = parallel() ? 1 : 0;
  applied_.solver.threads = draft_.solver.threads = threads;
  solver_->set_threads(threads);
}

void SimSession::push(const Vec3d& impulse) {
  if (divergence_) return;
  const std::size_t n = solver_->vertex_count();
  std::vector<float> xyz(3 * n);
  solver_->copy_positions(xyz.data());
  Vec3d lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY}, centre{};
  for (std::size_t v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      const double x = xyz[3 * v + k];
      lo[k] = std::min(lo[k], x);
      hi[k] = std::max(hi[k], x);
      centre[k] += x / double(n);
    }
  }
  // A quarter of the cloth's diagonal: a hand-sized push on the middle, not a shove of the
  // whole sheet.
  const double diagonal =
      std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
  solver_->apply_impulse(centre, std::max(0.05, 0.25 * diagonal), impulse);
}

FrameAdvance SimSession::advance(const FrameStepper& stepper, double wall_seconds) {
  const FrameAdvance r = stepper.advance(*solver_, wall_seconds, 1.0, paused || divergence_);
  if (r.divergence) divergence_ = r.divergence;
  return r;
}

void SimSession::single_step() {
  if (divergence_) return;
  const AdvanceResult r = solver_->step(1);
  if (r.divergence) divergence_ = r.divergence;
}

bool SimSession::structure_pending() const {
  for (std::size_t c = 0; c < draft_.cloths.size(); ++c)
    if (draft_.cloths[c].resolution != applied_.cloths[c].resolution) return true;
  return false;
}

}  // namespace clothlab::vis
