#include "tune/live_reference.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "sim/model/model.hpp"
#include "sim/scene/validate.hpp"
#include "sim/solver.hpp"
#include "sim/stability/spectrum.hpp"
#include "tune/ladder.hpp"

namespace clothlab::tune {

namespace {

void copy_state(const Solver& solver, Positions& positions, Positions& velocities) {
  const std::size_t n = solver.vertex_count();
  positions.resize(n);
  velocities.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    positions[i] = solver.position(int(i));
    velocities[i] = solver.velocity(int(i));
  }
}

// The cubic Hermite interpolant at s in [0, 1] of a step of h s from (p0, v0) to (p1, v1).
Vec3d hermite(const Vec3d& p0, const Vec3d& v0, const Vec3d& p1, const Vec3d& v1, double h,
              double s) {
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = 3 * s2 - 2 * s3,
               h11 = s3 - s2;
  Vec3d p;
  for (int c = 0; c < 3; ++c) p[c] = h00 * p0[c] + h10 * h * v0[c] + h01 * p1[c] + h11 * h * v1[c];
  return p;
}

}  // namespace

Scene live_reference_scene(const Scene& shown, double fraction) {
  Scene s = shown;
  SolverSpec& solver = s.solver;
  solver.backend = Backend::cpu;
  solver.threads = 1;
  solver.tolerance = 0.0;
  solver.precision = Precision::f64;
  solver.integrator = IntegratorKind::rk4;
  solver.iterations = 0;
  const int n = reference_substeps(estimate_spectrum(build_model<double>(s)), fraction, false);
  solver.dt = kFrame / n;
  solver.dt_auto = false;
  solver.substeps = 1;
  validate_scene(s);
  return s;
}

LiveReference::LiveReference(const Scene& reference) : solver_(make_solver(reference)) {
  step_ = solver_->dt();
  char text[64];
  std::snprintf(text, sizeof text, "rk4 (double), step %.3g ms", 1e3 * step_);
  label_ = text;
  thread_ = std::thread([this] { work(); });
}

LiveReference::~LiveReference() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    cancel_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void LiveReference::restart(const Solver& shown) {
  cancel_ = true;
  wait();
  cancel_ = false;
  solver_->load_state(shown);
  if (shown.pins_released() && !solver_->pins_released()) solver_->release_pins();
  offset_ = solver_->time() - shown.time();
  copy_state(*solver_, before_, velocity_);  // the state a request at this very time reads
  copy_state(*solver_, after_, velocity1_);
  std::lock_guard lock(mutex_);
  failure_.clear();
  fresh_ = false;
}

bool LiveReference::submit(const Solver& shown) {
  {
    std::lock_guard lock(mutex_);
    if (pending_ || running_ || !failure_.empty()) return false;
    shown_.resize(shown.vertex_count());
    for (std::size_t i = 0; i < shown_.size(); ++i) shown_[i] = shown.position(int(i));
    request_time_ = shown.time();
    pending_ = true;
  }
  changed_.notify_all();
  return true;
}

bool LiveReference::busy() const {
  std::lock_guard lock(mutex_);
  return pending_ || running_;
}

void LiveReference::wait() const {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return !pending_ && !running_; });
}

bool LiveReference::take(LiveComparison& out) {
  std::lock_guard lock(mutex_);
  if (!fresh_) return false;
  out.time = result_.time;
  out.distance = result_.distance;
  out.per_vertex.swap(result_.per_vertex);
  fresh_ = false;
  return true;
}

double LiveReference::cost() const {
  std::lock_guard lock(mutex_);
  return simulated_ > 0.0 ? wall_ / simulated_ : 0.0;
}

std::string LiveReference::failure() const {
  std::lock_guard lock(mutex_);
  return failure_;
}

void LiveReference::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return pending_ || quit_; });
    if (quit_) return;
    pending_ = false;
    running_ = true;
    lock.unlock();
    run_request();
    lock.lock();
    running_ = false;
    changed_.notify_all();
  }
}

// Steps to the request's time, interpolates there and measures every vertex's distance.
void LiveReference::run_request() {
  const double target = request_time_ + offset_;
  if (!advance_to(target)) return;
  // Where the request lies in the last step, 0 to 1; at its end (a time the reference reached
  // itself, as when both runs share a step) its state is read as it is.
  const double s = std::clamp((target - (solver_->time() - step_)) / step_, 0.0, 1.0);
  const bool at_end = s > 1.0 - 1e-9;
  reference_.resize(shown_.size());
  for (std::size_t i = 0; i < shown_.size(); ++i)
    reference_[i] =
        at_end ? after_[i] : hermite(before_[i], velocity_[i], after_[i], velocity1_[i], step_, s);
  const Distance total = distance(reference_, shown_, &work_);
  std::lock_guard lock(mutex_);
  result_.time = request_time_;
  result_.distance = total;
  result_.per_vertex.swap(work_);
  fresh_ = true;
}

// Steps until the reference's clock reaches `target`, keeping its states at the start and the end
// of the last step (a target within the last step already taken needs no step). False when
// cancelled or diverged.
bool LiveReference::advance_to(double target) {
  const long last = static_cast<long>(std::ceil(target / step_ - 1e-9));
  const long per_chunk = std::max(1L, std::lround(kFrame / step_ / 4.0));
  bool ok = true;
  while (ok && solver_->step_count() < last - 1) {
    if (cancel_) return false;
    ok = timed_steps(std::min(per_chunk, last - 1 - solver_->step_count()));
  }
  if (solver_->step_count() >= last) return ok;  // within the last step taken
  if (ok) copy_state(*solver_, before_, velocity_);
  if (ok) ok = timed_steps(1);
  if (ok) copy_state(*solver_, after_, velocity1_);
  return ok;
}

// `count` steps, their wall time counted in cost() as they go (a slow reference shows its pace
// before its first comparison); on divergence the failure says where.
bool LiveReference::timed_steps(long count) {
  const auto start = std::chrono::steady_clock::now();
  const double t0 = solver_->time();
  const bool ok = solver_->step(count).ok();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::lock_guard lock(mutex_);
  wall_ += wall;
  simulated_ += solver_->time() - t0;
  if (!ok) {
    char text[64];
    std::snprintf(text, sizeof text, "the reference diverged at t = %.3f s", solver_->time());
    failure_ = text;
  }
  return ok;
}

}  // namespace clothlab::tune
