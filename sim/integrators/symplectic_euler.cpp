// Symplectic (semi-implicit) Euler: v' = v + dt a(t, x, v), x' = x + dt v'. First order but
// symplectic: energy oscillates without drift for conservative forces (Hairer, Lubich & Wanner,
// "Geometric Numerical Integration", ch. VI.3). Stable for dt < 2 / omega_max.
#include "sim/core/parallel.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {
namespace {

template <class T>
class SymplecticEuler final : public Integrator<T> {
 public:
  explicit SymplecticEuler(std::size_t n) { f_.resize(n); }

  void step(const System<T>& sys, State<T>& s, double t, T dt) override {
    sys.forces(t, s.pos, s.vel, f_);
    const T* inv_m = sys.model.inv_mass.data();
    for_each_block(s.pos.size(), sys.threads, [&](std::size_t b, std::size_t e) {
      for (int a = 0; a < 3; ++a) {
        T* x = s.pos.axis(a).data();
        T* v = s.vel.axis(a).data();
        const T* f = f_.axis(a).data();
#pragma omp simd
        for (std::size_t i = b; i < e; ++i) {
          v[i] += dt * f[i] * inv_m[i];
          x[i] += dt * v[i];
        }
      }
    });
  }

 private:
  Vec3Array<T> f_;
};

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_symplectic_euler(std::size_t n) {
  return std::make_unique<SymplecticEuler<T>>(n);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_symplectic_euler)

}  // namespace clothlab
