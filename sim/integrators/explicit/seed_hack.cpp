// The assignment's "hack" (docs/design.md): with a = a(t, x, v) and dv = a dt,
//   x' = x + (v + dv) dt + a dt^2 / 2,   v' = v + dv.
// It is symplectic Euler plus an extra a dt^2 / 2 in the position: first order, kept so the
// course's reference behaviour can be compared.
#include "sim/integrators/explicit/single_evaluation.hpp"

namespace clothlab {
namespace {

struct SeedHackRule {
  template <class T>
  static void apply(T& x, T& v, T a, T dt) {
    const T dv = a * dt;
    x += (v + dv) * dt + T(0.5) * a * dt * dt;
    v += dv;
  }
};

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_seed_hack(const Model<T>& m, const SolverSpec& /*spec*/) {
  return std::make_unique<SingleEvaluation<T, SeedHackRule>>(m.n);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_seed_hack)

}  // namespace clothlab
