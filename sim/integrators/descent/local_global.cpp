// Local/global backward Euler for mass-spring systems: Liu, Bargteil, O'Brien & Kavan 2013,
// "Fast Simulation of Mass-Spring Systems", ACM TOG 32(6), article 214.
//
// Backward Euler is the minimisation of
//   g(x) = 1/2 (x - y)^T M (x - y) + h^2 E(x),  y = x_n + h v_n + h^2 M^-1 f_ext,
// and each spring's Hooke energy is a minimum over an auxiliary vector d of fixed length:
//   1/2 k (|x_a - x_b| - L)^2 = min over |d| = L of 1/2 k |x_a - x_b - d|^2.
// The material is the scene's, spring for spring (spring_list()): k, L and c exactly as given.
// Local step (per spring, parallel): d = L (x_a - x_b) / |x_a - x_b|. Global step: a linear
// solve with the constant matrix
//   A = M + h drag I + sum_s (h^2 k_s + h c_s) A_s A_s^T
// (A_s A_s^T: the spring's graph-Laplacian block, the same scalar matrix for x, y and z) over
// the free vertices; a pinned end's column moves to the right-hand side. A is factored once
// (sparse LDL^T, AMD ordering) in double whatever T is: a float factor of the 64 x 64 matrix at
// 60 Hz measured a relative residual of 2e-6 (double: 3e-15) and was no faster. Each iteration
// is two triangular solves, done here by hand on the three coordinates at once: one pass over L
// instead of three, and no allocation (Eigen's solve allocates for its in-place permutation;
// here the unknowns are stored in the factor's order, so no permutation is needed).
// SolverSpec::iterations (0 -> 10) local/global pairs per step, started from y: measured on the
// 32 x 32 falling sheet at 60 Hz, 10 iterations from y leave the first step 5e-5 m RMS from
// the converged one, from x_n + h v_n 8e-4 m; later steps are within 2 % of each other. Then
// v_{n+1} = (x - x_n) / h. Convergence is slow when h^2 k / m is large (about 1400 there): ten
// plain iterations leave a step about 2e-3 m RMS from converged and the motion lags, which looks
// like heavy damping. So the iterations are Chebyshev-accelerated (Wang 2015, chebyshev.hpp;
// Wang's own application of it), with rho = solver.chebyshev_rho or kChebyshevRho after
// kChebyshevDelay plain iterations.
//
// What is implicit and what is explicit:
//  - spring stiffness: implicit (backward Euler once the iterations converge).
//  - along-spring damping -c ((v_a - v_b) . n) n: implicit too, in the same local/global form
//    (as Projective Dynamics treats any quadratic term): with u = (x_a - x_b) - (x_a - x_b)_n,
//    the step's dissipation (c / 2h) (n . u)^2 = min over p perpendicular to n of
//    (c / 2h) |u - p|^2, so the matrix gets the isotropic h c A_s A_s^T and the local step the
//    projection p = u - n (n . u); n is the spring's direction at x_n, frozen for the step. The
//    fixed point is backward Euler with the damping at v_{n+1}. An explicit damping force
//    from v_n (keeping A free of c) was tried first and blew up the 32 x 32 falling sheet
//    (c = 0.05 N*s/m) at 60 Hz within 0.3 s, while it ran stably with c = 0.01 or at
//    dt = 4 ms: explicit damping beside implicit stiffness needs h gamma < 2 + h^2 omega^2 / 2
//    mode by mode, which the linearised rest state meets but a deformed (compressed) lattice
//    evidently does not.
//  - linear drag -drag v: implicit through the diagonal M + h drag I. compute_external_forces()
//    includes -drag v_n in f, and (M + h drag I) x^ + h^2 f = M x^ + h drag x_n + h^2 (f +
//    drag v_n), x^ = x_n + h v_n: exactly backward Euler with the drag at v_{n+1}.
//  - gravity and wind: explicit, at the start of the step.
// Momentum: each spring adds +e at one end and -e at the other and the Laplacian's rows sum to
// zero, so without pins and external forces sum(M x) = sum(M x^) after every iteration:
// momentum is conserved to the round-off of the solve, whatever the iteration count.
// If h changes between calls the matrix is refactored then (this allocates); the solver passes a
// constant dt / substeps, factored in the constructor.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sim/core/parallel.hpp"
#include "sim/integrators/descent/chebyshev.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {
namespace {

constexpr int kDefaultIterations = 10;
// Measured on the 32 x 32 accuracy sheet at 1/60 s, RMS at 0.5 s from RK4 with 10 / 30
// iterations at k0 = 1e3: rho 0 (plain) 635 / 406 mm, 0.95 434 / 173, 0.97 382 / 139, 0.98
// 344 / 116, 0.99 294 / 85, 0.999 208 / 56. But at 0.99 the same sheet with 10 iterations gains
// energy (2.2 J above its start within 2 s, where 0.98 and below only lose it): the
// extrapolation overshoots while the iterate is far from converged. 0.97 keeps a margin. At
// k0 = 1e5 no rho helps the error (802 mm plain, 780-805 accelerated): there the iteration's
// slowest modes are the sheet's bending, which the constant matrix treats as stretching (its
// h^2 k L acts in every direction), so its spectral radius is within 1e-4 of 1 (docs/solver.md);
// there ten plain iterations also gain energy (1.3 J at the peak), 0.97 less (0.3 J). A restart
// when the update grows (Wang's safeguard, on the update instead of the energy) was tried: it
// cost accuracy (486 mm at 10 iterations with 0.99) and kept the gain at 1e5.
// The first iterations are left plain: the ratio of successive updates rises from 0.4 to 0.9
// over the first ten, so the early ones are not yet in the asymptotic regime rho describes.
constexpr double kChebyshevRho = 0.97;
constexpr int kChebyshevDelay = 3;

template <class T>
class LocalGlobal final : public Integrator<T> {
 public:
  LocalGlobal(const Model<T>& m, const SolverSpec& spec);

  void step(const System<T>& sys, State<T>& s, double t, T dt) override;

  SolveStats last_stats() const override { return {iterations_, 0.0, true}; }

 private:
  struct Link {
    std::int32_t spring;
    double sign;  // +1: the slot is the spring's end a; -1: end b
  };

  std::size_t spring_count() const { return rest_.size(); }

  // Keeps the springs that touch a free vertex; numbers the free vertices (natural order, for
  // the matrix; assign_slots() then reorders them).
  void build_springs(const Model<T>& m);

  // sum k A A^T and sum c A A^T over the free vertices (natural order); explicit zero diagonal
  // entries keep every diagonal in the pattern for M + h drag I.
  void build_laplacians();

  // Factors M + h drag I + h^2 K + h C. The first call also fixes the ordering and the slots.
  void factor(T dt);

  // Slots: the free vertices first, slot P(f) for natural free index f with Eigen's permutation
  // (P A P^T = L D L^T), so slot k is row k of the factor and the solve needs no permutation;
  // then the pinned vertices.
  void assign_slots();

  // Per free slot, its springs in spring order with the sign of J (+1 at end a, -1 at end b):
  // each slot gathers its own sum, so no two threads write one value and the order is fixed.
  void build_adjacency();

  // Per spring: n = (x_a - x_b) / |x_a - x_b| at x_n and n . (x_a - x_b)_n = |x_a - x_b|_n, the
  // damping term's frozen direction (n = 0 for a zero-length spring: no damping this step).
  void spring_directions(const State<T>& s, int threads);

  // base = (M + h drag) x^ + h^2 f + (h^2 k + h c) x_pin: the part of the right-hand side fixed
  // during the step. Then the start iterate y = x^ + h^2 f / (m + h drag): the step without
  // springs.
  void right_hand_side(double h, int threads);

  // Per spring, its column of the right-hand side, e = h^2 k d + h c (x_ab - p_perp) with
  // x_ab = x_a - x_b at the iterate, d = L x_ab / |x_ab| (a zero-length spring has no direction
  // and pushes nothing this iteration) and x_ab - p_perp = x_ab - n (n . x_ab - |x_ab|_n).
  template <bool Damped>
  void local_step(double h, int threads);

  // Chebyshev on the free slots: q = omega (q - x^(k-1)) + x^(k-1), x^(k-1) in older_.
  void accelerate(double omega, int threads);

  // q (free slots) = base + J e: the global step's right-hand side, in place of the iterate.
  void gather(int threads);

  // q <- (L D L^T)^-1 q on the free slots, three coordinates at once. L is unit lower
  // triangular, column-compressed, strictly-lower entries only (SimplicialLDLT's storage).
  // Sequential: each column depends on the previous ones.
  void solve_in_place();

  int iterations_;
  Chebyshev chebyshev_;
  T h_ = T(0);  // the step the matrix is factored for
  double drag_ = 0.0;
  std::size_t free_ = 0;  // free vertices = slots [0, free_)

  // Springs that touch a free vertex.
  std::vector<std::array<int, 2>> end_vertex_, end_slot_;
  std::vector<double> stiffness_, rest_, damping_, spring_weight_;
  std::vector<double> direction_;  // 4 per spring: n at x_n and |x_a - x_b| at x_n
  // vertex -> slot (after assign_slots; before it: natural free index or -1), slot -> vertex,
  // free slot -> natural free index.
  std::vector<int> vertex_slot_, slot_vertex_, free_index_;
  std::vector<std::size_t> adjacency_start_;
  std::vector<Link> adjacency_;

  std::vector<double> mass_;       // per free vertex, natural order
  std::vector<double> slot_mass_;  // per free slot: m + h drag
  std::vector<double> inv_diagonal_;
  Eigen::SparseMatrix<double> stiffness_laplacian_, damping_laplacian_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;

  std::vector<double> q_;     // 3 per slot: the iterate (free slots), the pins' positions
  std::vector<double> base_;  // 3 per free slot
  std::vector<double> e_;     // 3 per spring
  // 3 per free slot: the current iteration's start x^(k) and the previous one's x^(k-1).
  std::vector<double> current_, older_;
  Vec3Array<T> f_;
};

template <class T>
inline LocalGlobal<T>::LocalGlobal(const Model<T>& m, const SolverSpec& spec)
    : iterations_(spec.iterations > 0 ? spec.iterations : kDefaultIterations),
      chebyshev_(chebyshev_of(spec.chebyshev_rho, kChebyshevRho, kChebyshevDelay)) {
  build_springs(m);
  build_laplacians();
  factor(static_cast<T>(spec.dt / spec.substeps));
  build_adjacency();
  q_.assign(3 * slot_vertex_.size(), 0.0);
  base_.assign(3 * free_, 0.0);
  e_.assign(3 * spring_count(), 0.0);
  current_.assign(3 * free_, 0.0);
  older_.assign(3 * free_, 0.0);
  direction_.assign(4 * spring_count(), 0.0);
  f_.resize(m.n);
}

template <class T>
inline void LocalGlobal<T>::step(const System<T>& sys, State<T>& s, double t, T dt) {
  if (free_ == 0) return;
  if (dt != h_) factor(dt);  // allocates; never in a constant-step run
  const Model<T>& m = sys.model;
  const double h = dt;
  compute_external_forces(m, t, s.pos, s.vel, f_, sys.workspace, sys.threads);
  // x^ = x_n + h v_n in every slot (pinned slots keep x_n: pins never move).
  for_each_block(slot_vertex_.size(), sys.threads, [&](std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k) {
      const auto i = static_cast<std::size_t>(slot_vertex_[k]);
      const double hk = k < free_ ? h : 0.0;
      q_[3 * k] = double(s.pos.x[i]) + hk * double(s.vel.x[i]);
      q_[3 * k + 1] = double(s.pos.y[i]) + hk * double(s.vel.y[i]);
      q_[3 * k + 2] = double(s.pos.z[i]) + hk * double(s.vel.z[i]);
    }
  });
  const bool damped = m.has_damping;
  if (damped) spring_directions(s, sys.threads);
  right_hand_side(h, sys.threads);
  double omega = 1.0;
  for (int it = 0; it < iterations_; ++it) {
    if (damped) {
      local_step<true>(h, sys.threads);
    } else {
      local_step<false>(h, sys.threads);
    }
    std::copy(q_.begin(), q_.begin() + std::ptrdiff_t(3 * free_), current_.begin());
    gather(sys.threads);
    solve_in_place();
    omega = chebyshev_weight(chebyshev_, it, omega);
    if (it >= chebyshev_.delay) accelerate(omega, sys.threads);
    std::swap(older_, current_);  // older_ = this iteration's start, x^(k)
  }
  // v = (x - x_n) / h, x = x_{n+1} for the free vertices.
  const double inv_h = 1.0 / h;
  for_each_block(free_, sys.threads, [&](std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k) {
      const auto i = static_cast<std::size_t>(slot_vertex_[k]);
      for (int a = 0; a < 3; ++a) {
        T& x = s.pos.axis(a)[i];
        s.vel.axis(a)[i] = static_cast<T>((q_[3 * k + a] - double(x)) * inv_h);
        x = static_cast<T>(q_[3 * k + a]);
      }
    }
  });
}

template <class T>
inline void LocalGlobal<T>::build_springs(const Model<T>& m) {
  const SpringList<T> list = spring_list(m);
  vertex_slot_.assign(m.n, -1);
  for (std::size_t i = 0; i < m.n; ++i)
    if (m.inv_mass[i] != T(0)) vertex_slot_[i] = static_cast<int>(free_++);
  for (std::size_t s = 0; s < list.size(); ++s) {
    const auto [a, b] = list.ends[s];
    if (vertex_slot_[a] < 0 && vertex_slot_[b] < 0) continue;
    end_vertex_.push_back({a, b});
    stiffness_.push_back(double(list.stiffness[s]));
    rest_.push_back(double(list.rest_length[s]));
    damping_.push_back(double(list.damping[s]));
  }
  mass_.resize(free_);
  for (std::size_t i = 0; i < m.n; ++i)
    if (vertex_slot_[i] >= 0) mass_[static_cast<std::size_t>(vertex_slot_[i])] = double(m.mass[i]);
  drag_ = double(m.drag);
}

template <class T>
inline void LocalGlobal<T>::build_laplacians() {
  std::vector<Eigen::Triplet<double>> k_entries, c_entries;
  auto add = [&](std::vector<Eigen::Triplet<double>>& out, int a, int b, double w) {
    if (a >= 0) out.emplace_back(a, a, w);
    if (b >= 0) out.emplace_back(b, b, w);
    if (a >= 0 && b >= 0) {
      out.emplace_back(a, b, -w);
      out.emplace_back(b, a, -w);
    }
  };
  for (std::size_t s = 0; s < spring_count(); ++s) {
    const int a = vertex_slot_[end_vertex_[s][0]], b = vertex_slot_[end_vertex_[s][1]];
    add(k_entries, a, b, stiffness_[s]);
    add(c_entries, a, b, damping_[s]);
  }
  for (std::size_t k = 0; k < free_; ++k) k_entries.emplace_back(int(k), int(k), 0.0);
  const auto n = Eigen::Index(free_);
  stiffness_laplacian_.resize(n, n);
  stiffness_laplacian_.setFromTriplets(k_entries.begin(), k_entries.end());
  damping_laplacian_.resize(n, n);
  damping_laplacian_.setFromTriplets(c_entries.begin(), c_entries.end());
}

template <class T>
inline void LocalGlobal<T>::factor(T dt) {
  h_ = dt;
  if (free_ == 0) return;
  const double h = dt;
  Eigen::SparseMatrix<double> a = (h * h) * stiffness_laplacian_ + h * damping_laplacian_;
  for (std::size_t k = 0; k < free_; ++k)
    a.coeffRef(Eigen::Index(k), Eigen::Index(k)) += mass_[k] + h * drag_;
  if (slot_vertex_.empty()) {
    ldlt_.analyzePattern(a);
    assign_slots();
  }
  ldlt_.factorize(a);
  inv_diagonal_.resize(free_);
  for (std::size_t k = 0; k < free_; ++k) inv_diagonal_[k] = 1.0 / ldlt_.vectorD()[Eigen::Index(k)];
  slot_mass_.resize(free_);  // m + h drag, per slot
  for (std::size_t k = 0; k < free_; ++k)
    slot_mass_[k] = mass_[static_cast<std::size_t>(free_index_[k])] + h * drag_;
  spring_weight_.resize(spring_count());  // h^2 k + h c: the pinned end's matrix column
  for (std::size_t s = 0; s < spring_count(); ++s)
    spring_weight_[s] = h * h * stiffness_[s] + h * damping_[s];
}

template <class T>
inline void LocalGlobal<T>::assign_slots() {
  const auto& p = ldlt_.permutationP().indices();
  slot_vertex_.assign(vertex_slot_.size(), 0);
  free_index_.assign(free_, 0);
  std::size_t pinned = free_;
  for (std::size_t i = 0; i < vertex_slot_.size(); ++i) {
    const int f = vertex_slot_[i];
    if (f < 0) {
      slot_vertex_[pinned++] = static_cast<int>(i);
      continue;
    }
    const auto slot = static_cast<std::size_t>(p.size() ? p[f] : f);
    slot_vertex_[slot] = static_cast<int>(i);
    free_index_[slot] = f;
  }
  for (std::size_t k = 0; k < slot_vertex_.size(); ++k)
    vertex_slot_[static_cast<std::size_t>(slot_vertex_[k])] = static_cast<int>(k);
  end_slot_.resize(spring_count());
  for (std::size_t s = 0; s < spring_count(); ++s)
    end_slot_[s] = {vertex_slot_[end_vertex_[s][0]], vertex_slot_[end_vertex_[s][1]]};
}

template <class T>
inline void LocalGlobal<T>::build_adjacency() {
  adjacency_start_.assign(free_ + 1, 0);
  for (const auto& ends : end_slot_)
    for (int k : ends)
      if (static_cast<std::size_t>(k) < free_) ++adjacency_start_[static_cast<std::size_t>(k) + 1];
  for (std::size_t k = 0; k < free_; ++k) adjacency_start_[k + 1] += adjacency_start_[k];
  adjacency_.resize(adjacency_start_.back());
  std::vector<std::size_t> next(adjacency_start_.begin(), adjacency_start_.end() - 1);
  for (std::size_t s = 0; s < spring_count(); ++s) {
    for (int end = 0; end < 2; ++end) {
      const auto k = static_cast<std::size_t>(end_slot_[s][end]);
      if (k < free_) adjacency_[next[k]++] = {static_cast<std::int32_t>(s), end == 0 ? 1.0 : -1.0};
    }
  }
}

template <class T>
inline void LocalGlobal<T>::spring_directions(const State<T>& s, int threads) {
  for_each_block(spring_count(), threads, [&](std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k) {
      const auto ia = static_cast<std::size_t>(end_vertex_[k][0]);
      const auto ib = static_cast<std::size_t>(end_vertex_[k][1]);
      const double dx = double(s.pos.x[ia]) - double(s.pos.x[ib]);
      const double dy = double(s.pos.y[ia]) - double(s.pos.y[ib]);
      const double dz = double(s.pos.z[ia]) - double(s.pos.z[ib]);
      const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double inv = len > 0.0 ? 1.0 / len : 0.0;
      direction_[4 * k] = dx * inv;
      direction_[4 * k + 1] = dy * inv;
      direction_[4 * k + 2] = dz * inv;
      direction_[4 * k + 3] = len > 0.0 ? len : 0.0;
    }
  });
}

template <class T>
inline void LocalGlobal<T>::right_hand_side(double h, int threads) {
  const double h2 = h * h;
  for_each_block(free_, threads, [&](std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k) {
      const auto i = static_cast<std::size_t>(slot_vertex_[k]);
      const double force[3] = {double(f_.x[i]), double(f_.y[i]), double(f_.z[i])};
      double pin[3] = {0.0, 0.0, 0.0};
      for (std::size_t p = adjacency_start_[k]; p < adjacency_start_[k + 1]; ++p) {
        const auto s = static_cast<std::size_t>(adjacency_[p].spring);
        const auto other = static_cast<std::size_t>(end_slot_[s][adjacency_[p].sign > 0 ? 1 : 0]);
        if (other < free_) continue;
        for (int a = 0; a < 3; ++a) pin[a] += spring_weight_[s] * q_[3 * other + a];
      }
      const double d = slot_mass_[k];
      for (int a = 0; a < 3; ++a) {
        base_[3 * k + a] = d * q_[3 * k + a] + h2 * force[a] + pin[a];
        q_[3 * k + a] += h2 * force[a] / d;
      }
    }
  });
}

template <class T>
template <bool Damped>
inline void LocalGlobal<T>::local_step(double h, int threads) {
  const double h2 = h * h;
  for_each_block(spring_count(), threads, [&](std::size_t b, std::size_t e) {
    const double* __restrict q = q_.data();
    const double* __restrict dir = direction_.data();
    double* __restrict out = e_.data();
    for (std::size_t s = b; s < e; ++s) {
      const auto ka = static_cast<std::size_t>(end_slot_[s][0]);
      const auto kb = static_cast<std::size_t>(end_slot_[s][1]);
      const double dx = q[3 * ka] - q[3 * kb], dy = q[3 * ka + 1] - q[3 * kb + 1],
                   dz = q[3 * ka + 2] - q[3 * kb + 2];
      const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double scale = len > 0.0 ? h2 * stiffness_[s] * rest_[s] / len : 0.0;
      double ex = scale * dx, ey = scale * dy, ez = scale * dz;
      if constexpr (Damped) {
        const double hc = h * damping_[s];
        const double nx = dir[4 * s], ny = dir[4 * s + 1], nz = dir[4 * s + 2];
        const double along = nx * dx + ny * dy + nz * dz - dir[4 * s + 3];
        ex += hc * (dx - nx * along);
        ey += hc * (dy - ny * along);
        ez += hc * (dz - nz * along);
      }
      out[3 * s] = ex;
      out[3 * s + 1] = ey;
      out[3 * s + 2] = ez;
    }
  });
}

template <class T>
inline void LocalGlobal<T>::accelerate(double omega, int threads) {
  for_each_block(3 * free_, threads, [&](std::size_t b, std::size_t e) {
    double* __restrict q = q_.data();
    const double* __restrict old = older_.data();
#pragma omp simd
    for (std::size_t k = b; k < e; ++k) q[k] = omega * (q[k] - old[k]) + old[k];
  });
}

template <class T>
inline void LocalGlobal<T>::gather(int threads) {
  for_each_block(free_, threads, [&](std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k) {
      double sum[3] = {base_[3 * k], base_[3 * k + 1], base_[3 * k + 2]};
      for (std::size_t p = adjacency_start_[k]; p < adjacency_start_[k + 1]; ++p) {
        const auto s = static_cast<std::size_t>(adjacency_[p].spring);
        const double sign = adjacency_[p].sign;
        for (int a = 0; a < 3; ++a) sum[a] += sign * e_[3 * s + a];
      }
      for (int a = 0; a < 3; ++a) q_[3 * k + a] = sum[a];
    }
  });
}

template <class T>
inline void LocalGlobal<T>::solve_in_place() {
  const auto& l = ldlt_.matrixL().nestedExpression();
  const int* __restrict col = l.outerIndexPtr();
  const int* __restrict row = l.innerIndexPtr();
  const double* __restrict val = l.valuePtr();
  double* __restrict q = q_.data();
  const auto n = static_cast<int>(free_);
  for (int j = 0; j < n; ++j) {  // L z = b
    const double x = q[3 * j], y = q[3 * j + 1], z = q[3 * j + 2];
    for (int p = col[j]; p < col[j + 1]; ++p) {
      double* r = q + 3 * row[p];
      r[0] -= val[p] * x;
      r[1] -= val[p] * y;
      r[2] -= val[p] * z;
    }
  }
  for (int j = 0; j < n; ++j) {  // D w = z
    const double inv = inv_diagonal_[static_cast<std::size_t>(j)];
    q[3 * j] *= inv;
    q[3 * j + 1] *= inv;
    q[3 * j + 2] *= inv;
  }
  for (int j = n - 1; j >= 0; --j) {  // L^T x = w
    double x = q[3 * j], y = q[3 * j + 1], z = q[3 * j + 2];
    for (int p = col[j]; p < col[j + 1]; ++p) {
      const double* r = q + 3 * row[p];
      x -= val[p] * r[0];
      y -= val[p] * r[1];
      z -= val[p] * r[2];
    }
    q[3 * j] = x;
    q[3 * j + 1] = y;
    q[3 * j + 2] = z;
  }
}

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_local_global(const Model<T>& m, const SolverSpec& spec) {
  return std::make_unique<LocalGlobal<T>>(m, spec);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_local_global)

}  // namespace clothlab
