// Backward Euler solved by Newton's method. The first iteration is Baraff & Witkin's linearised
// step (1998, "Large steps in cloth simulation", SIGGRAPH, eq. (16)):
//   (M - h D - h^2 K) dv = h (f0 + h K v0),   v1 = v0 + dv,   x1 = x0 + h v1,
// with f0 = F(t, x0, v0) the full force every integrator uses (springs with along-spring
// damping, gravity, linear drag, wind), K = df/dx of the springs and D = df/dv (along-spring
// damping c d d^T per spring, and -drag I). Each further iteration (solver.newton_iterations,
// 0 -> kDefaultNewton) is a Newton step on backward Euler's residual in the end velocity v,
//   R(v) = M (v - v0) - h F(t + h, x0 + h v, v),
//   (M - h D - h^2 K) delta = -R,   v += delta,   x = x0 + h v,
// with K and D at the current iterate; the PCG starts from 0. First order; unconditionally
// stable for the springs. On the 32 x 32 accuracy sheet at 1/60 s the linearised step alone is
// 100-620 mm from an accurate run where the converged step is 43-47 mm (docs/solver.md), so
// Newton iterates by default (up to kDefaultNewton iterations, until newton_tolerance).
//
// Per spring (a, b) with d = (x_b - x_a) / l the stiffness block is
//   Ks = k [d d^T + max(0, 1 - L/l) (I - d d^T)],   df_a/dx_a = -Ks,   df_a/dx_b = Ks.
// The max(0, .) drops the transverse term of a compressed spring, which is negative and would
// make the system indefinite (the compression instability of Choi & Ko 2002; Baraff-Witkin's
// filtered formulation): the projected K is negative semi-definite, so A is symmetric positive
// definite and conjugate gradients apply. Left out of the Jacobian: the derivative of the damping
// force's direction with respect to x (as in Baraff-Witkin) and the whole wind force, which stays
// explicit inside f0 (its velocity term is weak next to the springs, and its position term,
// through the surface normals, is neither symmetric nor cheap).
//
// The matrix, stored matrix-free per spring, and its block-Jacobi preconditioner:
// newton_matrix.hpp.
//
// Solve: preconditioned conjugate gradients, block-Jacobi preconditioner (the inverse of each
// vertex's 3x3 diagonal block of A) or, with solver.linear_solver (auto: once block Jacobi's
// solves grow long on a grid), one aggregation multigrid K-cycle per iteration (multigrid.hpp),
// with flexible CG's beta = -z.q / p.q (Notay 2000, "Flexible conjugate gradients", SIAM J. Sci.
// Comput. 22(4)), since the K-cycle is not a fixed linear map. Pinned vertices (inv_mass 0) are
// filtered as in Baraff-Witkin: their dv, residual and search direction stay exactly 0. PCG starts
// from the previous step's dv (on the falling 32x32 sheet 36 instead of 45 iterations per step at
// dt = 1e-3, 131 instead of 137 at 1/60) unless invalidate() said the state changed, and stops
// when |r| <= tol |b| (r the recursively updated residual; tol = cg_tolerance, or automatic: see
// pcg_tolerance) or after cg_max_iterations
// (then last_stats().converged is false). Dot products are accumulated in double, one partial sum
// per 512-vertex block, added in block order.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "sim/core/parallel.hpp"
#include "sim/integrators/integrator.hpp"
#include "sim/integrators/newton/multigrid.hpp"
#include "sim/integrators/newton/newton_matrix.hpp"

namespace clothlab {
namespace {

// Partial sums per vertex block: |b|^2, r.r or p.q first, then r.z, then the warm start's r.r.
constexpr std::size_t kSums = 3;

constexpr int kDefaultNewton = 8;

// PCG's relative tolerance when solver.cg_tolerance is 0 (automatic). The single linearised
// step is the whole solve, so it is solved tightly. When Newton iterates, each linear solve only
// has to point the next iteration the right way (inexact Newton: Dembo, Eisenstat & Steihaug
// 1982, "Inexact Newton methods", SIAM J. Numer. Anal. 19(2); the outer iteration recomputes the
// true residual every time). Measured on the 32 x 32 accuracy sheet at 1/60 s, k0 = 1e3 / 1e4 /
// 1e5, RMS at 0.5 s from RK4 (`clothlab bench --suite largestep`, one run): bdf2 lands 20.6 /
// 20.5 / 23.6 mm with 1e-2 against 20.5 / 19.3 / 23.6 mm with 1e-6, at 0.46 / 0.49 / 0.63 of
// the cost; implicit_euler 47.5 / 47.4 / 51.1 mm against 47.4 / 47.3 / 50.1 mm at 0.51 / 0.59 /
// 0.35 of the cost. With 3e-2 bdf2 was 77.6 mm at k0 = 1e5 and with 1e-1 105 mm, so 1e-2 is
// the loosest that keeps the converged accuracy.
constexpr double kLinearisedTolerance = 1e-6;
constexpr double kNewtonForcing = 1e-2;

int newton_iterations(const SolverSpec& spec) {
  return spec.newton_iterations > 0 ? spec.newton_iterations : kDefaultNewton;
}

// solver.linear_solver = "auto" starts with block Jacobi and takes multigrid, on grid and tube
// cloths, for the rest of the run once a block-Jacobi solve needs more than this many iterations
// (a large or stiff sheet): a K-cycle costs 6-12 block-Jacobi iterations (docs/solver.md,
// "Multigrid preconditioner", has the measurements behind the number).
constexpr int kMultigridAfter = 150;

// Whether the solver keeps a multigrid hierarchy: when asked for, or for "auto" on grid and tube
// cloths of at least kMultigridFrom vertices (below, block Jacobi's solves stay short). From
// kMultigridAlways vertices "auto" starts with it: there a block-Jacobi solve of even 100
// iterations costs more than the multigrid's (256^2: 361 against 1752 ms a frame on the
// accuracy sheet, 700 against 1332 ms a step on one thread on the default scene).
constexpr std::size_t kMultigridFrom = 256;
constexpr std::size_t kMultigridAlways = 65536;

template <class T>
bool multigrid_possible(const Model<T>& m, const SolverSpec& spec) {
  if (spec.linear_solver != LinearSolver::automatic)
    return spec.linear_solver == LinearSolver::multigrid;
  return m.n >= kMultigridFrom &&
         std::none_of(m.cloths.begin(), m.cloths.end(), [](const ClothRange& c) { return c.mesh; });
}

double pcg_tolerance(const SolverSpec& spec) {
  if (spec.cg_tolerance > 0.0) return spec.cg_tolerance;
  return newton_iterations(spec) > 1 ? kNewtonForcing : kLinearisedTolerance;
}

template <class T>
class ImplicitEuler final : public Integrator<T> {
 public:
  ImplicitEuler(const Model<T>& m, const SolverSpec& spec);

  void step(const System<T>& sys, State<T>& s, double t, T dt) override;

  // The previous dv no longer predicts the next one.
  void invalidate() override { warm_ = false; }
  // After a collision response the previous dv is still a good first guess.
  void state_corrected() override {}

  SolveStats last_stats() const override { return stats_; }

 private:
  // One linear solve (M - h D - h^2 K) dv = b by PCG, warm-started from the last step's first
  // dv on the first Newton iteration, from 0 on later ones.
  SolveStats solve(const Model<T>& m, const State<T>& state, T h, bool first, int threads);

  // |delta|_M / |v - v0|_M after a Newton iteration (delta in dv_): how much the last
  // correction changed the step's change of velocity, in the mass-weighted norm.
  double correction_ratio(const Model<T>& m, const Vec3Array<T>& vel, int threads);

  // v += dv; then x += h v on the first iteration (x was x0), x = x0 + h v on later ones.
  void update(State<T>& s, T h, bool first, int threads);

  // For vertices [b, e): the right side b (first: h (f0 + h K v0); later: h F - M (v - v0)),
  // the matrix's slots and preconditioner there, r = b - A dv (warm) or r = b, dv = 0 (cold),
  // and with block Jacobi z = P r and p = z. Partial sums: |b|^2, r.z (block Jacobi) and r.r.
  void setup_block(const Model<T>& m, const State<T>& state, T h, bool warm, bool first,
                   std::size_t blk, std::size_t b, std::size_t e);

  // dv += alpha p, r -= alpha q and with block Jacobi z = P r on [b, e); partial sums r.r and
  // (block Jacobi) r.z.
  void update_residual(T alpha, std::size_t blk, std::size_t b, std::size_t e);

  // u.w over [b, e), in double.
  static double dot(const Vec3Array<T>& u, const Vec3Array<T>& w, std::size_t b, std::size_t e);

  // The per-block partial sums, added in block order (the same for any thread count).
  std::array<double, kSums> sum_partials() const;

  std::size_t n_;
  double tolerance_;
  int max_iterations_;
  int newton_;               // Newton iterations per step, at most
  double newton_tolerance_;  // stop once |delta|_M <= this |v - v0|_M
  NewtonMatrix<T> matrix_;
  std::unique_ptr<MultigridPreconditioner<T>> multigrid_;  // grid cloths (solver.linear_solver)
  bool use_multigrid_ = false;                             // multigrid_ is PCG's preconditioner now

  Vec3Array<T> f0_;
  Vec3Array<T> dv_, r_, z_, p_, q_;
  Vec3Array<T> first_dv_, x0_, v0_;  // newton_ > 1: the first dv (warm start), x0 and v0
  Vec3Array<T> scratch_;             // multigrid: its cycle's residuals
  std::vector<double> partials_;     // kSums per vertex block
  bool warm_ = false;
  SolveStats stats_;
};

template <class T>
inline ImplicitEuler<T>::ImplicitEuler(const Model<T>& m, const SolverSpec& spec)
    : n_(m.n),
      tolerance_(pcg_tolerance(spec)),
      max_iterations_(spec.cg_max_iterations),
      newton_(newton_iterations(spec)),
      newton_tolerance_(spec.newton_tolerance),
      matrix_(m) {
  f0_.resize(n_);
  for (Vec3Array<T>* v : {&dv_, &r_, &z_, &p_, &q_}) v->resize(n_);
  if (newton_ > 1)
    for (Vec3Array<T>* v : {&first_dv_, &x0_, &v0_}) v->resize(n_);
  partials_.assign(kSums * block_count(n_), 0.0);
  if (multigrid_possible(m, spec)) {
    multigrid_ = std::make_unique<MultigridPreconditioner<T>>(m, matrix_);
    scratch_.resize(n_);
    use_multigrid_ = spec.linear_solver == LinearSolver::multigrid || m.n >= kMultigridAlways;
  }
}

template <class T>
inline void ImplicitEuler<T>::step(const System<T>& sys, State<T>& s, double t, T dt) {
  const T h = dt;
  if (newton_ > 1) {
    x0_ = s.pos;  // copies into the sized buffers: no allocation
    v0_ = s.vel;
  }
  SolveStats total;
  for (int k = 0; k < newton_; ++k) {
    const bool first = k == 0;
    // Later iterations solve for delta in dv_'s place; the first dv stays the next warm start.
    if (k == 1) std::swap(dv_, first_dv_);
    sys.forces(first ? t : t + double(h), s.pos, s.vel, f0_);
    const SolveStats st = solve(sys.model, s, h, first, sys.threads);
    total.iterations += st.iterations;
    ++total.solves;
    if (multigrid_ && st.iterations > kMultigridAfter) use_multigrid_ = true;
    total.residual = std::max(total.residual, st.residual);
    total.converged = total.converged && st.converged;
    update(s, h, first, sys.threads);
    if (!first && correction_ratio(sys.model, s.vel, sys.threads) <= newton_tolerance_) break;
  }
  if (newton_ > 1) std::swap(dv_, first_dv_);
  stats_ = total;
  warm_ = true;
}

template <class T>
inline SolveStats ImplicitEuler<T>::solve(const Model<T>& m, const State<T>& state, T h, bool first,
                                          int threads) {
  // Slot blocks, preconditioner, right side and initial residual, per vertex block.
  const bool warm = first && warm_;
  for_each_block_indexed(n_, threads, [&](std::size_t blk, std::size_t b, std::size_t e) {
    setup_block(m, state, h, warm, first, blk, b, e);
  });
  const auto [bb, rz_start, rr_start] = sum_partials();
  double rz = rz_start, rr = rr_start;
  if (use_multigrid_) {  // the coarse operators of this iteration's matrix, z = K(r), p = z
    multigrid_->refresh(m, matrix_, h, threads);
    rz = multigrid_->apply(m, matrix_, h, r_, z_, scratch_, nullptr, threads).rz;
    for (int a = 0; a < 3; ++a) p_.axis(a) = z_.axis(a);
  }

  const double b_norm = std::sqrt(bb);
  const double target = tolerance_ * b_norm;
  int it = 0;
  bool converged = std::sqrt(rr) <= target;
  while (!converged && it < max_iterations_) {
    // q = A p and p.q.
    for_each_block_indexed(n_, threads, [&](std::size_t blk, std::size_t b, std::size_t e) {
      matrix_.apply_block(m, h, p_, q_, blk, b, e);
      partials_[kSums * blk] = dot(p_, q_, b, e);
    });
    const double pq = sum_partials()[0];
    if (!(pq > 0.0)) break;  // A is SPD on the free vertices: only p = 0 (r = 0) lands here
    const T alpha = static_cast<T>(rz / pq);
    for_each_block_indexed(n_, threads, [&](std::size_t blk, std::size_t b, std::size_t e) {
      update_residual(alpha, blk, b, e);
    });
    const double rz_old = rz;
    const auto sums = sum_partials();
    rr = sums[0], rz = sums[1];
    ++it;
    converged = std::sqrt(rr) <= target;
    if (converged) break;
    T beta;
    if (use_multigrid_) {  // flexible CG: the K-cycle is not a fixed linear map
      const auto dots = multigrid_->apply(m, matrix_, h, r_, z_, scratch_, &q_, threads);
      rz = dots.rz;
      beta = static_cast<T>(-dots.qz / pq);
    } else {
      beta = static_cast<T>(rz / rz_old);
    }
    for_each_block(n_, threads, [&](std::size_t b, std::size_t e) {
      for (int a = 0; a < 3; ++a) {
        T* __restrict p = p_.axis(a).data();
        const T* __restrict z = z_.axis(a).data();
#pragma omp simd
        for (std::size_t i = b; i < e; ++i) p[i] = z[i] + beta * p[i];
      }
    });
  }
  return {it, b_norm > 0.0 ? std::sqrt(rr) / b_norm : 0.0, converged};
}

template <class T>
inline double ImplicitEuler<T>::correction_ratio(const Model<T>& m, const Vec3Array<T>& vel,
                                                 int threads) {
  for_each_block_indexed(n_, threads, [&](std::size_t blk, std::size_t b, std::size_t e) {
    double delta = 0.0, change = 0.0;
    for (int a = 0; a < 3; ++a)
      for (std::size_t i = b; i < e; ++i) {
        const double d = dv_.axis(a)[i], c = double(vel.axis(a)[i]) - double(v0_.axis(a)[i]);
        delta += double(m.mass[i]) * d * d;
        change += double(m.mass[i]) * c * c;
      }
    partials_[kSums * blk] = delta;
    partials_[kSums * blk + 1] = change;
  });
  const auto sums = sum_partials();
  return sums[1] > 0.0 ? std::sqrt(sums[0] / sums[1]) : 0.0;
}

template <class T>
inline void ImplicitEuler<T>::update(State<T>& s, T h, bool first, int threads) {
  for_each_block(n_, threads, [&](std::size_t b, std::size_t e) {
    for (int a = 0; a < 3; ++a) {
      T* __restrict x = s.pos.axis(a).data();
      T* __restrict v = s.vel.axis(a).data();
      const T* __restrict dv = dv_.axis(a).data();
      if (first) {
#pragma omp simd
        for (std::size_t i = b; i < e; ++i) {
          v[i] += dv[i];
          x[i] += h * v[i];
        }
      } else {
        const T* __restrict x0 = x0_.axis(a).data();
#pragma omp simd
        for (std::size_t i = b; i < e; ++i) {
          v[i] += dv[i];
          x[i] = x0[i] + h * v[i];
        }
      }
    }
  });
}

template <class T>
inline void ImplicitEuler<T>::setup_block(const Model<T>& m, const State<T>& state, T h, bool warm,
                                          bool first, std::size_t blk, std::size_t b,
                                          std::size_t e) {
  T* __restrict bx = r_.x.data();
  T* __restrict by = r_.y.data();
  T* __restrict bz = r_.z.data();
  const Vec3Array<T>& vel = state.vel;
  for (std::size_t i = b; i < e; ++i) {
    bx[i] = h * f0_.x[i], by[i] = h * f0_.y[i], bz[i] = h * f0_.z[i];
    if (!first) {  // Newton on R(v): b = h F - M (v - v0)
      bx[i] -= m.mass[i] * (vel.x[i] - v0_.x[i]);
      by[i] -= m.mass[i] * (vel.y[i] - v0_.y[i]);
      bz[i] -= m.mass[i] * (vel.z[i] - v0_.z[i]);
    }
  }
  matrix_.setup_block(m, state, h, first, r_, blk, b, e);
  double bb = 0.0;
  for (std::size_t i = b; i < e; ++i)
    bb += double(bx[i]) * bx[i] + double(by[i]) * by[i] + double(bz[i]) * bz[i];
  // The warm start reads the neighbours' dv across blocks: no block writes dv in this pass.
  if (warm) {
    matrix_.apply_block(m, h, dv_, q_, blk, b, e);
    for (int a = 0; a < 3; ++a) {
      T* __restrict r = r_.axis(a).data();
      const T* __restrict q = q_.axis(a).data();
#pragma omp simd
      for (std::size_t i = b; i < e; ++i) r[i] -= q[i];
    }
  } else {
    for (int a = 0; a < 3; ++a) std::fill(dv_.axis(a).begin() + b, dv_.axis(a).begin() + e, T(0));
  }
  partials_[kSums * blk] = bb;
  if (!use_multigrid_) {  // the multigrid's cycle sets z and p after this pass
    matrix_.precondition(r_, z_, b, e);
    for (int a = 0; a < 3; ++a)
      std::copy(z_.axis(a).begin() + b, z_.axis(a).begin() + e, p_.axis(a).begin() + b);
    partials_[kSums * blk + 1] = dot(r_, z_, b, e);
  }
  partials_[kSums * blk + 2] = warm ? dot(r_, r_, b, e) : bb;
}

template <class T>
inline void ImplicitEuler<T>::update_residual(T alpha, std::size_t blk, std::size_t b,
                                              std::size_t e) {
  for (int a = 0; a < 3; ++a) {
    T* __restrict dv = dv_.axis(a).data();
    T* __restrict r = r_.axis(a).data();
    const T* __restrict p = p_.axis(a).data();
    const T* __restrict q = q_.axis(a).data();
#pragma omp simd
    for (std::size_t i = b; i < e; ++i) {
      dv[i] += alpha * p[i];
      r[i] -= alpha * q[i];
    }
  }
  partials_[kSums * blk] = dot(r_, r_, b, e);
  if (use_multigrid_) return;  // its cycle follows
  matrix_.precondition(r_, z_, b, e);
  partials_[kSums * blk + 1] = dot(r_, z_, b, e);
}

template <class T>
inline double ImplicitEuler<T>::dot(const Vec3Array<T>& u, const Vec3Array<T>& w, std::size_t b,
                                    std::size_t e) {
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    const T* __restrict pu = u.axis(a).data();
    const T* __restrict pw = w.axis(a).data();
#pragma omp simd reduction(+ : sum)
    for (std::size_t i = b; i < e; ++i) sum += double(pu[i]) * double(pw[i]);
  }
  return sum;
}

template <class T>
inline std::array<double, kSums> ImplicitEuler<T>::sum_partials() const {
  std::array<double, kSums> sums{};
  for (std::size_t k = 0; k < block_count(n_); ++k)
    for (std::size_t c = 0; c < kSums; ++c) sums[c] += partials_[kSums * k + c];
  return sums;
}

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_implicit_euler(const Model<T>& m, const SolverSpec& spec) {
  return std::make_unique<ImplicitEuler<T>>(m, spec);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_implicit_euler)

}  // namespace clothlab
