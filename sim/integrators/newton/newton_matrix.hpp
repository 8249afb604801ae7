// The matrix of every Newton iteration of the implicit integrators (implicit_euler.cpp, and
// bdf2.cpp through it), A = M + h drag I - h D - h^2 K, with K the springs' compression-clamped
// stiffness and D their along-spring damping, and its block-Jacobi preconditioner.
//
// Matrix-free: each spring's block B_s = h^2 Ks + h c d d^T = alpha I + e e^T (e = sqrt(beta) d,
// beta >= 0; 4 numbers, the same at both ends) is computed once per Newton iteration in each
// of the spring's two slots, from that end's side, in the pass that also sums the diagonal
// blocks (on the 256^2 sheet a frame took 0.7x the time of a pass per spring whose blocks the
// slots then gathered, one thread), and the product (A u)_a = (m_a + h drag) u_a + sum_s B_s (u_a -
// u_b) is gathered per vertex (no atomics: the same bits for any thread count; the differences u_a
// - u_b keep it accurate in float where the h^2 k terms dwarf the mass). The neighbours are stored
// per 512-vertex block, slot-major: where a block's neighbours sit at a few fixed index offsets b -
// a (a grid cloth's stencil) a slot is one offset and the neighbours are read as a contiguous run
// ("diagonal" storage, no gather instructions); any other topology gets a padded neighbour-index
// table for that block. Measured on the 64x64 sheet at dt = 1/60 (one thread, AVX-512): PCG
// steps 1.8x (double) and 2.6x (float) faster than with a gathering neighbour table for every
// block, and 1.9x / 5x faster than a scalar walk over a CSR adjacency list.
//
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "sim/core/parallel.hpp"
#include "sim/core/symmetric3.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {

// How one vertex block stores its neighbours: `slots` slots of (end - begin) entries each from
// entry `entry`; with `diagonal`, slot k holds the neighbours at index offset shift[k].
struct BlockLayout {
  std::size_t entry = 0, slots = 0, shift = 0;  // shift: first of its offsets in shifts_
  bool diagonal = false;
};

template <class T>
class NewtonMatrix {
 public:
  explicit NewtonMatrix(const Model<T>& m);

  // For vertices [b, e) of block blk, from the state s: each slot's spring block B_s, the
  // diagonal blocks and their inverses; with `first` (the linearised step) each spring's
  // h^2 Ks (v_o - v_i) share of the right side `rhs`, which the caller filled before. Each
  // spring is evaluated at both its ends, from the vertex's own side: the same block (e flips
  // sign, e e^T does not), and no pass over springs or gather of their blocks. Pinned vertices
  // get a zero inverse and a zero right side, so their z, p and dv stay 0.
  void setup_block(const Model<T>& m, const State<T>& s, T h, bool first, Vec3Array<T>& rhs,
                   std::size_t blk, std::size_t b, std::size_t e);

  // out = A u on vertices [b, e) of block blk, 0 on pinned ones (which keeps their residual 0).
  void apply_block(const Model<T>& m, T h, const Vec3Array<T>& u, Vec3Array<T>& out,
                   std::size_t blk, std::size_t b, std::size_t e) const;

  // z = P r on [b, e): the inverse diagonal blocks (block Jacobi).
  void precondition(const Vec3Array<T>& r, Vec3Array<T>& out, std::size_t b, std::size_t e) const;
  T free(std::size_t i) const { return free_[i]; }

  // The springs in spring_list order and, after setup_block(), each one's block B_s = alpha I +
  // e e^T as (alpha, ex, ey, ez): what multigrid.hpp sums its coarse operators from.
  std::size_t spring_count() const { return ends_.size(); }
  std::array<int, 2> spring_ends(std::size_t s) const { return ends_[s]; }
  std::array<T, 4> spring_block(std::size_t s) const;

 private:
  // Slots [lo, hi) of diagonal slot k in vertex block [b, e): the vertices whose neighbour
  // i + shift is a vertex; outside that range the slot is empty. Empty slots inside it read a
  // real vertex and hold the zero block.
  std::pair<std::size_t, std::size_t> diagonal_range(const BlockLayout& l, std::size_t k,
                                                     std::size_t b, std::size_t e) const;

  // One slot's spring, seen from vertex i towards its neighbour o at offset (dx, dy, dz) with
  // relative velocity (ux, uy, uz) = v_o - v_i: B_s = h^2 Ks + h c d d^T = alpha I + e e^T with
  // d = (x_o - x_i) / l, Ks = k [d d^T + max(0, 1 - L/l) (I - d d^T)] (a zero-length spring at
  // zero length is k I), e = sqrt(beta) d; and r = h^2 Ks (v_o - v_i), i's share of the
  // linearised step's right side.
  struct SlotValue {
    T alpha, ex, ey, ez, rx, ry, rz;
  };
  template <bool WithRhs>
  static SlotValue slot_value(T dx, T dy, T dz, T ux, T uy, T uz, T ks, T rest, T c, T h);

  // Diagonal slot `row` (neighbour i + shift) for vertices [lo, hi) of the block from b: each
  // entry's block, added to the diagonal blocks and (WithRhs) the right side. Contiguous loads
  // and stores: vectorised.
  template <bool WithRhs>
  void diagonal_slots(const State<T>& s, T h, Vec3Array<T>& rhs, std::size_t row,
                      std::ptrdiff_t shift, std::size_t b, std::size_t lo, std::size_t hi);

  // Slot `at` of vertex i, its spring to vertex o (the neighbour-table layout): as
  // diagonal_slots for one entry.
  void slot_block(const State<T>& s, T h, bool first, Vec3Array<T>& rhs, std::size_t at,
                  std::size_t i, std::size_t o);

  // Inverts the symmetric positive definite diagonal blocks of [b, e) in place (adjugate over
  // determinant, in double: in float the h^2 k terms can dwarf the mass); zero on pinned
  // vertices, whose right side is zeroed too.
  void invert_diagonal(Vec3Array<T>& rhs, std::size_t b, std::size_t e);

  // Per vertex block, the slots of its neighbours (in index order). Diagonal storage when the
  // block's distinct offsets are at most twice its largest neighbour count (a grid stencil: as
  // many offsets as neighbours; a block straddling two grids of different widths: twice); else a
  // padded neighbour-index table. Returns each entry's spring (ns for an empty entry, which in the
  // table points at the vertex itself) and records each spring's entry at its first end.
  std::vector<std::int32_t> build_layout(std::size_t ns);

  std::size_t n_;
  std::vector<std::array<int, 2>> ends_;  // the springs in spring_list order
  std::vector<std::size_t> spring_slot_;  // each spring's entry at its first end

  // Neighbour slots per vertex block (see build_layout); per entry its spring's constants and,
  // per Newton iteration, the spring's block.
  std::vector<BlockLayout> layout_;
  std::vector<std::ptrdiff_t> shifts_;
  std::vector<std::int32_t> entry_other_;
  AlignedVector<T> stiffness_, rest_length_, damping_;
  AlignedVector<T> alpha_, ex_, ey_, ez_;

  AlignedVector<T> free_;     // 1 for a free vertex, 0 for a pinned one
  AlignedVector<T> precond_;  // xx, xy, xz, yy, yz, zz of the inverse blocks, n each
};

template <class T>
inline NewtonMatrix<T>::NewtonMatrix(const Model<T>& m) : n_(m.n) {
  const SpringList<T> list = spring_list(m);
  const std::size_t ns = list.size();
  ends_ = list.ends;
  const std::vector<std::int32_t> entry_spring = build_layout(ns);
  // Each entry's spring constants; an empty entry keeps 0 stiffness, 0 damping and 0 rest
  // length, whose block is 0 (see slot_value).
  for (AlignedVector<T>* v : {&stiffness_, &rest_length_, &damping_})
    v->assign(entry_spring.size(), T(0));
  for (std::size_t at = 0; at < entry_spring.size(); ++at) {
    const auto sp = static_cast<std::size_t>(entry_spring[at]);
    if (sp == ns) continue;
    stiffness_[at] = list.stiffness[sp];
    rest_length_[at] = list.rest_length[sp];
    damping_[at] = list.damping[sp];
  }
  free_.resize(n_);
  for (std::size_t i = 0; i < n_; ++i) free_[i] = m.inv_mass[i] == T(0) ? T(0) : T(1);
  for (AlignedVector<T>* v : {&alpha_, &ex_, &ey_, &ez_}) v->assign(entry_spring.size(), T(0));
  precond_.assign(6 * n_, T(0));
}

template <class T>
inline void NewtonMatrix<T>::setup_block(const Model<T>& m, const State<T>& s, T h, bool first,
                                         Vec3Array<T>& rhs, std::size_t blk, std::size_t b,
                                         std::size_t e) {
  T* __restrict pc = precond_.data();  // the diagonal block first, inverted in place below
  const std::size_t n = n_;
  for (std::size_t i = b; i < e; ++i) {
    const T diag = m.mass[i] + h * m.drag;
    pc[i] = diag, pc[n + i] = 0, pc[2 * n + i] = 0;
    pc[3 * n + i] = diag, pc[4 * n + i] = 0, pc[5 * n + i] = diag;
  }
  const BlockLayout& l = layout_[blk];
  const std::size_t len = e - b;
  for (std::size_t k = 0; k < l.slots; ++k) {
    const std::size_t row = l.entry + k * len;  // entry of vertex i: row + (i - b)
    if (l.diagonal) {
      // Entries outside [lo, hi) have no neighbour: they keep the zeros of construction.
      const auto [lo, hi] = diagonal_range(l, k, b, e);
      if (first)
        diagonal_slots<true>(s, h, rhs, row, shifts_[l.shift + k], b, lo, hi);
      else
        diagonal_slots<false>(s, h, rhs, row, shifts_[l.shift + k], b, lo, hi);
    } else {
      for (std::size_t i = b; i < e; ++i)
        slot_block(s, h, first, rhs, row + (i - b), i,
                   static_cast<std::size_t>(entry_other_[row + (i - b)]));
    }
  }
  invert_diagonal(rhs, b, e);
}

template <class T>
inline void NewtonMatrix<T>::apply_block(const Model<T>& m, T h, const Vec3Array<T>& u,
                                         Vec3Array<T>& out, std::size_t blk, std::size_t b,
                                         std::size_t e) const {
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
  for (std::size_t k = 0; k < l.slots; ++k) {
    const std::size_t row = l.entry + k * len;  // entry of vertex i: row + (i - b)
    if (l.diagonal) {
      // Neighbour i + shift for i in [lo, hi), the vertices whose neighbour index is in the
      // arrays; outside that range the slot is empty. Empty slots inside it read a real vertex
      // and multiply by the zero block.
      const std::ptrdiff_t shift = shifts_[l.shift + k];
      // Plain variables, not a structured binding: clang before 16 cannot use one inside the
      // `omp simd` loop below (scripts/fuzz builds with clang).
      const std::pair<std::size_t, std::size_t> range = diagonal_range(l, k, b, e);
      const std::size_t lo = range.first, hi = range.second;
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

template <class T>
inline void NewtonMatrix<T>::precondition(const Vec3Array<T>& r, Vec3Array<T>& out, std::size_t b,
                                          std::size_t e) const {
  const T* __restrict pc = precond_.data();
  const std::size_t n = n_;
  const T *rx = r.x.data(), *ry = r.y.data(), *rz = r.z.data();
  T *zx = out.x.data(), *zy = out.y.data(), *zz = out.z.data();
#pragma omp simd
  for (std::size_t i = b; i < e; ++i) {
    const T x = rx[i], y = ry[i], z = rz[i];
    zx[i] = pc[i] * x + pc[n + i] * y + pc[2 * n + i] * z;
    zy[i] = pc[n + i] * x + pc[3 * n + i] * y + pc[4 * n + i] * z;
    zz[i] = pc[2 * n + i] * x + pc[4 * n + i] * y + pc[5 * n + i] * z;
  }
}

template <class T>
inline std::array<T, 4> NewtonMatrix<T>::spring_block(std::size_t s) const {
  const std::size_t at = spring_slot_[s];
  return {alpha_[at], ex_[at], ey_[at], ez_[at]};
}

template <class T>
inline std::pair<std::size_t, std::size_t> NewtonMatrix<T>::diagonal_range(const BlockLayout& l,
                                                                           std::size_t k,
                                                                           std::size_t b,
                                                                           std::size_t e) const {
  const std::ptrdiff_t shift = shifts_[l.shift + k];
  const auto n = static_cast<std::ptrdiff_t>(n_);
  const auto lo = std::max<std::ptrdiff_t>(std::ptrdiff_t(b), -shift);
  const auto hi = std::min<std::ptrdiff_t>(std::ptrdiff_t(e), n - shift);
  return {static_cast<std::size_t>(lo), static_cast<std::size_t>(std::max(lo, hi))};
}

template <class T>
template <bool WithRhs>
inline typename NewtonMatrix<T>::SlotValue NewtonMatrix<T>::slot_value(T dx, T dy, T dz, T ux, T uy,
                                                                       T uz, T ks, T rest, T c,
                                                                       T h) {
  const T h2 = h * h;
  const T len = std::sqrt(dx * dx + dy * dy + dz * dz);
  const T inv_len = len > T(0) ? T(1) / len : T(0);
  dx *= inv_len, dy *= inv_len, dz *= inv_len;
  const T tw = len > rest ? T(1) - rest * inv_len : (rest > T(0) ? T(0) : T(1));
  const T root = std::sqrt(h2 * ks * (T(1) - tw) + h * c);
  SlotValue v{h2 * ks * tw, root * dx, root * dy, root * dz, T(0), T(0), T(0)};
  if constexpr (WithRhs) {
    const T along = (T(1) - tw) * (dx * ux + dy * uy + dz * uz);
    v.rx = h2 * ks * (tw * ux + along * dx);
    v.ry = h2 * ks * (tw * uy + along * dy);
    v.rz = h2 * ks * (tw * uz + along * dz);
  }
  return v;
}

template <class T>
template <bool WithRhs>
inline void NewtonMatrix<T>::diagonal_slots(const State<T>& s, T h, Vec3Array<T>& rhs,
                                            std::size_t row, std::ptrdiff_t shift, std::size_t b,
                                            std::size_t lo, std::size_t hi) {
  const std::size_t n = n_, at = row + (lo - b), o = std::size_t(std::ptrdiff_t(lo) + shift);
  const T *__restrict xi = s.pos.x.data() + lo, *__restrict yi = s.pos.y.data() + lo,
                      *__restrict zi = s.pos.z.data() + lo;
  const T *__restrict xo = s.pos.x.data() + o, *__restrict yo = s.pos.y.data() + o,
                      *__restrict zo = s.pos.z.data() + o;
  const T *__restrict vxi = s.vel.x.data() + lo, *__restrict vyi = s.vel.y.data() + lo,
                      *__restrict vzi = s.vel.z.data() + lo;
  const T *__restrict vxo = s.vel.x.data() + o, *__restrict vyo = s.vel.y.data() + o,
                      *__restrict vzo = s.vel.z.data() + o;
  const T *__restrict ks = stiffness_.data() + at, *__restrict rest = rest_length_.data() + at,
                      *__restrict c = damping_.data() + at;
  T* __restrict al = alpha_.data() + at;
  T* __restrict ex = ex_.data() + at;
  T* __restrict ey = ey_.data() + at;
  T* __restrict ez = ez_.data() + at;
  T* __restrict p0 = precond_.data() + lo;  // the diagonal blocks' six components
  T* __restrict p1 = p0 + n;
  T* __restrict p2 = p0 + 2 * n;
  T* __restrict p3 = p0 + 3 * n;
  T* __restrict p4 = p0 + 4 * n;
  T* __restrict p5 = p0 + 5 * n;
  T* __restrict bx = rhs.x.data() + lo, * __restrict by = rhs.y.data() + lo, * __restrict bz = rhs.z.data() + lo;
#pragma omp simd
  for (std::size_t j = 0; j < hi - lo; ++j) {
    const SlotValue v =
        WithRhs ? slot_value<true>(xo[j] - xi[j], yo[j] - yi[j], zo[j] - zi[j], vxo[j] - vxi[j],
                                   vyo[j] - vyi[j], vzo[j] - vzi[j], ks[j], rest[j], c[j], h)
                : slot_value<false>(xo[j] - xi[j], yo[j] - yi[j], zo[j] - zi[j], T(0), T(0), T(0),
                                    ks[j], rest[j], c[j], h);
    al[j] = v.alpha, ex[j] = v.ex, ey[j] = v.ey, ez[j] = v.ez;
    p0[j] += v.alpha + v.ex * v.ex;
    p1[j] += v.ex * v.ey;
    p2[j] += v.ex * v.ez;
    p3[j] += v.alpha + v.ey * v.ey;
    p4[j] += v.ey * v.ez;
    p5[j] += v.alpha + v.ez * v.ez;
    if constexpr (WithRhs) bx[j] += v.rx, by[j] += v.ry, bz[j] += v.rz;
  }
}

template <class T>
inline void NewtonMatrix<T>::slot_block(const State<T>& s, T h, bool first, Vec3Array<T>& rhs,
                                        std::size_t at, std::size_t i, std::size_t o) {
  const SlotValue v =
      slot_value<true>(s.pos.x[o] - s.pos.x[i], s.pos.y[o] - s.pos.y[i], s.pos.z[o] - s.pos.z[i],
                       s.vel.x[o] - s.vel.x[i], s.vel.y[o] - s.vel.y[i], s.vel.z[o] - s.vel.z[i],
                       stiffness_[at], rest_length_[at], damping_[at], h);
  alpha_[at] = v.alpha, ex_[at] = v.ex, ey_[at] = v.ey, ez_[at] = v.ez;
  T* __restrict pc = precond_.data();
  const std::size_t n = n_;
  pc[i] += v.alpha + v.ex * v.ex;
  pc[n + i] += v.ex * v.ey;
  pc[2 * n + i] += v.ex * v.ez;
  pc[3 * n + i] += v.alpha + v.ey * v.ey;
  pc[4 * n + i] += v.ey * v.ez;
  pc[5 * n + i] += v.alpha + v.ez * v.ez;
  if (first) rhs.x[i] += v.rx, rhs.y[i] += v.ry, rhs.z[i] += v.rz;
}

template <class T>
inline void NewtonMatrix<T>::invert_diagonal(Vec3Array<T>& rhs, std::size_t b, std::size_t e) {
  T* __restrict pc = precond_.data();
  const std::size_t n = n_;
  for (std::size_t i = b; i < e; ++i) {
    double block[6], adj[6];
    for (std::size_t c = 0; c < 6; ++c) block[c] = pc[c * n + i];
    const double det = symmetric3_adjugate(block, adj);
    const double scale = free_[i] != T(0) ? 1.0 / det : 0.0;
    for (std::size_t c = 0; c < 6; ++c) pc[c * n + i] = static_cast<T>(adj[c] * scale);
    rhs.x[i] *= free_[i], rhs.y[i] *= free_[i], rhs.z[i] *= free_[i];
  }
}

template <class T>
inline std::vector<std::int32_t> NewtonMatrix<T>::build_layout(std::size_t ns) {
  std::vector<std::vector<std::pair<std::int32_t, std::int32_t>>> rows(n_);
  for (std::size_t s = 0; s < ns; ++s) {
    const auto sp = static_cast<std::int32_t>(s);
    const auto [a, b] = ends_[s];
    rows[static_cast<std::size_t>(a)].emplace_back(b, sp);
    rows[static_cast<std::size_t>(b)].emplace_back(a, sp);
  }
  for (auto& row : rows) std::sort(row.begin(), row.end());
  layout_.resize(block_count(n_));
  spring_slot_.assign(ns, 0);
  std::vector<std::int32_t> entry_spring;
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
    l.entry = entry_spring.size();
    l.diagonal = offsets.size() <= 2 * widest;
    l.slots = l.diagonal ? offsets.size() : widest;
    l.shift = shifts_.size();
    if (l.diagonal) shifts_.insert(shifts_.end(), offsets.begin(), offsets.end());
    entry_spring.resize(l.entry + l.slots * len, static_cast<std::int32_t>(ns));
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
        const std::size_t at = l.entry + k * len + (i - b);
        entry_spring[at] = sp;
        entry_other_[at] = o;
        if (static_cast<int>(i) == ends_[static_cast<std::size_t>(sp)][0])
          spring_slot_[static_cast<std::size_t>(sp)] = at;
      }
    }
  }
  return entry_spring;
}

}  // namespace clothlab
