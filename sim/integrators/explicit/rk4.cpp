// Classical fourth-order Runge-Kutta on the first-order system (x, v)' = (v, a(t, x, v)).
// Four force evaluations per step; the reference integrator of the accuracy work.
#include "sim/core/parallel.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {
namespace {

template <class T>
class Rk4 final : public Integrator<T> {
 public:
  explicit Rk4(std::size_t n) {
    f_.resize(n);
    xs_.resize(n);
    vs_.resize(n);
    sum_x_.resize(n);
    sum_v_.resize(n);
  }

  void step(const System<T>& sys, State<T>& s, double t, T dt) override {
    const T h = dt, half = T(0.5) * dt;
    // Stage 1 at (x, v); the stage state for stage 2 is (x + h/2 v, v + h/2 a1). Each stage's
    // update runs inside its force sweep where it can (System::forces_then): it writes the
    // stage state the sweep reads only where no spring still reads it.
    sys.forces_then(t, s.pos, s.vel, f_, stage_update(sys, s, s.vel, half, true, T(1)));
    sys.forces_then(t + 0.5 * h, xs_, vs_, f_, stage_update(sys, s, vs_, half, false, T(2)));
    sys.forces_then(t + 0.5 * h, xs_, vs_, f_, stage_update(sys, s, vs_, h, false, T(2)));
    // Combine: x' = x + h/6 (v1 + 2 v2 + 2 v3 + v4), v' = v + h/6 (a1 + 2 a2 + 2 a3 + a4).
    const T* inv_m = sys.model.inv_mass.data();
    const T sixth = h / T(6);
    sys.forces_then(t + h, xs_, vs_, f_, [&](std::size_t b, std::size_t e) {
      for (int a = 0; a < 3; ++a) {
        T* x = s.pos.axis(a).data();
        T* v = s.vel.axis(a).data();
        const T *vs = vs_.axis(a).data(), *f = f_.axis(a).data();
        const T *sx = sum_x_.axis(a).data(), *sv = sum_v_.axis(a).data();
#pragma omp simd
        for (std::size_t i = b; i < e; ++i) {
          x[i] += sixth * (sx[i] + vs[i]);
          v[i] += sixth * (sv[i] + f[i] * inv_m[i]);
        }
      }
    });
  }

 private:
  // The update after a stage's force: adds weight * (stage velocity, stage acceleration) to the
  // sums, then forms the next stage state (x + c v_stage, v + c a_stage) on vertices [b, e).
  // `stage_vel` may alias vs_: each element is read before it is overwritten.
  auto stage_update(const System<T>& sys, const State<T>& s, const Vec3Array<T>& stage_vel, T c,
                    bool first, T weight) {
    return [this, &sys, &s, &stage_vel, c, first, weight](std::size_t b, std::size_t e) {
      const T* inv_m = sys.model.inv_mass.data();
      for (int a = 0; a < 3; ++a) {
        const T *x = s.pos.axis(a).data(), *v = s.vel.axis(a).data();
        const T *sv_in = stage_vel.axis(a).data(), *f = f_.axis(a).data();
        T *xs = xs_.axis(a).data(), *vs = vs_.axis(a).data();
        T *sx = sum_x_.axis(a).data(), *sv = sum_v_.axis(a).data();
        // simd: the aliasing is element by element (vs[i] read, then written), which a vector
        // does as a scalar loop would; without the pragma GCC's runtime overlap check sent
        // stages 2 and 3 (stage_vel is vs_) to its scalar loop.
#pragma omp simd
        for (std::size_t i = b; i < e; ++i) {
          const T vel = sv_in[i], acc = f[i] * inv_m[i];
          sx[i] = first ? vel : sx[i] + weight * vel;
          sv[i] = first ? acc : sv[i] + weight * acc;
          xs[i] = x[i] + c * vel;
          vs[i] = v[i] + c * acc;
        }
      }
    };
  }

  Vec3Array<T> f_, xs_, vs_, sum_x_, sum_v_;
};

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_rk4(const Model<T>& m, const SolverSpec& /*spec*/) {
  return std::make_unique<Rk4<T>>(m.n);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_rk4)

}  // namespace clothlab
