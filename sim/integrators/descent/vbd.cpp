// Vertex Block Descent: Chen, Macklin, Yang, Yuksel, Kim, Kavan & Chen 2024, "Vertex Block
// Descent", ACM TOG 43(4) (SIGGRAPH 2024), Algorithm 1.
//
// Backward Euler is the minimisation of the incremental potential (multiplied through by h^2)
//   G(x) = 1/2 sum_i w_i |x_i - t_i|^2 + h^2 sum_s E_s(x) + h D(x),
// with, per free vertex, w_i = m_i + h drag and t_i = x_n + h v_n + h^2 f_i / w_i (f: gravity,
// drag at v_n and wind, explicit at the start of the step; compute_external_forces()). With f
// holding -drag v_n this makes the linear drag implicit, exactly as in local_global.cpp. The
// springs are exactly the scene's (spring_list(): k, L, c): E_s = 1/2 k (|x_a - x_b| - L)^2, and
// the along-spring damper -c ((v_a - v_b) . n) n at v = (x - x_n) / h is the dissipation term
//   h D = (c h / 2) (n . (dx_a - dx_b))^2,   dx = x - x_n,
// with n the spring's current direction: its gradient at the vertex a is h c n (n . (dx_a -
// dx_b)), minus h^2 times the damping force, and its Hessian h c n n^T (the paper's Rayleigh
// term with the spring's own Hessian n n^T; the derivative of n is left out, as Baraff & Witkin
// 1998 do).
//
// One iteration visits every free vertex once and takes a Newton step on G as a function of
// that vertex alone (the paper's eq. (7)-(9)):
//   g_i = w_i (x_i - t_i) + sum_s [ -h^2 k (l - L) n + h c n (n . (dx_i - dx_j)) ],
//   H_i = w_i I + sum_s [ h^2 k (n n^T + max(0, 1 - L/l) (I - n n^T)) + h c n n^T ],
//   x_i -= H_i^-1 g_i,
// n = (x_j - x_i) / l. The max(0, .) keeps H_i positive definite (a compressed spring's
// transverse term is negative: the projection implicit_euler.cpp uses too). Vertices are coloured
// so that no two of a colour share a spring (greedy, in index order; on a grid the seed rule's
// 20-neighbour stencil takes 11 colours), and the vertices of one colour update in parallel in
// fixed blocks: bit-identical for any thread count. Grid cloths take the grid path instead
// (vbd_grid.hpp: 9 colours, vectorised rows); this path serves tubes and meshes and is the tests'
// reference. The arithmetic per spring is vbd_common.hpp's, shared by both paths.
//
// Initial guess: the paper's adaptive one (Sec. 3.6), x = x_n + h v_n + h^2 a~ with a~ the last
// step's acceleration (v_n - v_{n-1}) / h projected on gravity's direction and clamped to
// [0, |g|] (after invalidate() the full gravity). Chebyshev acceleration (Wang 2015, "A
// Chebyshev semi-iterative approach for accelerating projective and position-based dynamics",
// ACM TOG 34(6); chebyshev.hpp) after S = kChebyshevDelay plain iterations, with rho =
// solver.chebyshev_rho or kChebyshevRho. Then v_(n+1) = (x - x_n) / h. Pinned vertices keep x
// and v.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sim/core/parallel.hpp"
#include "sim/integrators/descent/chebyshev.hpp"
#include "sim/integrators/descent/vbd_common.hpp"
#include "sim/integrators/descent/vbd_grid.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {
namespace {

// Greedy vertex colouring of the spring graph: each vertex (in index order) takes the lowest
// colour none of its neighbours has. Returns the colour of each vertex.
std::vector<int> colour_vertices(std::size_t n, const std::vector<std::vector<int>>& adjacent) {
  std::vector<int> colour(n, -1);
  std::vector<char> taken;
  for (std::size_t i = 0; i < n; ++i) {
    taken.assign(adjacent[i].size() + 1, 0);
    for (int j : adjacent[i]) {
      const int c = colour[static_cast<std::size_t>(j)];
      if (c >= 0 && c < static_cast<int>(taken.size())) taken[static_cast<std::size_t>(c)] = 1;
    }
    int c = 0;
    while (taken[static_cast<std::size_t>(c)]) ++c;
    colour[i] = c;
  }
  return colour;
}

template <class T>
class Vbd final : public Integrator<T> {
 public:
  // colours: one per vertex (the tests give the grid path's); empty: a greedy colouring.
  Vbd(const Model<T>& m, const SolverSpec& spec, std::vector<int> colours = {});

  void step(const System<T>& sys, State<T>& s, double t, T h) override;

  void invalidate() override { warm_ = false; }
  void state_corrected() override {}  // the last velocity still predicts the next acceleration
  SolveStats last_stats() const override { return {iterations_, 0.0, true}; }

 private:
  // Colours the free vertices and stores, colour by colour, each one's springs (other end,
  // k, L, c) in a compact adjacency list.
  void build(const Model<T>& m, std::vector<int> colour);

  // Packs x_n (start_), the inertial target t (target_) and the initial guess (x_), all vertices
  // (pinned ones sit at x_n in all three).
  void predict(const Model<T>& m, const State<T>& s, T h, int threads);

  // One Newton step on G for each free vertex of [begin, end) (positions in order_): no two
  // share a spring, so the order within the range does not matter.
  void descend(std::size_t begin, std::size_t end, T h);

  // Chebyshev after iteration it (0-based) over free vertices [b, e) of order_: x^(k) = omega
  // (x^(k) - x^(k-2)) + x^(k-2) from the second iteration on (k = it + 1; x^(0) the initial
  // guess), then shifts the last two iterates (previous_ = x^(k-1), older_ = x^(k-2)).
  void accelerate(std::size_t b, std::size_t e, T omega, int it);

  // x_(n+1) = x, v_(n+1) = (x - x_n) / h for the free vertices; remembers v_n.
  void finish(const Model<T>& m, State<T>& s, T h, int threads);

  int iterations_;
  Chebyshev chebyshev_;
  bool warm_ = false;
  T drag_ = 0;
  // Free vertices colour by colour (order_), with their springs: links [link_start_[k],
  // link_start_[k + 1]) of other_ (the other end), stiffness_, rest_, damping_.
  std::vector<std::size_t> colour_start_;
  std::vector<std::int32_t> order_, link_start_, other_;
  AlignedVector<T> stiffness_, rest_, damping_, weight_;  // weight_: m per entry of order_
  Vec3Array<T> f_, last_vel_;
  // Packed per vertex (x, y, z, unused): the iterate, x_n, the inertial target, and the two
  // previous iterates for Chebyshev.
  AlignedVector<T> x_, start_, target_, older_, previous_;
};

template <class T>
inline Vbd<T>::Vbd(const Model<T>& m, const SolverSpec& spec, std::vector<int> colours)
    : iterations_(spec.iterations > 0 ? spec.iterations : kVbdDefaultIterations),
      chebyshev_(chebyshev_of(spec.chebyshev_rho, kVbdChebyshevRho, kVbdChebyshevDelay)) {
  build(m, std::move(colours));
  f_.resize(m.n);
  x_.assign(4 * m.n, T(0));
  start_.assign(4 * m.n, T(0));
  target_.assign(4 * m.n, T(0));
  older_.assign(4 * m.n, T(0));
  previous_.assign(4 * m.n, T(0));
  last_vel_.resize(m.n);
}

template <class T>
inline void Vbd<T>::step(const System<T>& sys, State<T>& s, double t, T h) {
  const Model<T>& m = sys.model;
  compute_external_forces(m, t, s.pos, s.vel, f_, sys.workspace, sys.threads);
  predict(m, s, h, sys.threads);
  const int colours = static_cast<int>(colour_start_.size()) - 1;
  const std::size_t free = order_.size();
  T omega = 1;
  for (int it = 0; it < iterations_; ++it) {
    for_each_phase_block(
        colours,
        [&](int c) {
          return colour_start_[static_cast<std::size_t>(c) + 1] -
                 colour_start_[static_cast<std::size_t>(c)];
        },
        sys.threads,
        [&](int c, std::size_t b, std::size_t e) {
          const std::size_t first = colour_start_[static_cast<std::size_t>(c)];
          descend(first + b, first + e, h);
        });
    omega = static_cast<T>(chebyshev_weight(chebyshev_, it, double(omega)));
    for_each_block(free, sys.threads,
                   [&](std::size_t b, std::size_t e) { accelerate(b, e, omega, it); });
  }
  finish(m, s, h, sys.threads);
  warm_ = true;
}

template <class T>
inline void Vbd<T>::build(const Model<T>& m, std::vector<int> colour) {
  const SpringList<T> list = spring_list(m);
  std::vector<std::vector<int>> adjacent(m.n), springs(m.n);
  for (std::size_t s = 0; s < list.size(); ++s) {
    const auto [a, b] = list.ends[s];
    if (list.stiffness[s] == T(0) && list.damping[s] == T(0)) continue;
    adjacent[a].push_back(b), springs[a].push_back(static_cast<int>(s));
    adjacent[b].push_back(a), springs[b].push_back(static_cast<int>(s));
  }
  if (colour.empty()) colour = colour_vertices(m.n, adjacent);
  int colours = 0;
  for (std::size_t i = 0; i < m.n; ++i)
    if (m.inv_mass[i] != T(0)) colours = std::max(colours, colour[i] + 1);
  colour_start_.assign(static_cast<std::size_t>(colours) + 1, 0);
  for (int c = 0; c < colours; ++c) {
    for (std::size_t i = 0; i < m.n; ++i) {
      if (m.inv_mass[i] == T(0) || colour[i] != c) continue;
      order_.push_back(static_cast<std::int32_t>(i));
      link_start_.push_back(static_cast<std::int32_t>(other_.size()));
      for (std::size_t q = 0; q < adjacent[i].size(); ++q) {
        const auto s = static_cast<std::size_t>(springs[i][q]);
        other_.push_back(adjacent[i][q]);
        stiffness_.push_back(list.stiffness[s]);
        rest_.push_back(list.rest_length[s]);
        damping_.push_back(list.damping[s]);
      }
    }
    colour_start_[static_cast<std::size_t>(c) + 1] = order_.size();
  }
  link_start_.push_back(static_cast<std::int32_t>(other_.size()));
  weight_.assign(order_.size(), T(0));
  for (std::size_t k = 0; k < order_.size(); ++k)
    weight_[k] = m.mass[static_cast<std::size_t>(order_[k])];
  drag_ = m.drag;
}

template <class T>
inline void Vbd<T>::predict(const Model<T>& m, const State<T>& s, T h, int threads) {
  const bool warm = warm_;
  for_each_block(m.n, threads, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      const VbdStart<T> v = vbd_start(m, i, s, f_, last_vel_, h, warm);
      for (int a = 0; a < 3; ++a) {
        start_[4 * i + a] = v.start[a];
        target_[4 * i + a] = v.target[a];
        x_[4 * i + a] = previous_[4 * i + a] = v.guess[a];
      }
    }
  });
}

template <class T>
inline void Vbd<T>::descend(std::size_t begin, std::size_t end, T h) {
  const T h2 = h * h;
  T* __restrict x = x_.data();
  const T* __restrict x0 = start_.data();
  const T* __restrict target = target_.data();
  for (std::size_t k = begin; k < end; ++k) {
    const auto i = static_cast<std::size_t>(order_[k]);
    const T w = weight_[k] + h * drag_;
    T* xi = x + 4 * i;
    const T dix = xi[0] - x0[4 * i], diy = xi[1] - x0[4 * i + 1], diz = xi[2] - x0[4 * i + 2];
    VbdBlock<T> blk =
        vbd_inertia(w, xi[0] - target[4 * i], xi[1] - target[4 * i + 1], xi[2] - target[4 * i + 2]);
    for (auto q = static_cast<std::size_t>(link_start_[k]);
         q < static_cast<std::size_t>(link_start_[k + 1]); ++q) {
      const auto j = static_cast<std::size_t>(other_[q]);
      const T* xj = x + 4 * j;
      vbd_add_spring(xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2], dix - (xj[0] - x0[4 * j]),
                     diy - (xj[1] - x0[4 * j + 1]), diz - (xj[2] - x0[4 * j + 2]),
                     h2 * stiffness_[q], h * damping_[q], rest_[q], blk);
    }
    T sx, sy, sz;
    vbd_newton_step(blk, sx, sy, sz);  // zero where H is not positive definite
    xi[0] -= sx, xi[1] -= sy, xi[2] -= sz;
  }
}

template <class T>
inline void Vbd<T>::accelerate(std::size_t b, std::size_t e, T omega, int it) {
  for (std::size_t k = b; k < e; ++k) {
    const auto i = 4 * static_cast<std::size_t>(order_[k]);
    for (int a = 0; a < 3; ++a) {
      T& x = x_[i + a];
      if (it >= 1) x = omega * (x - older_[i + a]) + older_[i + a];
      older_[i + a] = previous_[i + a];
      previous_[i + a] = x;
    }
  }
}

template <class T>
inline void Vbd<T>::finish(const Model<T>& m, State<T>& s, T h, int threads) {
  const T inv_h = T(1) / h;
  for_each_block(m.n, threads, [&](std::size_t b, std::size_t e) {
    for (int a = 0; a < 3; ++a) {
      T* __restrict x = s.pos.axis(a).data();
      T* __restrict v = s.vel.axis(a).data();
      T* __restrict last = last_vel_.axis(a).data();
      for (std::size_t i = b; i < e; ++i) {
        last[i] = v[i];
        if (m.inv_mass[i] == T(0)) continue;
        v[i] = (x_[4 * i + a] - start_[4 * i + a]) * inv_h;
        x[i] = x_[4 * i + a];
      }
    }
  });
}

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_vbd(const Model<T>& m, const SolverSpec& spec) {
  if (vbd_grid_applies(m)) return make_vbd_grid(m, spec);
  return std::make_unique<Vbd<T>>(m, spec);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_vbd)

template <class T>
std::unique_ptr<Integrator<T>> make_vbd_in_order(const Model<T>& m, const SolverSpec& spec,
                                                 std::vector<int> colours) {
  return std::make_unique<Vbd<T>>(m, spec, std::move(colours));
}
template std::unique_ptr<Integrator<float>> make_vbd_in_order<float>(const Model<float>&,
                                                                     const SolverSpec&,
                                                                     std::vector<int>);
template std::unique_ptr<Integrator<double>> make_vbd_in_order<double>(const Model<double>&,
                                                                       const SolverSpec&,
                                                                       std::vector<int>);

}  // namespace clothlab
