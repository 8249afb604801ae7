#include "sim/solver.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "sim/body/body_motion.hpp"
#include "sim/core/parallel.hpp"
#include "sim/core/vec3_eigen.hpp"
#include "sim/integrators/constraints/coarse_stretch.hpp"
#include "sim/integrators/constraints/tethers.hpp"
#include "sim/model/model_check.hpp"
#include "sim/solver_impl.hpp"
#include "sim/stability/step_limit.hpp"

namespace clothlab {
namespace {

// solver.threads = 0 ("auto"): one thread below kParallelMinVertices, where a second thread's
// wake-up and barriers cost more than it computes (docs/results.md, "Threads"), else all cores
// OpenMP offers; with triangle contact from kParallelMinContactVertices on, whose broad and narrow
// phases pay for a second thread on far smaller cloths (docs/contact.md section 7). An explicit
// count is used as given.
int resolve_threads(int requested, std::size_t vertices, bool cloth_contact) {
  if (requested > 0) return requested;
  const std::size_t least = cloth_contact ? kParallelMinContactVertices : kParallelMinVertices;
  return vertices < least ? 1 : omp_get_max_threads();
}

template <class T>
State<T> initial_state(const Model<T>& m) {
  State<T> s;
  s.pos = m.rest_positions;
  s.vel.resize(m.n);
  return s;
}

// The longest side in vertices of the cloths whose sweeps must carry corrections across them
// alone (a mesh cloth counts as a square of its vertices): xpbd's coarse stretch levels carry
// them on the grids that have levels (sim/integrators/constraints/coarse_stretch.hpp).
template <class T>
int substep_side(const Model<T>& m, const SolverSpec& spec) {
  int side = 1;
  for (std::size_t c = 0; c < m.cloths.size(); ++c) {
    const ClothRange& r = m.cloths[c];
    const bool levels = spec.integrator == IntegratorKind::xpbd && spec.coarse_stretch &&
                        m.kernel == SpringKernel::row_sweep && stretch_limited(m, c) &&
                        coarse_level_count(r.nu, r.nv) > 0;
    if (levels) continue;
    side = std::max(
        side, r.mesh ? static_cast<int>(std::ceil(std::sqrt(double(r.nu)))) : std::max(r.nu, r.nv));
  }
  return side;
}

// The scene's solver block with dt = "auto" and substeps = "auto" resolved
// (sim/stability/step_limit.hpp), so the integrator is built for the step it will take.
template <class T>
SolverSpec resolve_step(const Model<T>& m, SolverSpec spec) {
  if (spec.dt_auto) spec.dt = choose_step(spec.integrator, estimate_spectrum(m)).dt;
  if (spec.substeps == 0)
    spec.substeps = auto_substeps(spec.integrator, spec.dt, substep_side(m, spec));
  return spec;
}

// Fast limbs (docs/contact.md section 3): no surface of the dancing body may move more than half
// its thinnest feature in one substep, or a vertex could be stepped over rather than pushed. The
// fastest surface speed over the dance (sampled every 5 ms) sets the most a substep may be. The
// dance is a 16-beat loop, so its first two minutes hold every move it makes (longer would cost
// start-up time: 24 000 samples of about 6 us each already).
SolverSpec limit_substep_for_body(const Scene& scene, SolverSpec spec) {
  if (!scene.mannequin || !scene.mannequin->motion) return spec;
  const BodyMotion& body = *scene.mannequin->motion;
  const std::vector<double> keys = body.dance().keyframe_times();
  const double end = std::min(keys.empty() ? 10.0 : keys.back() + 1.0, 120.0);
  const double speed = body.max_surface_speed(0.0, end);
  if (!(speed > 0.0)) return spec;
  const double h_max = 0.5 * body.thinnest_feature() / speed;
  if (spec.dt / spec.substeps > h_max) spec.substeps = static_cast<int>(std::ceil(spec.dt / h_max));
  return spec;
}

template <class T>
double initial_energy(const Model<T>& m) {
  std::vector<double> partials;
  return compute_energy(m, initial_state(m), partials, 1).total();
}

// The model and the step, each checked once as built (sim/model/model_check.hpp).
template <class T>
Model<T> checked(Model<T> m, const Scene& scene) {
  check_built_model(m, scene, initial_energy(m));
  return m;
}

SolverSpec checked(SolverSpec spec, const Scene& scene) {
  check_step(spec.dt, spec.substeps, scene);
  return spec;
}

}  // namespace

template <class T>
SolverT<T>::SolverT(const Scene& scene, SpringKernel kernel)
    : model_(checked(build_model<T>(scene, kernel), scene)),
      state_(initial_state(model_)),
      spec_(checked(limit_substep_for_body(scene, resolve_step(model_, scene.solver)), scene)),
      dt_(spec_.dt),
      substeps_(spec_.substeps),
      threads_(resolve_threads(scene.solver.threads, model_.n, scene.solver.cloth_contact)),
      integrator_(make_integrator<T>(model_, spec_)),
      monitor_(model_, state_, initial_energy(model_)) {
  workspace_.resize(model_);
  force_field_.resize(model_.n);
  // The built state's forces, once: a cloth whose every value is representable can still have
  // forces that are not (a 1e30 m sheet's squared edge lengths overflow a float).
  compute_forces(model_, 0.0, state_.pos, state_.vel, force_field_, workspace_, threads_);
  check_built_forces(force_field_, model_, scene);
  if (!scene.colliders.empty())
    contacts_ = std::make_unique<ContactResponse<T>>(
        scene.colliders, model_,
        scene.solver.cloth_contact ? kHoldReach * scene.solver.self_thickness : 0.0);
  if (spec_.self_collision) self_ = std::make_unique<SelfCollision<T>>(model_, spec_);
  check_contact_thickness(model_, scene);
  if (spec_.cloth_contact) cloth_contact_ = std::make_unique<TriangleContact<T>>(model_, spec_);
  const bool pins_move = std::any_of(scene.cloths.begin(), scene.cloths.end(),
                                     [](const ClothSpec& c) { return !c.pins_follow.empty(); });
  if (pins_move) moving_pins_ = std::make_unique<KinematicPins<T>>(scene, model_);
  for (const ClothSpec& c : scene.cloths) pins_.at.push_back(c.release_at);
  pins_.built_at = pins_.at;
  pins_.built_pins = model_.pinned;
}

template <class T>
AdvanceResult SolverT<T>::advance(double duration) {
  const double wanted = pending_ + duration;
  // The relative margin absorbs round-off in wanted / dt (1.0 / 0.001 is 999.99...).
  const auto count = static_cast<long>(std::floor(wanted / dt_ * (1.0 + 1e-12)));
  pending_ = std::max(0.0, wanted - static_cast<double>(count) * dt_);
  return step(count);
}

// The step loop of both backends: the CPU-side parts (release, contacts, moving pins, grab,
// checks) run on state_, which the helpers keep current where the integrator runs on a step
// backend (sync_state() reads it back, mirror_written() and state_corrected() send it up); on
// the CPU they cost a test of a null pointer.
template <class T>
AdvanceResult SolverT<T>::step(long count) {
  AdvanceResult result;
  if (diverged_) {
    result.divergence = diverged_;
    return result;
  }
  const System<T> sys{model_, workspace_, threads_};
  const double h = dt_ / substeps_;
  Divergence report;
  for (long k = 0; k < count; ++k) {
    const double t0 = time();
    release_due(false);
    // Self-collision pairs once per step, reused by every substep (docs/contact.md section 2).
    if (self_) {
      sync_state();
      self_->find_pairs(model_, state_, dt_, threads_);
    }
    int pass_begin = 0, pass_end = 0;  // triangle contact's pass: its substeps
    for (int sub = 0; sub < substeps_; ++sub) {
      const double t = t0 + sub * h;
      if (contacts_) {
        sync_state();
        contacts_->begin(state_, t, h, threads_);
      }
      if (moving_pins_) {
        sync_state();
        moving_pins_->drive(model_, state_, t, h);
        mirror_written();
      }
      if (cloth_contact_ && sub == pass_end) {
        sync_state();
        pass_begin = sub;
        pass_end = sub + cloth_contact_->pass_span(state_, h, substeps_ - sub, threads_);
        cloth_contact_->begin(state_, threads_);
      }
      record(integrate(sys, t, h));
      if (moving_pins_) {
        sync_state();
        moving_pins_->place(model_, state_, t0 + (sub + 1) * h);
        mirror_written();
      }
      bool corrected = false;
      if (grab_) {
        sync_state();
        pull_grabbed(h);
        corrected = true;
      }
      if (contacts_) {
        sync_state();
        if (contacts_->respond(model_, state_, t, h, threads_)) corrected = true;
      }
      if (self_) {
        sync_state();
        if (self_->respond(model_, state_, h)) corrected = true;
      }
      // Last: the fail-safe's guarantee holds for the positions it leaves.
      if (cloth_contact_ && sub + 1 == pass_end) {
        sync_state();
        const double span = (pass_end - pass_begin) * h;
        const ColliderTouches* touches = contacts_ ? &contacts_->touches() : nullptr;
        if (cloth_contact_->respond(model_, state_, span, threads_, touches)) corrected = true;
        tangles_.count(cloth_contact_->last().overflow, t);
      }
      if (corrected) state_corrected();
    }
    ++steps_;
    ++result.steps;
    if (!check_after(k, count)) continue;
    sync_state();
    if (stuck_in_tangle(report) ||
        monitor_.check(model_, state_, steps_, time(), threads_, report)) {
      diverged_ = report;
      result.divergence = report;
      break;
    }
  }
  return result;
}

template <class T>
long SolverT<T>::intersections() const {
  sync_state();
  if (!counter_)
    counter_ =
        std::make_unique<IntersectionCounter>(model_.triangles, points_of(model_.rest_positions));
  return counter_->count(points_of(state_.pos));
}

template <class T>
SolveStats SolverT<T>::integrate(const System<T>& sys, double t, double h) {
  if (backend_) return backend_->integrate(t, h);
  integrator_->step(sys, state_, t, static_cast<T>(h));
  return integrator_->last_stats();
}

template <class T>
void SolverT<T>::sync_state() const {
  if (backend_ && backend_->ahead()) backend_->pull(const_cast<State<T>&>(state_));
}

template <class T>
void SolverT<T>::mirror_written() {
  if (backend_) backend_->push(state_);
}

template <class T>
void SolverT<T>::state_corrected() {
  if (backend_)
    backend_->push(state_);  // forgets Verlet's stored force, as the CPU's integrator does
  else
    integrator_->state_corrected();
}

template <class T>
void SolverT<T>::pins_changed() {
  if (backend_) backend_->pins_changed(model_);
}

// A run stuck in a tangle stops with a report (sim/contact/tangle_watch.hpp).
template <class T>
bool SolverT<T>::stuck_in_tangle(Divergence& out) const {
  if (!tangles_.stuck()) return false;
  char why[200];
  std::snprintf(why, sizeof why,
                "cloth contact: %d tangles beyond the pair bound since t = %.4g s held every free "
                "vertex (an exploding cloth, or cloth pressed denser than the bound)",
                tangles_.tangles, tangles_.since);
  monitor_.stuck(model_, state_, steps_, time(), why, out);
  return true;
}

// Without CPU work between the substeps the mirror is read once per step() call: in the window,
// once per frame.
template <class T>
bool SolverT<T>::check_after(long k, long count) const {
  return !backend_ || !backend_->ahead() || k + 1 == count;
}

template <class T>
void SolverT<T>::set_step_backend(std::unique_ptr<StepBackend<T>> backend) {
  backend_ = std::move(backend);
}

template <class T>
void SolverT<T>::record(const SolveStats& s) {
  ++totals_.substeps;
  totals_.iterations += s.iterations;
  totals_.solves += s.solves;
  totals_.max_iterations = std::max(totals_.max_iterations, s.iterations);
  totals_.max_residual = std::max(totals_.max_residual, s.residual);
  if (!s.converged) ++totals_.unconverged;
}

template <class T>
int SolverT<T>::vertex_index(const VertexRef& v) const {
  const ClothRange& c = model_.cloths[static_cast<std::size_t>(v.cloth)];
  return c.offset + v.i + v.j * c.nu;
}

// The total force comes from the backend's own force pass where it has one; a single source
// (springs, gravity, drag, wind) from the CPU's code on the mirror.
template <class T>
void SolverT<T>::update_force_field(ForceSource source) {
  force_source_ = source;
  if (backend_ && source == ForceSource::total && backend_->total_force(time(), force_field_))
    return;
  sync_state();
  compute_force_source(model_, time(), state_.pos, state_.vel, force_field_, workspace_, threads_,
                       source);
}

template <class T>
Energy SolverT<T>::energy() {
  sync_state();
  return compute_energy(model_, state_, energy_partials_, threads_);
}

template <class T>
void SolverT<T>::apply_impulse(const Vec3d& center, double radius, const Vec3d& impulse) {
  sync_state();
  add_impulse(center, radius, impulse);
  mirror_written();
}

template <class T>
void SolverT<T>::add_impulse(const Vec3d& center, double radius, const Vec3d& impulse) {
  auto distance2 = [&](std::size_t i) {
    const Vec3d p = vec3_at(state_.pos, static_cast<int>(i));
    return (p[0] - center[0]) * (p[0] - center[0]) + (p[1] - center[1]) * (p[1] - center[1]) +
           (p[2] - center[2]) * (p[2] - center[2]);
  };
  // Weights (1 - r^2/R^2)^2 of the free vertices in reach, and their mass-weighted sum.
  const double r2max = radius * radius;
  std::vector<double> w(model_.n, 0.0);
  double weight_mass = 0.0;  // sum of w_i m_i
  for (std::size_t i = 0; i < model_.n; ++i) {
    if (model_.inv_mass[i] == T(0)) continue;
    const double r2 = distance2(i);
    if (r2 >= r2max) continue;
    const double q = 1.0 - r2 / r2max;
    w[i] = q * q;
    weight_mass += w[i] * double(model_.mass[i]);
  }
  if (weight_mass == 0.0) {  // nothing in reach: the nearest free vertex takes the whole impulse
    double best = INFINITY;
    std::size_t nearest = model_.n;
    for (std::size_t i = 0; i < model_.n; ++i) {
      if (model_.inv_mass[i] == T(0)) continue;
      const double r2 = distance2(i);
      if (r2 < best) best = r2, nearest = i;
    }
    if (nearest == model_.n) return;
    w[nearest] = 1.0;
    weight_mass = double(model_.mass[nearest]);
  }
  // dv_i = J w_i / sum(w m): sum m_i dv_i = J. The energy it adds raises the divergence allowance.
  double added = 0.0;
  for (std::size_t i = 0; i < model_.n; ++i) {
    if (w[i] == 0.0) continue;
    for (int a = 0; a < 3; ++a) {
      const double dv = impulse[a] * w[i] / weight_mass;
      const double v0 = state_.vel.axis(a)[i];
      state_.vel.axis(a)[i] = static_cast<T>(v0 + dv);
      added += 0.5 * double(model_.mass[i]) * ((v0 + dv) * (v0 + dv) - v0 * v0);
    }
  }
  monitor_.add_energy(std::abs(added));
  integrator_->invalidate();
}

template <class T>
void SolverT<T>::load_state(const Solver& other) {
  if (other.vertex_count() != model_.n)
    throw std::invalid_argument("load_state: the solvers have different vertex counts");
  sync_state();  // so that nothing pulls the backend's old state over what is written here
  for (std::size_t i = 0; i < model_.n; ++i) {
    const Vec3d p = other.position(static_cast<int>(i)), v = other.velocity(static_cast<int>(i));
    for (int a = 0; a < 3; ++a) {
      state_.pos.axis(a)[i] = static_cast<T>(p[a]);
      state_.vel.axis(a)[i] = model_.inv_mass[i] == T(0) ? T(0) : static_cast<T>(v[a]);
    }
  }
  steps_ = other.step_count();
  // Keep the simulated time: with another dt the step count is rescaled.
  if (other.dt() != dt_) steps_ = static_cast<long>(std::llround(other.time() / dt_));
  pending_ = 0.0;
  diverged_.reset();
  tangles_ = {};
  state_changed();
  mirror_written();
}

template <class T>
void SolverT<T>::set_state(const std::vector<Vec3d>& positions,
                           const std::vector<Vec3d>& velocities) {
  if (positions.size() != model_.n || velocities.size() != model_.n)
    throw std::invalid_argument("set_state: one position and one velocity per vertex");
  sync_state();  // so that nothing pulls the backend's old state over what is written here
  for (std::size_t i = 0; i < model_.n; ++i)
    for (int a = 0; a < 3; ++a) {
      state_.pos.axis(a)[i] = static_cast<T>(positions[i][a]);
      state_.vel.axis(a)[i] = static_cast<T>(velocities[i][a]);
    }
  state_changed();
  mirror_written();
}

template <class T>
void SolverT<T>::copy_normals(float* xyz) {
  if (backend_ && backend_->normals(xyz)) return;
  compute_surface(model_, state_.pos, workspace_, threads_);
  copy_xyz(workspace_.normal, xyz);
}

template <class T>
void SolverT<T>::set_threads(int threads) {
  threads_ = resolve_threads(threads, model_.n, spec_.cloth_contact);
}

template <class T>
void SolverT<T>::reset() {
  sync_state();  // the backend's state is about to be replaced: never pull it over the reset
  restore_pins();
  grab_.reset();
  pins_.at = pins_.built_at;
  state_ = initial_state(model_);
  steps_ = 0;
  pending_ = 0.0;
  diverged_.reset();
  tangles_ = {};
  totals_ = {};
  integrator_->invalidate();
  mirror_written();
}

template <class T>
void SolverT<T>::release_due(bool all) {
  bool any = false;
  for (std::size_t c = 0; c < model_.cloths.size(); ++c) {
    const bool due = all || (pins_.at[c] && time() >= *pins_.at[c] - 0.5 * dt_);
    if (!due) continue;
    const ClothRange& r = model_.cloths[c];
    for (int v = r.offset; v < r.offset + r.nu * r.nv; ++v) {
      const auto i = static_cast<std::size_t>(v);
      if (model_.inv_mass[i] != T(0)) continue;
      model_.inv_mass[i] = T(1) / model_.mass[i];
      any = true;
    }
    pins_.at[c].reset();
  }
  if (!any) return;
  std::erase_if(model_.pinned,
                [&](int v) { return model_.inv_mass[static_cast<std::size_t>(v)] != T(0); });
  pins_.released = true;
  // The integrators build their systems around the pinned vertices (filters, factorisations):
  // a new one for the new pins (once, at the release; the step loop itself never allocates).
  integrator_ = make_integrator<T>(model_, spec_);
  pins_changed();
}

template <class T>
bool SolverT<T>::grab(int vertex, const Vec3d& target) {
  if (vertex < 0 || static_cast<std::size_t>(vertex) >= model_.n || pinned(vertex)) return false;
  grab_ = GrabTarget{vertex, target};
  return true;
}

// The grab as a velocity filter after the substep (like the collision response, so it works
// with every integrator): the velocity moves a fraction beta = h / tau of the way to the one
// that closes the gap in one substep, and the position follows; a spring-damper pull with time
// constant tau, stable for any stiffness because beta <= 1/2. The kinetic energy it adds joins
// the divergence monitor's allowance (the user's hand is a source).
template <class T>
void SolverT<T>::pull_grabbed(double h) {
  constexpr double kTau = 0.004;  // s
  const double beta = std::min(0.5, h / kTau);
  const auto i = static_cast<std::size_t>(grab_->vertex);
  double added = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double x = state_.pos.axis(a)[i], v = state_.vel.axis(a)[i];
    const double dv = beta * ((grab_->target[a] - x) / h - v);
    state_.vel.axis(a)[i] = static_cast<T>(v + dv);
    state_.pos.axis(a)[i] = static_cast<T>(x + h * dv);
    added += 0.5 * double(model_.mass[i]) * ((v + dv) * (v + dv) - v * v);
  }
  monitor_.add_energy(std::abs(added));
}

template <class T>
void SolverT<T>::release_pins() {
  release_due(true);
}

template <class T>
void SolverT<T>::restore_pins() {
  if (!pins_.released) return;
  for (int v : pins_.built_pins) model_.inv_mass[static_cast<std::size_t>(v)] = T(0);
  model_.pinned = pins_.built_pins;
  pins_.released = false;
  integrator_ = make_integrator<T>(model_, spec_);
  pins_changed();
}

template <class T>
void SolverT<T>::state_changed() {
  integrator_->invalidate();
  // Whatever was written is the caller's input: its energy joins the divergence allowance.
  const Energy e = energy();
  monitor_.add_energy(std::abs(e.kinetic) + std::abs(e.elastic));
}

template class SolverT<float>;
template class SolverT<double>;

const char* backend_name(const SolverState& solver) {
  const DeviceCloth* device = solver.device_cloth();
  return device ? device->name() : "CPU";
}

std::unique_ptr<Solver> make_solver(const Scene& scene) {
  return make_solver(scene, SpringKernel::row_sweep);
}

std::unique_ptr<Solver> make_solver(const Scene& scene, SpringKernel kernel) {
  if (scene.solver.precision == Precision::f64)
    return std::make_unique<SolverT<double>>(scene, kernel);
  return std::make_unique<SolverT<float>>(scene, kernel);
}

}  // namespace clothlab
