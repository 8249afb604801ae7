// One interface for every time integrator. An integrator advances (x, v) by one fixed step dt;
// it owns the scratch buffers it needs (allocated at construction, so stepping never allocates).
#pragma once

#include <memory>

#include "sim/forces/force_field.hpp"
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

  void forces(double t, const Vec3Array<T>& x, const Vec3Array<T>& v, Vec3Array<T>& f) const {
    compute_forces(model, t, x, v, f, workspace, threads);
  }
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
};

template <class T>
std::unique_ptr<Integrator<T>> make_integrator(IntegratorKind kind, std::size_t n);

// Factories, one per file in sim/integrators/.
template <class T>
std::unique_ptr<Integrator<T>> make_explicit_euler(std::size_t n);
template <class T>
std::unique_ptr<Integrator<T>> make_symplectic_euler(std::size_t n);
template <class T>
std::unique_ptr<Integrator<T>> make_seed_hack(std::size_t n);
template <class T>
std::unique_ptr<Integrator<T>> make_verlet(std::size_t n);
template <class T>
std::unique_ptr<Integrator<T>> make_rk4(std::size_t n);

}  // namespace clothlab

// Explicit instantiation of a factory for float and double.
#define CLOTHLAB_INSTANTIATE_FACTORY(name)                                \
  template std::unique_ptr<Integrator<float>> name<float>(std::size_t n); \
  template std::unique_ptr<Integrator<double>> name<double>(std::size_t n);
