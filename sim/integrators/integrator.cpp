#include "sim/integrators/integrator.hpp"

namespace clothlab {

template <class T>
std::unique_ptr<Integrator<T>> make_integrator(const Model<T>& m, const SolverSpec& spec) {
  switch (spec.integrator) {
    case IntegratorKind::explicit_euler:
      return make_explicit_euler<T>(m, spec);
    case IntegratorKind::symplectic_euler:
      return make_symplectic_euler<T>(m, spec);
    case IntegratorKind::seed_hack:
      return make_seed_hack<T>(m, spec);
    case IntegratorKind::verlet:
      return make_verlet<T>(m, spec);
    case IntegratorKind::rk4:
      return make_rk4<T>(m, spec);
    case IntegratorKind::implicit_euler:
      return make_implicit_euler<T>(m, spec);
    case IntegratorKind::xpbd:
      return make_xpbd<T>(m, spec);
    case IntegratorKind::local_global:
      return make_local_global<T>(m, spec);
    case IntegratorKind::vbd:
      return make_vbd<T>(m, spec);
    case IntegratorKind::bdf2:
      return make_bdf2<T>(m, spec);
  }
  return nullptr;
}

template std::unique_ptr<Integrator<float>> make_integrator<float>(const Model<float>&,
                                                                   const SolverSpec&);
template std::unique_ptr<Integrator<double>> make_integrator<double>(const Model<double>&,
                                                                     const SolverSpec&);

}  // namespace clothlab
