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
// Matrix-free: each spring's block B_s = h^2 Ks + h c d d^T = alpha I + e e^T (e = sqrt(beta) d,
// beta >= 0; 4 numbers, the same at both ends) is computed once per step, per spring, and the
// product (A u)_a = (m_a + h drag) u_a + sum_s B_s (u_a - u_b) is gathered per vertex (no
// atomics: the same bits for any thread count; the differences u_a - u_b keep it accurate in
// float where the h^2 k terms dwarf the mass). The neighbours are stored per 512-vertex block,
// slot-major: where a block's neighbours sit at a few fixed index offsets b - a (a grid cloth's
// stencil) a slot is one offset and the neighbours are read as a contiguous run ("diagonal"
// storage, no gather instructions); any other topology gets a padded neighbour-index table for
// that block. Measured on the 64x64 sheet at dt = 1/60 (one thread, AVX-512): PCG steps 1.8x
// (double) and 2.6x (float) faster than with a gathering neighbour table for every block, and
// 1.9x / 5x faster than a scalar walk over a CSR adjacency list.
//
// Solve: preconditioned conjugate gradients, block-Jacobi preconditioner (the inverse of each
// vertex's 3x3 diagonal block of A). Pinned vertices (inv_mass 0) are filtered as in
// Baraff-Witkin: their dv, residual and search direction stay exactly 0. PCG starts from the
// previous step's dv (on the falling 32x32 sheet 36 instead of 45 iterations per step at
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
#include <utility>
#include <vector>

#include "sim/core/parallel.hpp"
#include "sim/integrators/integrator.hpp"

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

double pcg_tolerance(const SolverSpec& spec) {
  if (spec.cg_tolerance > 0.0) return spec.cg_tolerance;
  return newton_iterations(spec) > 1 ? kNewtonForcing : kLinearisedTolerance;
}

// How one vertex block stores its neighbours: `slots` slots of (end - begin) entries each from
// entry `entry`; with `diagonal`, slot k holds the neighbours at index offset shift[k].
struct BlockLayout {
  std::size_t entry = 0, slots = 0, shift = 0;  // shift: first of its offsets in shifts_
  bool diagonal = false;
};

template <class T>
class ImplicitEuler final : public Integrator<T> {
 public:
  ImplicitEuler(const Model<T>& m, const SolverSpec& spec)
      : n_(m.n),
        tolerance_(pcg_tolerance(spec)),
        max_iterations_(spec.cg_max_iterations),
        newton_(newton_iterations(spec)),
        newton_tolerance_(spec.newton_tolerance) {
    const SpringList<T> list = spring_list(m);
    const std::size_t ns = list.size();
    end_a_.resize(ns);
    end_b_.resize(ns);
    for (std::size_t s = 0; s < ns; ++s) {
      end_a_[s] = list.ends[s][0];
      end_b_[s] = list.ends[s][1];
    }
    stiffness_ = list.stiffness;
    rest_length_ = list.rest_length;
    damping_ = list.damping;
    // One extra all-zero spring at index ns: what empty slots point at (it adds 0).
    blocks_.assign(ns + 1, {});
    build_layout(ns);

    free_.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) free_[i] = m.inv_mass[i] == T(0) ? T(0) : T(1);
    f0_.resize(n_);
    for (Vec3Array<T>* v : {&dv_, &r_, &z_, &p_, &q_}) v->resize(n_);
    if (newton_ > 1)
      for (Vec3Array<T>* v : {&first_dv_, &x0_, &v0_}) v->resize(n_);
    for (AlignedVector<T>* v : {&alpha_, &ex_, &ey_, &ez_}) v->assign(entry_spring_.size(), T(0));
    precond_.assign(6 * n_, T(0));
    partials_.assign(kSums * block_count(n_), 0.0);
  }

  void step(const System<T>& sys, State<T>& s, double t, T dt) override {
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
      assemble_springs(s, h, sys.threads);
      const SolveStats st = solve(sys.model, s.vel, h, first, sys.threads);
      total.iterations += st.iterations;
      total.residual = std::max(total.residual, st.residual);
      total.converged = total.converged && st.converged;
      update(s, h, first, sys.threads);
      if (!first && correction_ratio(sys.model, s.vel, sys.threads) <= newton_tolerance_) break;
    }
    if (newton_ > 1) std::swap(dv_, first_dv_);
    stats_ = total;
    warm_ = true;
  }

  // The previous dv no longer predicts the next one.
  void invalidate() override { warm_ = false; }
  // After a collision response the previous dv is still a good first guess.
  void state_corrected() override {}

  SolveStats last_stats() const override { return stats_; }

 private:
  // One linear solve (M - h D - h^2 K) dv = b by PCG, warm-started from the last step's first
  // dv on the first Newton iteration, from 0 on later ones.
  SolveStats solve(const Model<T>& m, const Vec3Array<T>& vel, T h, bool first, int threads) {
    // Slot blocks, preconditioner, right side and initial residual, per vertex block.
    const bool warm = first && warm_;
    for_each_block_indexed(n_, threads, [&](std::size_t blk, std::size_t b, std::size_t e) {
      setup_block(m, vel, h, warm, first, blk, b, e);
    });
    const auto [bb, rz_start, rr_start] = sum_partials();
    double rz = rz_start, rr = rr_start;

    const double b_norm = std::sqrt(bb);
    const double target = tolerance_ * b_norm;
    int it = 0;
    bool converged = std::sqrt(rr) <= target;
    while (!converged && it < max_iterations_) {
      // q = A p and p.q.
      for_each_block_indexed(n_, threads, [&](std::size_t blk, std::size_t b, std::size_t e) {
        apply_block(m, h, p_, q_, blk, b, e);
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
      const T beta = static_cast<T>(rz / rz_old);
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

  // |delta|_M / |v - v0|_M after a Newton iteration (delta in dv_): how much the last
  // correction changed the step's change of velocity, in the mass-weighted norm.
  double correction_ratio(const Model<T>& m, const Vec3Array<T>& vel, int threads) {
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

  // v += dv; then x += h v on the first iteration (x was x0), x = x0 + h v on later ones.
  void update(State<T>& s, T h, bool first, int threads) {
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

  // Per vertex block, the slots of its neighbours (in index order). Diagonal storage when the
  // block's distinct offsets are at most twice its largest neighbour count (a grid stencil: as
  // many offsets as neighbours; a block straddling two grids of different widths: twice); else a
  // padded neighbour-index table. Empty entries point at the zero spring ns and, in the table,
  // at the vertex itself.
  void build_layout(std::size_t ns) {
    std::vector<std::vector<std::pair<std::int32_t, std::int32_t>>> rows(n_);
    for (std::size_t s = 0; s < ns; ++s) {
      const auto sp = static_cast<std::int32_t>(s);
      rows[static_cast<std::size_t>(end_a_[s])].emplace_back(end_b_[s], sp);
      rows[static_cast<std::size_t>(end_b_[s])].emplace_back(end_a_[s], sp);
    }
    for (auto& row : rows) std::sort(row.begin(), row.end());
    layout_.resize(block_count(n_));
    std::vector<std::ptrdiff_t> offsets;
    for (std::size_t blk = 0; blk < layout_.size(); ++blk) {
      const std::size_t b = blk * kBlockSize, e = std::min(n_, b + kBlockSize), len = e - b;
      std::size_t widest = 0;
      offsets.clear();
      for (std::size_t i = b; i < e; ++i) {
        widest = std::max(widest, rows[i].size());
        for (const auto& [o, sp] : rows[i])
          offsets.push_back(static_cast<std::ptrdiff_t>(o) - static_cast<std::ptrdiff_t>(i));
      }
      std::sort(offsets.begin(), offsets.end());
      offsets.erase(std::unique(offsets.begin(), offsets.end()), offsets.end());
      BlockLayout& l = layout_[blk];
      l.entry = entry_spring_.size();
      l.diagonal = offsets.size() <= 2 * widest;
      l.slots = l.diagonal ? offsets.size() : widest;
      l.shift = shifts_.size();
      if (l.diagonal) shifts_.insert(shifts_.end(), offsets.begin(), offsets.end());
      entry_spring_.resize(l.entry + l.slots * len, static_cast<std::int32_t>(ns));
      entry_other_.resize(l.entry + l.slots * len);
      for (std::size_t k = 0; k < l.slots; ++k)
        for (std::size_t i = b; i < e; ++i)
          entry_other_[l.entry + k * len + (i - b)] = static_cast<std::int32_t>(i);
      for (std::size_t i = b; i < e; ++i) {
        for (std::size_t q = 0; q < rows[i].size(); ++q) {
          const auto [o, sp] = rows[i][q];
          std::size_t k = q;
          if (l.diagonal) {
            const std::ptrdiff_t off =
                static_cast<std::ptrdiff_t>(o) - static_cast<std::ptrdiff_t>(i);
            k = static_cast<std::size_t>(std::lower_bound(offsets.begin(), offsets.end(), off) -
                                         offsets.begin());
          }
          entry_spring_[l.entry + k * len + (i - b)] = sp;
          entry_other_[l.entry + k * len + (i - b)] = o;
        }
      }
    }
  }

  // Per spring: B_s, and Ks (v_a - v_b), the spring's share of the right side's h^2 K v0 term.
  void assemble_springs(const State<T>& s, T h, int threads) {
    const T h2 = h * h;
    for_each_block(end_a_.size(), threads, [&](std::size_t b, std::size_t e) {
      const T *px = s.pos.x.data(), *py = s.pos.y.data(), *pz = s.pos.z.data();
      const T *vx = s.vel.x.data(), *vy = s.vel.y.data(), *vz = s.vel.z.data();
      for (std::size_t k = b; k < e; ++k) {
        const auto i = static_cast<std::size_t>(end_a_[k]), j = static_cast<std::size_t>(end_b_[k]);
        T dx = px[j] - px[i], dy = py[j] - py[i], dz = pz[j] - pz[i];
        const T len = std::sqrt(dx * dx + dy * dy + dz * dz);
        const T inv_len = len > T(0) ? T(1) / len : T(0);
        dx *= inv_len, dy *= inv_len, dz *= inv_len;
        const T rest = rest_length_[k], ks = stiffness_[k];
        // Transverse weight max(0, 1 - L/l); a zero-length spring at zero length is k I.
        const T tw = len > rest ? T(1) - rest * inv_len : (rest > T(0) ? T(0) : T(1));
        const T root = std::sqrt(h2 * ks * (T(1) - tw) + h * damping_[k]);
        const T ux = vx[i] - vx[j], uy = vy[i] - vy[j], uz = vz[i] - vz[j];
        const T along = (T(1) - tw) * (dx * ux + dy * uy + dz * uz);
        blocks_[k] = {h2 * ks * tw,
                      root * dx,
                      root * dy,
                      root * dz,
                      {ks * (tw * ux + along * dx), ks * (tw * uy + along * dy),
                       ks * (tw * uz + along * dz)}};
      }
    });
  }

  // For vertices [b, e): copies their springs' blocks into the slots, forms the diagonal blocks
  // and their inverses, the right side b (first: h (f0 + h K v0); later: h F - M (v - v0)),
  // r = b - A dv (warm) or r = b, dv = 0 (cold), z = P r and p = z. Partial sums: |b|^2, r.z
  // and r.r.
  void setup_block(const Model<T>& m, const Vec3Array<T>& vel, T h, bool warm, bool first,
                   std::size_t blk, std::size_t b, std::size_t e) {
    const T h2 = h * h;
    T* __restrict bx = r_.x.data();
    T* __restrict by = r_.y.data();
    T* __restrict bz = r_.z.data();
    T* __restrict pc = precond_.data();  // the diagonal block first, inverted in place below
    const std::size_t n = n_;
    for (std::size_t i = b; i < e; ++i) {
      const T diag = m.mass[i] + h * m.drag;
      bx[i] = h * f0_.x[i], by[i] = h * f0_.y[i], bz[i] = h * f0_.z[i];
      if (!first) {  // Newton on R(v): b = h F - M (v - v0)
        bx[i] -= m.mass[i] * (vel.x[i] - v0_.x[i]);
        by[i] -= m.mass[i] * (vel.y[i] - v0_.y[i]);
        bz[i] -= m.mass[i] * (vel.z[i] - v0_.z[i]);
      }
      pc[i] = diag, pc[n + i] = 0, pc[2 * n + i] = 0;
      pc[3 * n + i] = diag, pc[4 * n + i] = 0, pc[5 * n + i] = diag;
    }
    const BlockLayout& l = layout_[blk];
    const std::size_t len = e - b;
    for (std::size_t k = 0; k < l.slots; ++k) {
      for (std::size_t i = b; i < e; ++i) {
        const std::size_t at = l.entry + k * len + (i - b);
        const SpringBlock& bs = blocks_[static_cast<std::size_t>(entry_spring_[at])];
        alpha_[at] = bs.alpha, ex_[at] = bs.ex, ey_[at] = bs.ey, ez_[at] = bs.ez;
        pc[i] += bs.alpha + bs.ex * bs.ex;
        pc[n + i] += bs.ex * bs.ey;
        pc[2 * n + i] += bs.ex * bs.ez;
        pc[3 * n + i] += bs.alpha + bs.ey * bs.ey;
        pc[4 * n + i] += bs.ey * bs.ez;
        pc[5 * n + i] += bs.alpha + bs.ez * bs.ez;
        // bs.rhs is Ks (v_a - v_b) for the spring's ends a < b; at the b end the sign flips.
        const T w = !first ? T(0) : static_cast<std::size_t>(entry_other_[at]) > i ? -h2 : h2;
        bx[i] += w * bs.rhs[0], by[i] += w * bs.rhs[1], bz[i] += w * bs.rhs[2];
      }
    }
    // Inverse of the symmetric positive definite diagonal block (adjugate over determinant, in
    // double: in float the h^2 k terms can dwarf the mass); zero on pinned vertices, whose
    // right side is zeroed too, so their z, p and dv stay 0.
    double bb = 0.0;
    for (std::size_t i = b; i < e; ++i) {
      const double xx = pc[i], xy = pc[n + i], xz = pc[2 * n + i];
      const double yy = pc[3 * n + i], yz = pc[4 * n + i], zz = pc[5 * n + i];
      const double cxx = yy * zz - yz * yz, cxy = xz * yz - xy * zz, cxz = xy * yz - xz * yy;
      const double cyy = xx * zz - xz * xz, cyz = xy * xz - xx * yz, czz = xx * yy - xy * xy;
      const double det = xx * cxx + xy * cxy + xz * cxz;
      const double scale = free_[i] != T(0) ? 1.0 / det : 0.0;
      pc[i] = static_cast<T>(cxx * scale), pc[n + i] = static_cast<T>(cxy * scale);
      pc[2 * n + i] = static_cast<T>(cxz * scale), pc[3 * n + i] = static_cast<T>(cyy * scale);
      pc[4 * n + i] = static_cast<T>(cyz * scale), pc[5 * n + i] = static_cast<T>(czz * scale);
      bx[i] *= free_[i], by[i] *= free_[i], bz[i] *= free_[i];
      bb += double(bx[i]) * bx[i] + double(by[i]) * by[i] + double(bz[i]) * bz[i];
    }
    // The warm start reads the neighbours' dv across blocks: no block writes dv in this pass.
    if (warm) {
      apply_block(m, h, dv_, q_, blk, b, e);
      for (int a = 0; a < 3; ++a) {
        T* __restrict r = r_.axis(a).data();
        const T* __restrict q = q_.axis(a).data();
#pragma omp simd
        for (std::size_t i = b; i < e; ++i) r[i] -= q[i];
      }
    } else {
      for (int a = 0; a < 3; ++a) std::fill(dv_.axis(a).begin() + b, dv_.axis(a).begin() + e, T(0));
    }
    precondition(b, e);
    for (int a = 0; a < 3; ++a)
      std::copy(z_.axis(a).begin() + b, z_.axis(a).begin() + e, p_.axis(a).begin() + b);
    partials_[kSums * blk] = bb;
    partials_[kSums * blk + 1] = dot(r_, z_, b, e);
    partials_[kSums * blk + 2] = warm ? dot(r_, r_, b, e) : bb;
  }

  // out = A u on vertices [b, e) of block blk, 0 on pinned ones (which keeps their residual 0).
  void apply_block(const Model<T>& m, T h, const Vec3Array<T>& u, Vec3Array<T>& out,
                   std::size_t blk, std::size_t b, std::size_t e) const {
    const T* __restrict ux = u.x.data();
    const T* __restrict uy = u.y.data();
    const T* __restrict uz = u.z.data();
    T* __restrict ox = out.x.data();
    T* __restrict oy = out.y.data();
    T* __restrict oz = out.z.data();
    const T* __restrict mass = m.mass.data();
    const T drag = h * m.drag;
#pragma omp simd
    for (std::size_t i = b; i < e; ++i) {
      const T diag = mass[i] + drag;
      ox[i] = diag * ux[i], oy[i] = diag * uy[i], oz[i] = diag * uz[i];
    }
    const BlockLayout& l = layout_[blk];
    const std::size_t len = e - b;
    const auto n = static_cast<std::ptrdiff_t>(n_);
    for (std::size_t k = 0; k < l.slots; ++k) {
      const std::size_t row = l.entry + k * len;  // entry of vertex i: row + (i - b)
      if (l.diagonal) {
        // Neighbour i + shift for i in [lo, hi), the vertices whose neighbour index is in the
        // arrays; outside that range the slot is empty. Empty slots inside it read a real vertex
        // and multiply by the zero block.
        const std::ptrdiff_t shift = shifts_[l.shift + k];
        const auto lo =
            static_cast<std::size_t>(std::max<std::ptrdiff_t>(std::ptrdiff_t(b), -shift));
        const auto hi =
            static_cast<std::size_t>(std::min<std::ptrdiff_t>(std::ptrdiff_t(e), n - shift));
        if (lo >= hi) continue;
        const std::size_t first = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(lo) + shift);
        const T* __restrict vx = ux + first;
        const T* __restrict vy = uy + first;
        const T* __restrict vz = uz + first;
        const T* __restrict al = alpha_.data() + row + (lo - b);
        const T* __restrict ex = ex_.data() + row + (lo - b);
        const T* __restrict ey = ey_.data() + row + (lo - b);
        const T* __restrict ez = ez_.data() + row + (lo - b);
        T* __restrict px = ox + lo;
        T* __restrict py = oy + lo;
        T* __restrict pz = oz + lo;
        const T* __restrict wx = ux + lo;
        const T* __restrict wy = uy + lo;
        const T* __restrict wz = uz + lo;
#pragma omp simd
        for (std::size_t j = 0; j < hi - lo; ++j) {
          const T dx = wx[j] - vx[j], dy = wy[j] - vy[j], dz = wz[j] - vz[j];
          const T proj = ex[j] * dx + ey[j] * dy + ez[j] * dz;
          px[j] += al[j] * dx + proj * ex[j];
          py[j] += al[j] * dy + proj * ey[j];
          pz[j] += al[j] * dz + proj * ez[j];
        }
      } else {
        const std::int32_t* __restrict nb = entry_other_.data() + row;
        const T* __restrict al = alpha_.data() + row;
        const T* __restrict ex = ex_.data() + row;
        const T* __restrict ey = ey_.data() + row;
        const T* __restrict ez = ez_.data() + row;
#pragma omp simd
        for (std::size_t i = b; i < e; ++i) {
          const std::size_t j = i - b;
          const auto o = static_cast<std::size_t>(nb[j]);
          const T dx = ux[i] - ux[o], dy = uy[i] - uy[o], dz = uz[i] - uz[o];
          const T proj = ex[j] * dx + ey[j] * dy + ez[j] * dz;
          ox[i] += al[j] * dx + proj * ex[j];
          oy[i] += al[j] * dy + proj * ey[j];
          oz[i] += al[j] * dz + proj * ez[j];
        }
      }
    }
    const T* __restrict keep = free_.data();
#pragma omp simd
    for (std::size_t i = b; i < e; ++i) ox[i] *= keep[i], oy[i] *= keep[i], oz[i] *= keep[i];
  }

  // z = P r on [b, e).
  void precondition(std::size_t b, std::size_t e) {
    const T* __restrict pc = precond_.data();
    const std::size_t n = n_;
    const T *rx = r_.x.data(), *ry = r_.y.data(), *rz = r_.z.data();
    T *zx = z_.x.data(), *zy = z_.y.data(), *zz = z_.z.data();
#pragma omp simd
    for (std::size_t i = b; i < e; ++i) {
      const T x = rx[i], y = ry[i], z = rz[i];
      zx[i] = pc[i] * x + pc[n + i] * y + pc[2 * n + i] * z;
      zy[i] = pc[n + i] * x + pc[3 * n + i] * y + pc[4 * n + i] * z;
      zz[i] = pc[2 * n + i] * x + pc[4 * n + i] * y + pc[5 * n + i] * z;
    }
  }

  // dv += alpha p, r -= alpha q, z = P r on [b, e); partial sums r.r and r.z.
  void update_residual(T alpha, std::size_t blk, std::size_t b, std::size_t e) {
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
    precondition(b, e);
    partials_[kSums * blk] = dot(r_, r_, b, e);
    partials_[kSums * blk + 1] = dot(r_, z_, b, e);
  }

  // u.w over [b, e), in double.
  static double dot(const Vec3Array<T>& u, const Vec3Array<T>& w, std::size_t b, std::size_t e) {
    double sum = 0.0;
    for (int a = 0; a < 3; ++a) {
      const T* __restrict pu = u.axis(a).data();
      const T* __restrict pw = w.axis(a).data();
#pragma omp simd reduction(+ : sum)
      for (std::size_t i = b; i < e; ++i) sum += double(pu[i]) * double(pw[i]);
    }
    return sum;
  }

  // The per-block partial sums, added in block order (the same for any thread count).
  std::array<double, kSums> sum_partials() const {
    std::array<double, kSums> sums{};
    for (std::size_t k = 0; k < block_count(n_); ++k)
      for (std::size_t c = 0; c < kSums; ++c) sums[c] += partials_[kSums * k + c];
    return sums;
  }

  // B_s = alpha I + e e^T, one spring's block of A - M - h drag I, and rhs = Ks (v_a - v_b).
  struct SpringBlock {
    T alpha = 0, ex = 0, ey = 0, ez = 0;
    std::array<T, 3> rhs{};
  };

  std::size_t n_;
  double tolerance_;
  int max_iterations_;
  int newton_;               // Newton iterations per step, at most
  double newton_tolerance_;  // stop once |delta|_M <= this |v - v0|_M

  // Springs in spring_list order, and per step their blocks (plus the zero spring).
  std::vector<std::int32_t> end_a_, end_b_;
  AlignedVector<T> stiffness_, rest_length_, damping_;
  std::vector<SpringBlock> blocks_;

  // Neighbour slots per vertex block (see build_layout) and, per step, the blocks they hold.
  std::vector<BlockLayout> layout_;
  std::vector<std::ptrdiff_t> shifts_;
  std::vector<std::int32_t> entry_spring_, entry_other_;
  AlignedVector<T> alpha_, ex_, ey_, ez_;

  AlignedVector<T> free_;  // 1 for a free vertex, 0 for a pinned one
  Vec3Array<T> f0_;
  Vec3Array<T> dv_, r_, z_, p_, q_;
  Vec3Array<T> first_dv_, x0_, v0_;  // newton_ > 1: the first dv (warm start), x0 and v0
  AlignedVector<T> precond_;         // xx, xy, xz, yy, yz, zz of the inverse blocks, n each
  std::vector<double> partials_;     // kSums per vertex block
  bool warm_ = false;
  SolveStats stats_;
};

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_implicit_euler(const Model<T>& m, const SolverSpec& spec) {
  return std::make_unique<ImplicitEuler<T>>(m, spec);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_implicit_euler)

}  // namespace clothlab
