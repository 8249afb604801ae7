#include "sim/integrators/integrator.hpp"

namespace clothlab {

template <class T>
std::unique_ptr<Integrator<T>> make_integrator(IntegratorKind kind, std::size_t n) {
  switch (kind) {
    case IntegratorKind::explicit_euler:
      return make_explicit_euler<T>(n);
    case IntegratorKind::symplectic_euler:
      return make_symplectic_euler<T>(n);
    case IntegratorKind::seed_hack:
      return make_seed_hack<T>(n);
    case IntegratorKind::verlet:
      return make_verlet<T>(n);
    case IntegratorKind::rk4:
      return make_rk4<T>(n);
  }
  return nullptr;
}

template std::unique_ptr<Integrator<float>> make_integrator<float>(IntegratorKind, std::size_t);
template std::unique_ptr<Integrator<double>> make_integrator<double>(IntegratorKind, std::size_t);

}  // namespace clothlab
