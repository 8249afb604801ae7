// SolverT<T>: the Solver for one scalar type. Exposed (rather than hidden in solver.cpp) for the
// code that extends the solver itself: the GPU backend (gpu/backend_solver.cpp) and the benchmark
// that times its parts (bench/self_collision_bench.cpp). Tests and everything else reach a solver
// through the role interfaces of sim/solver.hpp. Its integrator substeps run on the CPU, or
// on a step backend (sim/step_backend.hpp; the GPU's is gpu/gpu_step.hpp) that keeps the state
// itself while this solver's model, pins, contacts and checks work on a mirror of it.
#pragma once

#include <vector>

#include "sim/contact/contact_response.hpp"
#include "sim/contact/intersections.hpp"
#include "sim/contact/kinematic_pins.hpp"
#include "sim/contact/self_collision.hpp"
#include "sim/contact/tangle_watch.hpp"
#include "sim/contact/triangle_contact.hpp"
#include "sim/solver.hpp"
#include "sim/step_backend.hpp"

namespace clothlab {

// Vertex i of a, in double.
template <class T>
Vec3d vec3_at(const Vec3Array<T>& a, int i) {
  const auto k = static_cast<std::size_t>(i);
  return {double(a.x[k]), double(a.y[k]), double(a.z[k])};
}

// a as x, y, z floats per vertex.
template <class T>
void copy_xyz(const Vec3Array<T>& a, float* xyz) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    xyz[3 * i] = static_cast<float>(a.x[i]);
    xyz[3 * i + 1] = static_cast<float>(a.y[i]);
    xyz[3 * i + 2] = static_cast<float>(a.z[i]);
  }
}

// The cloths' pins that let go at a time (cloth.release_at), and what reset() restores.
struct PinRelease {
  std::vector<std::optional<double>> at;  // per cloth, s; reset when it happened
  std::vector<std::optional<double>> built_at;
  std::vector<int> built_pins;  // global indices, as built
  bool released = false;        // some cloth's pins have let go
};

// A vertex the user holds (Solver::grab): pulled towards `target` every substep.
struct GrabTarget {
  int vertex = 0;
  Vec3d target{};
};

template <class T>
class SolverT : public Solver {
 public:
  // kernel: the spring kernel (tests and benchmarks compare both; the default is the fast one).
  explicit SolverT(const Scene& scene, SpringKernel kernel = SpringKernel::row_sweep);

  AdvanceResult advance(double duration) override;
  AdvanceResult step(long count) override;
  double time() const override { return static_cast<double>(steps_) * dt_; }
  long step_count() const override { return steps_; }
  double dt() const override { return dt_; }
  int substeps() const override { return substeps_; }
  SolveStats last_solve() const override { return integrator_->last_stats(); }
  const SolveTotals& solve_totals() const override { return totals_; }
  std::size_t vertex_count() const override { return model_.n; }
  std::size_t spring_count() const override { return model_.spring_count; }
  int vertex_index(const VertexRef& v) const override;
  VertexRef vertex_ref(int index) const override { return vertex_ref_of(model_.cloths, index); }
  Vec3d position(int vertex) const override;
  Vec3d velocity(int vertex) const override;
  Vec3d rest_position(int vertex) const override { return vec3_at(model_.rest_positions, vertex); }
  double mass(int vertex) const override;
  bool pinned(int vertex) const override;
  void update_force_field(ForceSource source = ForceSource::total) override;
  Vec3d force(int vertex) const override { return vec3_at(force_field_, vertex); }
  ForceSource force_field_source() const override { return force_source_; }
  Energy energy() override;
  std::optional<Divergence> energy_divergence(const Energy& e) const override;
  void apply_impulse(const Vec3d& center, double radius, const Vec3d& impulse) override;
  void copy_positions(float* xyz) const override;
  void copy_rest_positions(float* xyz) const override { copy_xyz(model_.rest_positions, xyz); }
  void copy_normals(float* xyz) override;
  const std::vector<std::array<int, 3>>& triangles() const override { return model_.triangles; }
  std::vector<std::array<int, 2>> spring_pairs() const override;
  const std::vector<ClothRange>& cloths() const override { return model_.cloths; }
  void copy_velocities(float* xyz) const override;
  void load_state(const Solver& other) override;
  void set_state(const std::vector<Vec3d>& positions,
                 const std::vector<Vec3d>& velocities) override;
  void set_threads(int threads) override;
  int threads() const override { return threads_; }
  void reset() override;
  void release_pins() override;
  bool pins_released() const override { return pins_.released; }
  bool grab(int vertex, const Vec3d& target) override;
  void release_grab() override { grab_.reset(); }
  std::optional<int> grabbed() const override;
  ContactStats last_contacts() const override;
  std::optional<SelfCollisionStats> last_self_collision() const override;
  std::optional<ClothContactStats> last_cloth_contact() const override;
  long intersections() const override;
  double self_thickness() const override { return spec_.self_thickness; }
  DeviceCloth* device_cloth() const override;

  // Moves the integrator to `backend`, which takes over the current state (the solver's own
  // integrator is kept for nothing but its statistics' type).
  void set_step_backend(std::unique_ptr<StepBackend<T>> backend);

  // The self-collision response (solver.self_collision), or null when it is off.
  const SelfCollision<T>* self_collision() const { return self_.get(); }

  // Direct access for the backend and the component benchmarks. Call state_changed() after
  // writing the state.
  const Model<T>& model() const { return model_; }
  State<T>& state() { return state_; }
  void state_changed();

 protected:
  // Where the integrator runs: in place on state_, or on the step backend with state_ as its
  // mirror; on the CPU these cost a test of a null pointer.
  // One integrator substep of h seconds from time t; returns its statistics.
  SolveStats integrate(const System<T>& sys, double t, double h);
  // Brings state_ up to date before CPU code reads it. Logically const: the mirror is a cache of
  // the state the backend holds.
  void sync_state() const;
  // CPU code wrote state_ (moving pins) where the integrator's cached force stays valid.
  void mirror_written();
  // CPU code corrected state_ after a substep (the grab, a collision response).
  void state_corrected();
  // The pinned set changed (a release, a reset).
  void pins_changed();
  // Whether the divergence check runs after step k (0-based) of a step(count) call: after every
  // step where the mirror is current anyway, else once at the end of the call.
  bool check_after(long k, long count) const;

  void record(const SolveStats& s);
  // apply_impulse on state_.
  void add_impulse(const Vec3d& center, double radius, const Vec3d& impulse);
  // Lets go of the pins of the cloths whose release time has come (all of them with `all`).
  void release_due(bool all);
  void restore_pins();
  void pull_grabbed(double h);

  Model<T> model_;
  State<T> state_;
  SolverSpec spec_;  // the scene's, with dt and substeps resolved when dt = "auto"
  double dt_ = 0.0;
  int substeps_ = 1;
  long steps_ = 0;
  double pending_ = 0.0;  // s of requested time not yet stepped (less than one dt)
  int threads_ = 1;
  std::unique_ptr<Integrator<T>> integrator_;
  std::unique_ptr<StepBackend<T>> backend_;            // null: the integrator runs here, on state_
  std::unique_ptr<ContactResponse<T>> contacts_;       // only with colliders
  std::unique_ptr<SelfCollision<T>> self_;             // only with solver.self_collision
  std::unique_ptr<TriangleContact<T>> cloth_contact_;  // only with solver.cloth_contact
  // Built by the first intersections() call (a scene that never counts pays nothing).
  mutable std::unique_ptr<IntersectionCounter> counter_;
  std::unique_ptr<KinematicPins<T>> moving_pins_;  // only with cloth.pins_follow
  PinRelease pins_;
  std::optional<GrabTarget> grab_;
  ForceWorkspace<T> workspace_;
  Vec3Array<T> force_field_;
  ForceSource force_source_ = ForceSource::total;  // what force_field_ holds
  std::vector<double> energy_partials_;
  DivergenceMonitor<T> monitor_;
  std::optional<Divergence> diverged_;
  TangleWatch tangles_;
  bool stuck_in_tangle(Divergence& out) const;
  SolveTotals totals_;
};

template <class T>
inline double SolverT<T>::mass(int vertex) const {
  return double(model_.mass[static_cast<std::size_t>(vertex)]);
}

template <class T>
inline bool SolverT<T>::pinned(int vertex) const {
  return model_.inv_mass[static_cast<std::size_t>(vertex)] == T(0);
}

template <class T>
inline std::vector<std::array<int, 2>> SolverT<T>::spring_pairs() const {
  return clothlab::spring_pairs(model_);
}

template <class T>
inline std::optional<int> SolverT<T>::grabbed() const {
  return grab_ ? std::optional<int>(grab_->vertex) : std::nullopt;
}

template <class T>
inline ContactStats SolverT<T>::last_contacts() const {
  return contacts_ ? contacts_->last() : ContactStats{};
}

template <class T>
inline std::optional<SelfCollisionStats> SolverT<T>::last_self_collision() const {
  return self_ ? std::optional<SelfCollisionStats>(self_->last()) : std::nullopt;
}

template <class T>
inline std::optional<ClothContactStats> SolverT<T>::last_cloth_contact() const {
  return cloth_contact_ ? std::optional<ClothContactStats>(cloth_contact_->last()) : std::nullopt;
}

template <class T>
inline DeviceCloth* SolverT<T>::device_cloth() const {
  return backend_ ? backend_->device_cloth() : nullptr;
}

template <class T>
inline Vec3d SolverT<T>::position(int vertex) const {
  sync_state();
  return vec3_at(state_.pos, vertex);
}

template <class T>
inline Vec3d SolverT<T>::velocity(int vertex) const {
  sync_state();
  return vec3_at(state_.vel, vertex);
}

template <class T>
inline std::optional<Divergence> SolverT<T>::energy_divergence(const Energy& e) const {
  sync_state();
  Divergence d;
  if (!monitor_.check_energy(model_, state_, e, steps_, time(), d)) return std::nullopt;
  return d;
}

template <class T>
inline void SolverT<T>::copy_positions(float* xyz) const {
  sync_state();
  copy_xyz(state_.pos, xyz);
}

template <class T>
inline void SolverT<T>::copy_velocities(float* xyz) const {
  sync_state();
  copy_xyz(state_.vel, xyz);
}

extern template class SolverT<float>;
extern template class SolverT<double>;

}  // namespace clothlab
