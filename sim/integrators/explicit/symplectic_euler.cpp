// Symplectic (semi-implicit) Euler: v' = v + dt a(t, x, v), x' = x + dt v'. First order but
// symplectic: energy oscillates without drift for conservative forces (Hairer, Lubich & Wanner,
// "Geometric Numerical Integration", ch. VI.3). Stable for dt < 2 / omega_max.
#include "sim/integrators/explicit/single_evaluation.hpp"

namespace clothlab {
namespace {

struct SymplecticEulerRule {
  template <class T>
  static void apply(T& x, T& v, T a, T dt) {
    v += dt * a;
    x += dt * v;
  }
};

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_symplectic_euler(const Model<T>& m,
                                                     const SolverSpec& /*spec*/) {
  return std::make_unique<SingleEvaluation<T, SymplecticEulerRule>>(m.n);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_symplectic_euler)

}  // namespace clothlab
