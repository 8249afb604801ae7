// One interface for every time integrator. An integrator advances (x, v) by one fixed step dt;
// it owns the scratch buffers it needs (allocated at construction, so stepping never allocates).
#pragma once

#include <memory>

#include "sim/core/parallel.hpp"
#include "sim/forces/force_field.hpp"
#include "sim/forces/fused_band_pass.hpp"
#include "sim/model/model.hpp"

namespace clothlab {

template <class T>
struct State {
  Vec3Array<T> pos, vel;
};

// What an integrator may use: the model, force evaluation and the thread count.
template <class T>
struct System {
  const Model<T>& model;
  ForceWorkspace<T>& workspace;
  int threads = 1;

  // false: forces_then() makes two passes where it could make one (tests compare the two).
  bool fuse = true;

  void forces(double t, const Vec3Array<T>& x, const Vec3Array<T>& v, Vec3Array<T>& f) const {
    compute_forces(model, t, x, v, f, workspace, threads);
  }

  // f = F(t, x, v), then update(b, e) on vertex ranges that cover every vertex once, each as soon
  // as its force is final: inside the force sweep on grid cloths without wind
  // (sim/forces/fused_band_pass.hpp), else as a second pass over vertex blocks. update may write
  // x and v in its own range.
  template <class Update>
  void forces_then(double t, const Vec3Array<T>& x, const Vec3Array<T>& v, Vec3Array<T>& f,
                   Update&& update) const {
    if (fuse && band_pass_fusable(model)) {
      forces_then_update(model, x, v, f, workspace, threads, update);
      return;
    }
    forces(t, x, v, f);
    for_each_block(model.n, threads, update);
  }
};

// What an iterative integrator did in its last step (PCG iterations and relative residual for
// implicit_euler; sweeps for the constraint and local/global methods). Explicit methods report 0.
struct SolveStats {
  int iterations = 0;
  double residual = 0.0;  // relative: |r| / |b| for PCG, 0 where not measured
  bool converged = true;  // false when PCG stopped at its iteration cap
  int solves = 0;         // linear solves (the implicit methods' Newton iterations)
};

template <class T>
class Integrator {
 public:
  virtual ~Integrator() = default;
  // Advances s from time t to t + dt.
  virtual void step(const System<T>& sys, State<T>& s, double t, T dt) = 0;
  // The state or the model changed outside step() (push, reset, parameter edit): forget any
  // value cached from the previous step.
  virtual void invalidate() {}
  // The collision response moved some vertices after step(): forget values cached from the
  // state (Verlet's end-of-step force). A warm start that only guesses may stay.
  virtual void state_corrected() { invalidate(); }
  virtual SolveStats last_stats() const { return {}; }
};

// The integrator the solver spec names, with its parameters (iterations, CG tolerance), sized
// for the model (allocated here, so stepping never allocates).
template <class T>
std::unique_ptr<Integrator<T>> make_integrator(const Model<T>& m, const SolverSpec& spec);

// Factories, one per file in sim/integrators/.
template <class T>
std::unique_ptr<Integrator<T>> make_explicit_euler(const Model<T>& m, const SolverSpec& spec);
template <class T>
std::unique_ptr<Integrator<T>> make_symplectic_euler(const Model<T>& m, const SolverSpec& spec);
template <class T>
std::unique_ptr<Integrator<T>> make_seed_hack(const Model<T>& m, const SolverSpec& spec);
template <class T>
std::unique_ptr<Integrator<T>> make_verlet(const Model<T>& m, const SolverSpec& spec);
template <class T>
std::unique_ptr<Integrator<T>> make_rk4(const Model<T>& m, const SolverSpec& spec);
template <class T>
std::unique_ptr<Integrator<T>> make_implicit_euler(const Model<T>& m, const SolverSpec& spec);
template <class T>
std::unique_ptr<Integrator<T>> make_xpbd(const Model<T>& m, const SolverSpec& spec);
template <class T>
std::unique_ptr<Integrator<T>> make_local_global(const Model<T>& m, const SolverSpec& spec);
template <class T>
std::unique_ptr<Integrator<T>> make_vbd(const Model<T>& m, const SolverSpec& spec);
template <class T>
std::unique_ptr<Integrator<T>> make_bdf2(const Model<T>& m, const SolverSpec& spec);

}  // namespace clothlab

// Explicit instantiation of a factory for float and double.
#define CLOTHLAB_INSTANTIATE_FACTORY(name)                                                         \
  template std::unique_ptr<Integrator<float>> name<float>(const Model<float>&, const SolverSpec&); \
  template std::unique_ptr<Integrator<double>> name<double>(const Model<double>&,                  \
                                                            const SolverSpec&);
