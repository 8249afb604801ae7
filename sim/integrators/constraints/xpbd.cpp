// XPBD: extended position-based dynamics with small steps.
//   Macklin, Mueller & Chentanez 2016, "XPBD: Position-Based Simulation of Compliant Constrained
//   Dynamics" (MIG '16), eq. (26) with damping;
//   Macklin, Storey, Lu, Terdiman, Chentanez, Jeschke & Mueller 2019, "Small Steps in Physics
//   Simulation" (SCA '19): many substeps, one constraint sweep each, lambda reset every substep.
//
// The material is the scene's, spring for spring (spring_list()): each spring (a, b) with
// stiffness k, rest length L and along-spring damping c is the distance constraint
//   C(x) = |x_a - x_b| - L,  grad_a C = n = (x_a - x_b) / |x_a - x_b|,  grad_b C = -n,
// with compliance alpha = 1 / k, so the constraint potential (1/2) alpha^-1 C^2 is exactly the
// spring's Hooke energy (1/2) k (|x_a - x_b| - L)^2, and with the paper's Rayleigh damping
// beta = c, whose dissipation (1/2) beta (grad C . v)^2 gives the force -c ((v_a - v_b) . n) n,
// exactly the along-spring damper. In the paper's notation (alpha~ = alpha / h^2,
// gamma = alpha~ beta~ / h = alpha beta / h = c / (k h)) eq. (26) reads
//   dlambda = (-C - alpha~ lambda - gamma grad C . (x - x_prev)) / ((1 + gamma) w + alpha~),
// w = w_a + w_b; we multiply it through by 1/alpha~ = k h^2 to get
//   dlambda = (-k h^2 C - lambda - c h grad C . (x - x_prev)) / ((k h^2 + c h) w + 1),
// the same value with no division by k, so a spring with k = 0 is a pure (implicit) damper and
// one with k = c = 0 does nothing. Then x_a += w_a dlambda n, x_b -= w_b dlambda n, which moves
// no momentum (m_a w_a = m_b w_b = 1 for free ends).
//
// Per substep h: gravity and wind are explicit at the start of the substep (the paper's
// prediction v += h f_ext / m); linear drag is taken implicitly per vertex,
// v = (v + h (f_ext + drag v) / m) / (1 + h drag / m), so no drag is too large for it; then
// x_prev = x, x += h v, `iterations` Gauss-Seidel sweeps (SolverSpec::iterations, 0 -> 1) and
// v = (x - x_prev) / h. With one sweep on one spring that does not turn this is exactly backward
// Euler (first order); as h -> 0 (k h^2 w << 1) it tends to symplectic Euler. With few sweeps a
// stiff lattice is left stretched (the constraints do not converge): more substeps fix that.
//
// Grid cloths (the row-sweep kernel) take the grid path instead (xpbd_grid.hpp: the same update
// in batches of one stencil offset and parity class, with tethers and coarse stretch levels);
// this file's path serves tubes and meshes and is the tests' reference.
// Parallelism: Gauss-Seidel is sequential, so the springs are edge-coloured once (greedy, in
// spring_list() order: no two springs of a colour share a vertex) and stored colour by colour.
// The colours are swept in order, one after another, and the springs of one colour are
// independent, so they run in parallel in fixed blocks: the result is bit-identical for any
// thread count. On the seed rule's 20-neighbour grid greedy colouring finds 20 colours, the
// minimum (the vertex degree), of about n / 2 springs each.
// Layout: during the projection each vertex is packed as (x, y, z, 1/m), one cache line per
// spring end instead of seven arrays (measured 20 % faster per sweep at 64 x 64; a SIMD loop
// with gathers and scatters was no faster than this scalar one).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sim/core/parallel.hpp"
#include "sim/integrators/constraints/xpbd_grid.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {
namespace {

// Greedy edge colouring: each spring gets the lowest colour used by neither end so far. Returns
// the colour of each spring; at most 2 * max_degree - 1 colours.
std::vector<int> colour_springs(std::size_t n, const std::vector<std::array<int, 2>>& ends) {
  std::vector<int> degree(n, 0);
  for (const auto& e : ends) ++degree[e[0]], ++degree[e[1]];
  int max_degree = 0;
  for (int d : degree) max_degree = std::max(max_degree, d);
  const std::size_t words = static_cast<std::size_t>(std::max(1, 2 * max_degree - 1) + 63) / 64;
  std::vector<std::uint64_t> used(n * words, 0);  // per vertex: bit c set when colour c is taken
  std::vector<int> colour(ends.size());
  for (std::size_t s = 0; s < ends.size(); ++s) {
    const std::uint64_t* ua = &used[static_cast<std::size_t>(ends[s][0]) * words];
    const std::uint64_t* ub = &used[static_cast<std::size_t>(ends[s][1]) * words];
    int c = 0;
    for (std::size_t w = 0; w < words; ++w) {
      const std::uint64_t free_bits = ~(ua[w] | ub[w]);
      if (free_bits != 0) {
        c = static_cast<int>(w * 64) + __builtin_ctzll(free_bits);
        break;
      }
    }
    colour[s] = c;
    for (int v : ends[s]) used[static_cast<std::size_t>(v) * words + c / 64] |= 1ull << (c % 64);
  }
  return colour;
}

template <class T>
class Xpbd final : public Integrator<T> {
 public:
  // order: a colour per spring of spring_list(m) (xpbd_grid_colours), or empty for the greedy
  // colouring.
  Xpbd(const Model<T>& m, const SolverSpec& spec, const std::vector<int>& order = {});

  void step(const System<T>& sys, State<T>& s, double t, T h) override;

  SolveStats last_stats() const override { return {sweeps_, 0.0, true}; }

 private:
  // v += h f / m with drag implicit per vertex; x_prev = x; x += h v, into the packed arrays.
  // Pinned vertices (inv_mass 0) keep v = 0 and do not move.
  void predict(const Model<T>& m, const State<T>& s, T h, int threads);

  // One XPBD update (eq. (26), multiplied through by k h^2) of springs [begin, end) of one
  // colour. No two of them share a vertex, so they do not interact and the order within the
  // colour does not matter. First: lambda is 0 (reset at the start of the substep). Positions
  // are packed (x, y, z, w) per vertex: one cache line per end instead of seven arrays.
  template <bool First>
  void project(std::size_t begin, std::size_t end, T h);

  int sweeps_;
  std::vector<std::size_t> colour_start_;  // springs of colour c: [colour_start_[c], [c + 1])
  std::vector<std::int32_t> a_, b_;        // ends, sorted by colour
  AlignedVector<T> stiffness_, rest_, damping_, lambda_;
  Vec3Array<T> f_;
  AlignedVector<T> p_, prev_;  // per vertex (x, y, z, inv_mass) and (x_prev, 0)
};

template <class T>
inline Xpbd<T>::Xpbd(const Model<T>& m, const SolverSpec& spec, const std::vector<int>& order)
    : sweeps_(spec.iterations > 0 ? spec.iterations : 1) {
  const SpringList<T> list = spring_list(m);
  // Springs that can act: not both ends pinned, and some stiffness or damping.
  std::vector<std::array<int, 2>> ends;
  std::vector<std::size_t> source;
  std::vector<int> colour;
  for (std::size_t s = 0; s < list.size(); ++s) {
    const auto [a, b] = list.ends[s];
    const bool movable = m.inv_mass[a] != T(0) || m.inv_mass[b] != T(0);
    if (movable && (list.stiffness[s] != T(0) || list.damping[s] != T(0))) {
      ends.push_back(list.ends[s]);
      source.push_back(s);
      if (!order.empty()) colour.push_back(order[s]);
    }
  }
  if (order.empty()) colour = colour_springs(m.n, ends);
  int colours = 0;
  for (int c : colour) colours = std::max(colours, c + 1);
  // Counting sort by colour, stable: spring_list() order within a colour.
  colour_start_.assign(static_cast<std::size_t>(colours) + 1, 0);
  for (int c : colour) ++colour_start_[static_cast<std::size_t>(c) + 1];
  for (int c = 0; c < colours; ++c) colour_start_[c + 1] += colour_start_[c];
  std::vector<std::size_t> next(colour_start_.begin(), colour_start_.end() - 1);
  const std::size_t count = ends.size();
  a_.resize(count);
  b_.resize(count);
  stiffness_.resize(count);
  rest_.resize(count);
  damping_.resize(count);
  lambda_.assign(count, T(0));
  for (std::size_t s = 0; s < count; ++s) {
    const std::size_t k = next[static_cast<std::size_t>(colour[s])]++;
    a_[k] = ends[s][0];
    b_[k] = ends[s][1];
    stiffness_[k] = list.stiffness[source[s]];
    rest_[k] = list.rest_length[source[s]];
    damping_[k] = list.damping[source[s]];
  }
  f_.resize(m.n);
  p_.assign(4 * m.n, T(0));
  prev_.assign(4 * m.n, T(0));
}

template <class T>
inline void Xpbd<T>::step(const System<T>& sys, State<T>& s, double t, T h) {
  const Model<T>& m = sys.model;
  compute_external_forces(m, t, s.pos, s.vel, f_, sys.workspace, sys.threads);
  predict(m, s, h, sys.threads);
  // Every colour of every sweep in one parallel region (a barrier between colours).
  const int colours = static_cast<int>(colour_start_.size()) - 1;
  for_each_phase_block(
      sweeps_ * colours,
      [&](int phase) {
        const auto c = static_cast<std::size_t>(phase % colours);
        return colour_start_[c + 1] - colour_start_[c];
      },
      sys.threads,
      [&](int phase, std::size_t b, std::size_t e) {
        const std::size_t first = colour_start_[static_cast<std::size_t>(phase % colours)];
        if (phase < colours) {
          project<true>(first + b, first + e, h);
        } else {
          project<false>(first + b, first + e, h);
        }
      });
  // x = the projected positions, v = (x - x_prev) / h.
  const T inv_h = T(1) / h;
  for_each_block(m.n, sys.threads, [&](std::size_t b, std::size_t e) {
    const T* __restrict p = p_.data();
    const T* __restrict prev = prev_.data();
    for (int a = 0; a < 3; ++a) {
      T* __restrict x = s.pos.axis(a).data();
      T* __restrict v = s.vel.axis(a).data();
#pragma omp simd
      for (std::size_t i = b; i < e; ++i) {
        x[i] = p[4 * i + a];
        v[i] = (p[4 * i + a] - prev[4 * i + a]) * inv_h;
      }
    }
  });
}

template <class T>
inline void Xpbd<T>::predict(const Model<T>& m, const State<T>& s, T h, int threads) {
  const T* __restrict inv_m = m.inv_mass.data();
  const T drag = m.drag;
  for_each_block(m.n, threads, [&](std::size_t b, std::size_t e) {
    T* __restrict p = p_.data();
    T* __restrict prev = prev_.data();
    for (int a = 0; a < 3; ++a) {
      const T* __restrict x = s.pos.axis(a).data();
      const T* __restrict v = s.vel.axis(a).data();
      const T* __restrict f = f_.axis(a).data();
#pragma omp simd
      for (std::size_t i = b; i < e; ++i) {
        // f already holds -drag v; adding it back and dividing makes the drag implicit.
        const T hw = h * inv_m[i];
        const T v_new =
            inv_m[i] > T(0) ? (v[i] + hw * (f[i] + drag * v[i])) / (T(1) + hw * drag) : T(0);
        prev[4 * i + a] = x[i];
        p[4 * i + a] = x[i] + h * v_new;
      }
    }
#pragma omp simd
    for (std::size_t i = b; i < e; ++i) p[4 * i + 3] = inv_m[i];
  });
}

template <class T>
template <bool First>
inline void Xpbd<T>::project(std::size_t begin, std::size_t end, T h) {
  T* __restrict p = p_.data();
  const T* __restrict prev = prev_.data();
  const std::int32_t* __restrict ia = a_.data();
  const std::int32_t* __restrict ib = b_.data();
  const T* __restrict ks = stiffness_.data();
  const T* __restrict rest = rest_.data();
  const T* __restrict cs = damping_.data();
  T* __restrict lambda = lambda_.data();
  const T h2 = h * h;
  for (std::size_t s = begin; s < end; ++s) {
    T* pa = p + 4 * static_cast<std::size_t>(ia[s]);
    T* pb = p + 4 * static_cast<std::size_t>(ib[s]);
    const T* qa = prev + 4 * static_cast<std::size_t>(ia[s]);
    const T* qb = prev + 4 * static_cast<std::size_t>(ib[s]);
    const T dx = pa[0] - pb[0], dy = pa[1] - pb[1], dz = pa[2] - pb[2];
    const T len = std::sqrt(dx * dx + dy * dy + dz * dz);
    // A zero-length spring has no direction: it gets no correction (n = 0 and C = 0).
    const T inv_len = len > T(0) ? T(1) / len : T(0);
    const T nx = dx * inv_len, ny = dy * inv_len, nz = dz * inv_len;
    const T stretch = len > T(0) ? len - rest[s] : T(0);
    // grad C . (x - x_prev): the relative displacement along the spring this substep.
    const T moved = nx * ((pa[0] - qa[0]) - (pb[0] - qb[0])) +
                    ny * ((pa[1] - qa[1]) - (pb[1] - qb[1])) +
                    nz * ((pa[2] - qa[2]) - (pb[2] - qb[2]));
    const T kh2 = ks[s] * h2, ch = cs[s] * h;
    const T lam = First ? T(0) : lambda[s];
    const T wa = pa[3], wb = pb[3];
    const T dlambda = (-kh2 * stretch - lam - ch * moved) / ((kh2 + ch) * (wa + wb) + T(1));
    lambda[s] = lam + dlambda;
    const T da = wa * dlambda, db = wb * dlambda;
    pa[0] += da * nx;
    pa[1] += da * ny;
    pa[2] += da * nz;
    pb[0] -= db * nx;
    pb[1] -= db * ny;
    pb[2] -= db * nz;
  }
}

}  // namespace

template <class T>
std::unique_ptr<Integrator<T>> make_xpbd(const Model<T>& m, const SolverSpec& spec) {
  if (xpbd_grid_applies(m)) return make_xpbd_grid(m, spec);
  return std::make_unique<Xpbd<T>>(m, spec);
}
CLOTHLAB_INSTANTIATE_FACTORY(make_xpbd)

template <class T>
std::unique_ptr<Integrator<T>> make_xpbd_in_order(const Model<T>& m, const SolverSpec& spec,
                                                  std::vector<int> colours) {
  return std::make_unique<Xpbd<T>>(m, spec, colours);
}
template std::unique_ptr<Integrator<float>> make_xpbd_in_order<float>(const Model<float>&,
                                                                      const SolverSpec&,
                                                                      std::vector<int>);
template std::unique_ptr<Integrator<double>> make_xpbd_in_order<double>(const Model<double>&,
                                                                        const SolverSpec&,
                                                                        std::vector<int>);

}  // namespace clothlab
