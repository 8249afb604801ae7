// The skeleton shared by the one-stage integrators (explicit Euler, symplectic Euler, seed_hack):
// evaluate the force once at the start of the step, then update every vertex independently with
// the integrator's Rule:  Rule::apply(x, v, a, dt)  for each coordinate, a = f / m. On grid
// cloths without wind the update runs inside the force sweep (sim/forces/fused_band_pass.hpp).
#pragma once

#include "sim/integrators/integrator.hpp"

namespace clothlab {

template <class T, class Rule>
class SingleEvaluation final : public Integrator<T> {
 public:
  explicit SingleEvaluation(std::size_t n) { f_.resize(n); }

  void step(const System<T>& sys, State<T>& s, double t, T dt) override {
    sys.forces_then(t, s.pos, s.vel, f_,
                    [&](std::size_t b, std::size_t e) { apply_rule(sys.model, s, dt, b, e); });
  }

 private:
  // Rule on vertices [b, e), whose forces f_ are final.
  void apply_rule(const Model<T>& m, State<T>& s, T dt, std::size_t b, std::size_t e) const {
    const T* inv_m = m.inv_mass.data();
    for (int a = 0; a < 3; ++a) {
      T* x = s.pos.axis(a).data();
      T* v = s.vel.axis(a).data();
      const T* f = f_.axis(a).data();
#pragma omp simd
      for (std::size_t i = b; i < e; ++i) Rule::apply(x[i], v[i], f[i] * inv_m[i], dt);
    }
  }

  Vec3Array<T> f_;
};

}  // namespace clothlab
