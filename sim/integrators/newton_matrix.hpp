// The matrix of every Newton iteration of the implicit integrators (implicit_euler.cpp, and
// bdf2.cpp through it), A = M + h drag I - h D - h^2 K, with K the springs' compression-clamped
// stiffness and D their along-spring damping, and its block-Jacobi preconditioner.
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
  explicit NewtonMatrix(const Model<T>& m) : n_(m.n) {
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
    for (AlignedVector<T>* v : {&alpha_, &ex_, &ey_, &ez_}) v->assign(entry_spring_.size(), T(0));
    precond_.assign(6 * n_, T(0));
  }

  // Per spring: B_s, and Ks (v_a - v_b), the spring's share of the right side's h^2 K v0 term.
  void assemble(const State<T>& s, T h, int threads) {
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

  // For vertices [b, e) of block blk: copies their springs' blocks into the slots and forms the
  // diagonal blocks and their inverses; with `first` (the linearised step) adds each spring's
  // h^2 Ks (v_a - v_b) term to the right side `rhs`, which the caller filled before. Pinned
  // vertices get a zero inverse and a zero right side, so their z, p and dv stay 0.
  void setup_block(const Model<T>& m, T h, bool first, Vec3Array<T>& rhs, std::size_t blk,
                   std::size_t b, std::size_t e) {
    const T h2 = h * h;
    T* __restrict bx = rhs.x.data();
    T* __restrict by = rhs.y.data();
    T* __restrict bz = rhs.z.data();
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
    // double: in float the h^2 k terms can dwarf the mass).
    for (std::size_t i = b; i < e; ++i) {
      double block[6], adj[6];
      for (std::size_t c = 0; c < 6; ++c) block[c] = pc[c * n + i];
      const double det = symmetric3_adjugate(block, adj);
      const double scale = free_[i] != T(0) ? 1.0 / det : 0.0;
      for (std::size_t c = 0; c < 6; ++c) pc[c * n + i] = static_cast<T>(adj[c] * scale);
      bx[i] *= free_[i], by[i] *= free_[i], bz[i] *= free_[i];
    }
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

  // z = P r on [b, e): the inverse diagonal blocks (block Jacobi).
  void precondition(const Vec3Array<T>& r, Vec3Array<T>& out, std::size_t b, std::size_t e) const {
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
  T free(std::size_t i) const {
    return free_[i];
  }

  // The springs in spring_list order and, after assemble(), each one's block B_s = alpha I +
  // e e^T as (alpha, ex, ey, ez): what multigrid.hpp sums its coarse operators from.
  std::size_t spring_count() const {
    return end_a_.size();
  }
  std::array<int, 2> spring_ends(std::size_t s) const {
    return {end_a_[s], end_b_[s]};
  }
  std::array<T, 4> spring_block(std::size_t s) const {
    const SpringBlock& b = blocks_[s];
    return {b.alpha, b.ex, b.ey, b.ez};
  }

 private:
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

  // B_s = alpha I + e e^T, one spring's block of A - M - h drag I, and rhs = Ks (v_a - v_b).
  struct SpringBlock {
    T alpha = 0, ex = 0, ey = 0, ez = 0;
    std::array<T, 3> rhs{};
  };

  std::size_t n_;
  // Springs in spring_list order, and per step their blocks (plus the zero spring).
  std::vector<std::int32_t> end_a_, end_b_;
  AlignedVector<T> stiffness_, rest_length_, damping_;
  std::vector<SpringBlock> blocks_;

  // Neighbour slots per vertex block (see build_layout) and, per step, the blocks they hold.
  std::vector<BlockLayout> layout_;
  std::vector<std::ptrdiff_t> shifts_;
  std::vector<std::int32_t> entry_spring_, entry_other_;
  AlignedVector<T> alpha_, ex_, ey_, ez_;

  AlignedVector<T> free_;     // 1 for a free vertex, 0 for a pinned one
  AlignedVector<T> precond_;  // xx, xy, xz, yy, yz, zz of the inverse blocks, n each
};

}  // namespace clothlab
