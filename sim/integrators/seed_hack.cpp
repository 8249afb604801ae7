// The assignment's "hack" (design.md): with a = a(t, x, v) and dv = a dt,
//   x' = x + (v + dv) dt + a dt^2 / 2,   v' = v + dv.
// It is symplectic Euler plus an extra a dt^2 / 2 in the position: first order, slightly more
// dissipative-looking in practice, kept so the course's reference behaviour can be compared.
#include "sim/core/parallel.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {
namespace {

template <class T>
class SeedHack final : public Integrator<T> {
 public:
  explicit SeedHack(std::size_t n) { f_.resize(n); }

  void step(const System<T>& sys, State<T>& s, double t, T dt) override {
    sys.forces(t, s.pos, s.vel, f_);
    const T* inv_m = sys.model.inv_mass.data();
    const T half_dt2 = T(0.5) * dt * dt;
    for_each_block(s.pos.size(), sys.threads, [&](std::size_t b, std::size_t e) {
      for (int a = 0; a < 3; ++a) {
        T* x = s.pos.axis(a).data();
        T* v = s.vel.axis(a).data();
        const T* f = f_.axis(a).data();
#pragma omp simd
        for (std::size_t i = b; i < e; ++i) {
          const T acc = f[i] * inv_m[i];
          const T dv = acc * dt;
          x[i] += (v[i] + dv) * dt + acc * half_dt2;
          v[i] += dv;
        }
      }
    });
  }

 private:
  Vec3Array<T> f_;
};

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_seed_hack(std::size_t n) {
  return std::make_unique<SeedHack<T>>(n);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_seed_hack)

}  // namespace clothlab
