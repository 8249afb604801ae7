// Forward (explicit) Euler: x' = x + dt v, v' = v + dt a(t, x, v). First order; adds energy on
// every oscillation (|1 + i w dt| > 1), so it is unstable without damping. Kept as the baseline.
#include "sim/integrators/explicit/single_evaluation.hpp"

namespace clothlab {
namespace {

struct ExplicitEulerRule {
  template <class T>
  static void apply(T& x, T& v, T a, T dt) {
    x += dt * v;
    v += dt * a;
  }
};

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_explicit_euler(const Model<T>& m, const SolverSpec& /*spec*/) {
  return std::make_unique<SingleEvaluation<T, ExplicitEulerRule>>(m.n);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_explicit_euler)

}  // namespace clothlab
