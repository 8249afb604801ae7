// BDF2, the second-order backward differentiation formula (Curtiss & Hirschfelder 1952; Hairer &
// Wanner, "Solving Ordinary Differential Equations II", Sec. III.1), for cloth as in Choi & Ko
// 2002 ("Stable but responsive cloth", SIGGRAPH, eq. (4)), with a constant step h:
//   x_(n+1) - 4/3 x_n + 1/3 x_(n-1) = 2/3 h v_(n+1),
//   v_(n+1) - 4/3 v_n + 1/3 v_(n-1) = 2/3 h M^-1 F(x_(n+1), v_(n+1)).
// With x~ = 4/3 x_n - 1/3 x_(n-1), v~ = 4/3 v_n - 1/3 v_(n-1) and h~ = 2/3 h this is
//   x_(n+1) = x~ + h~ v_(n+1),   v_(n+1) = v~ + h~ M^-1 F(x_(n+1), v_(n+1)):
// exactly a backward-Euler step of size h~ from the state (x~, v~). So BDF2 hands that step to a
// backward-Euler solver of its own (solver.bdf2_solver: Newton with PCG, implicit_euler.cpp with
// solver.newton_iterations; or vertex block descent, vbd.cpp with solver.iterations), and keeps
// the previous state. The first step, and the first after invalidate() (a push, a reset, an
// edit), has no history and is one backward-Euler step of size h. Pinned vertices keep x~ = x_n
// exactly (4/3 x - 1/3 x is not x in floating point), so pins do not creep.
//
// For the linear oscillator BDF2's principal root of (3/2 - z) r^2 - 2 r + 1/2 = 0, z = i h w,
// gives the energy factor |r|^2 per step, 1 - (h w)^4 / 2 + O((h w)^6) against backward Euler's
// 1 / (1 + (h w)^2): BDF2 damps the well-resolved modes far less (tests/bdf2_test.cpp checks
// the factor over one period).
#include <memory>
#include <utility>

#include "sim/core/parallel.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {
namespace {

template <class T>
class Bdf2 final : public Integrator<T> {
 public:
  Bdf2(const Model<T>& m, const SolverSpec& spec) {
    SolverSpec inner = spec;
    inner.integrator =
        spec.bdf2_solver == StepSolver::vbd ? IntegratorKind::vbd : IntegratorKind::implicit_euler;
    inner_ = make_integrator<T>(m, inner);
    for (Vec3Array<T>* v : {&x_prev_, &v_prev_, &x_now_, &v_now_}) v->resize(m.n);
  }

  void step(const System<T>& sys, State<T>& s, double t, T h) override {
    if (!history_) {
      x_prev_ = s.pos;  // copies into the sized buffers: no allocation
      v_prev_ = s.vel;
      inner_->step(sys, s, t, h);
      history_ = true;
      return;
    }
    x_now_ = s.pos;
    v_now_ = s.vel;
    const Model<T>& m = sys.model;
    for_each_block(m.n, sys.threads, [&](std::size_t b, std::size_t e) {
      for (int a = 0; a < 3; ++a) {
        T* __restrict x = s.pos.axis(a).data();
        T* __restrict v = s.vel.axis(a).data();
        const T* __restrict xp = x_prev_.axis(a).data();
        const T* __restrict vp = v_prev_.axis(a).data();
        for (std::size_t i = b; i < e; ++i) {
          if (m.inv_mass[i] == T(0)) continue;
          x[i] = T(4) / T(3) * x[i] - T(1) / T(3) * xp[i];
          v[i] = T(4) / T(3) * v[i] - T(1) / T(3) * vp[i];
        }
      }
    });
    // The step's forces are those at its end: t + h, reached from x~ in h~ = 2/3 h.
    inner_->step(sys, s, t + double(h) / 3.0, T(2) / T(3) * h);
    std::swap(x_prev_, x_now_);
    std::swap(v_prev_, v_now_);
  }

  void invalidate() override {
    history_ = false;
    inner_->invalidate();
  }
  // A collision response moved vertices after the step: the corrected state is x_n, and the
  // history before it stays valid.
  void state_corrected() override { inner_->state_corrected(); }
  SolveStats last_stats() const override { return inner_->last_stats(); }

 private:
  std::unique_ptr<Integrator<T>> inner_;
  bool history_ = false;
  Vec3Array<T> x_prev_, v_prev_;  // x_(n-1), v_(n-1)
  Vec3Array<T> x_now_, v_now_;    // scratch: x_n, v_n while the step runs
};

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_bdf2(const Model<T>& m, const SolverSpec& spec) {
  return std::make_unique<Bdf2<T>>(m, spec);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_bdf2)

}  // namespace clothlab
