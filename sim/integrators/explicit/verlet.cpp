// Velocity Verlet (Swope et al. 1982; kick-drift-kick), second order and symplectic for
// position-dependent forces, one force evaluation per step (the end-of-step force is reused as
// the next step's start force). For velocity-dependent forces (damping, drag, wind) the
// end-of-step force is evaluated at the predicted velocity v_half + a dt/2, an O(dt^2)-accurate
// estimate of v', which keeps the method second order instead of dropping to first.
#include "sim/core/parallel.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {
namespace {

template <class T>
class Verlet final : public Integrator<T> {
 public:
  explicit Verlet(std::size_t n) {
    f_.resize(n);
    v_pred_.resize(n);
  }

  void step(const System<T>& sys, State<T>& s, double t, T dt) override {
    if (!force_valid_) sys.forces(t, s.pos, s.vel, f_);
    const T* inv_m = sys.model.inv_mass.data();
    const T half_dt = T(0.5) * dt;
    // Kick by half a step and drift; predict the end velocity for the force evaluation.
    for_each_block(s.pos.size(), sys.threads, [&](std::size_t b, std::size_t e) {
      for (int a = 0; a < 3; ++a) {
        T* x = s.pos.axis(a).data();
        T* v = s.vel.axis(a).data();
        T* vp = v_pred_.axis(a).data();
        const T* f = f_.axis(a).data();
#pragma omp simd
        for (std::size_t i = b; i < e; ++i) {
          const T kick = half_dt * f[i] * inv_m[i];
          v[i] += kick;
          x[i] += dt * v[i];
          vp[i] = v[i] + kick;
        }
      }
    });
    // The second kick, inside the force sweep where it can be (System::forces_then).
    sys.forces_then(t + static_cast<double>(dt), s.pos, v_pred_, f_,
                    [&](std::size_t b, std::size_t e) {
                      for (int a = 0; a < 3; ++a) {
                        T* v = s.vel.axis(a).data();
                        const T* f = f_.axis(a).data();
#pragma omp simd
                        for (std::size_t i = b; i < e; ++i) v[i] += half_dt * f[i] * inv_m[i];
                      }
                    });
    force_valid_ = true;
  }

  void invalidate() override {
    force_valid_ = false;
  }

 private:
  Vec3Array<T> f_, v_pred_;
  bool force_valid_ = false;
};

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_verlet(const Model<T>& m, const SolverSpec& /*spec*/) {
  return std::make_unique<Verlet<T>>(m.n);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_verlet)

}  // namespace clothlab
