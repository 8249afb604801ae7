// Multigrid as PCG's preconditioner for the implicit integrators (solver.linear_solver =
// "multigrid", or "auto" once block Jacobi's solves grow long): one cycle per PCG iteration over
// the finest level, the Newton matrix itself (newton_matrix.hpp: its matrix-free product and
// block-Jacobi inverse), with the aggregation levels of multigrid_hierarchy.hpp below it solved
// by their K-cycle. Block-Jacobi PCG's iterations grow with the grid's side (214 / 444 / 939 /
// 1826 on the falling sheet from 16^2 to 128^2); these grow about 1.1x per doubling (36 / 41 /
// 49 / 53; docs/solver.md, "Multigrid preconditioner").
//
// Per Newton iteration refresh() sums the first coarse level from the fine springs' blocks (each
// coarse vertex and edge gathers its own, no product) and the hierarchy the rest. Per PCG iteration
// apply(): z = omega P r (P the block-Jacobi inverse), the residual r - A z restricted to level
// 1 (each aggregate's sum), the coarse K-cycle, its correction copied back to each aggregate's
// vertices, and z += omega P (r - A z). Two products with A per cycle; pinned vertices stay 0.
#pragma once

#include <memory>
#include <vector>

#include "sim/core/parallel.hpp"
#include "sim/integrators/newton/multigrid_hierarchy.hpp"
#include "sim/integrators/newton/newton_matrix.hpp"

namespace clothlab {

template <class T>
class MultigridPreconditioner {
 public:
  MultigridPreconditioner(const Model<T>& m, const NewtonMatrix<T>& matrix);

  // Level 1 from the matrix's current spring blocks and diagonal, then the coarser levels. Each
  // coarse vertex and edge gathers its own sum (its vertices' mass and drag, then its springs,
  // in index order): in parallel, and the same bits for any thread count.
  void refresh(const Model<T>& m, const NewtonMatrix<T>& matrix, T h, int threads);

  struct Dots {
    double rz = 0.0, qz = 0.0;
  };

  // z = one cycle on r; returns r.z and, with q, q.z (`scratch` is overwritten). The whole cycle,
  // every level's loops, runs in one parallel region with barriers between the loops: a region
  // per loop cost more than the cycle's work below 128^2 (each wakes the sleeping threads), and
  // coarse levels on one thread left the other idle.
  Dots apply(const Model<T>& m, const NewtonMatrix<T>& matrix, T h, const Vec3Array<T>& r,
             Vec3Array<T>& z, Vec3Array<T>& scratch, const Vec3Array<T>* q, int threads);

  std::size_t levels() const { return 1 + coarse_->levels(); }

 private:
  // sum += the blocks of group g's springs (CSR start / spring), in their order.
  static void add_springs(const NewtonMatrix<T>& matrix, const std::vector<int>& start,
                          const std::vector<int>& spring, std::size_t g, double* sum);

  // out = r - A z on vertex block blk = [b, e) (0 on pinned vertices).
  static void residual(const Model<T>& m, const NewtonMatrix<T>& matrix, T h, const Vec3Array<T>& r,
                       const Vec3Array<T>& z, Vec3Array<T>& out, std::size_t blk, std::size_t b,
                       std::size_t e);

  // Level 1's right side on its vertices [b, e): each aggregate's sum of `fine`.
  void restrict_to(CoarseLevel& first, const Vec3Array<T>& fine, std::size_t b,
                   std::size_t e) const;

  CoarseMap fine_;
  std::unique_ptr<CoarseHierarchy> coarse_;
  std::vector<double> partials_;  // r.z and q.z per vertex block
  // CSR: the fine springs summed into each level-1 vertex's diagonal and each level-1 edge.
  std::vector<int> diag_start_, diag_spring_, edge_start_, edge_spring_;
};

template <class T>
inline MultigridPreconditioner<T>::MultigridPreconditioner(const Model<T>& m,
                                                           const NewtonMatrix<T>& matrix) {
  std::vector<std::array<int, 2>> springs(matrix.spring_count());
  for (std::size_t s = 0; s < springs.size(); ++s) springs[s] = matrix.spring_ends(s);
  std::vector<char> pinned(m.n, 0);
  for (std::size_t i = 0; i < m.n; ++i) pinned[i] = m.inv_mass[i] == T(0);
  std::vector<LevelGrid> grids;
  for (const ClothRange& c : m.cloths) grids.push_back({c.offset, c.nu, c.nv, c.mesh});
  fine_ = coarsen(m.n, springs, pinned, grids);
  coarse_ = std::make_unique<CoarseHierarchy>(fine_);
  partials_.assign(2 * block_count(m.n), 0.0);
  // Which fine springs each coarse vertex's diagonal and each coarse edge sum, in spring order.
  std::vector<int> to_diag(springs.size(), -1), to_edge(springs.size(), -1);
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const int t = fine_.edge_target[s];
    if (t >= 0) to_edge[s] = t;
    if (t < kInside) to_diag[s] = -2 - t;
  }
  group_by(to_diag, fine_.count, diag_start_, diag_spring_);
  group_by(to_edge, coarse_->first().edges.size(), edge_start_, edge_spring_);
}

template <class T>
inline void MultigridPreconditioner<T>::refresh(const Model<T>& m, const NewtonMatrix<T>& matrix,
                                                T h, int threads) {
  CoarseLevel& first = coarse_->first();
  for_each_block(first.n, threads, [&](std::size_t b, std::size_t e) {
    for (std::size_t c = b; c < e; ++c) {
      double sum[6] = {};
      for (int k = fine_.child_start[c]; k < fine_.child_start[c + 1]; ++k) {
        const auto i = std::size_t(fine_.child[std::size_t(k)]);
        const double d = double(m.mass[i]) + double(h) * double(m.drag);
        sum[0] += d, sum[3] += d, sum[5] += d;
      }
      add_springs(matrix, diag_start_, diag_spring_, c, sum);
      std::copy_n(sum, 6, &first.diag[6 * c]);
    }
  });
  for_each_block(first.edges.size(), threads, [&](std::size_t b, std::size_t e) {
    for (std::size_t t = b; t < e; ++t) {
      double sum[6] = {};
      add_springs(matrix, edge_start_, edge_spring_, t, sum);
      std::copy_n(sum, 6, &first.edge_block[6 * t]);
    }
  });
  coarse_->finish_refresh(threads);
}

template <class T>
inline typename MultigridPreconditioner<T>::Dots MultigridPreconditioner<T>::apply(
    const Model<T>& m, const NewtonMatrix<T>& matrix, T h, const Vec3Array<T>& r, Vec3Array<T>& z,
    Vec3Array<T>& scratch, const Vec3Array<T>* q, int threads) {
  const T omega = T(CoarseHierarchy::kOmega);
  const std::size_t n = m.n;
  CoarseLevel& first = coarse_->first();
  const long blocks = long(block_count(n));
  run_team(blocks > 1 ? threads : 1, [&] {
    team_blocks(n, [&](std::size_t, std::size_t b, std::size_t e) {  // z = omega P r
      matrix.precondition(r, z, b, e);
      for (int a = 0; a < 3; ++a)
        for (std::size_t i = b; i < e; ++i) z.axis(a)[i] *= omega;
    });
    team_blocks(n, [&](std::size_t k, std::size_t b, std::size_t e) {  // scratch = r - A z
      residual(m, matrix, h, r, z, scratch, k, b, e);
    });
    team_blocks(first.n, [&](std::size_t, std::size_t b, std::size_t e) {
      restrict_to(first, scratch, b, e);  // level 1's right side: each aggregate's sum
    });
    coarse_->solve();  // every thread: its loops are shared in this region
    team_blocks(n, [&](std::size_t, std::size_t b, std::size_t e) {
      for (int a = 0; a < 3; ++a) {  // z += P e (each vertex takes its aggregate's value)
        const CoarseReal* x = first.x.data() + std::size_t(a) * first.n;
        for (std::size_t i = b; i < e; ++i) {
          const int c = fine_.of[i];
          if (c >= 0) z.axis(a)[i] += T(x[c]);
        }
      }
    });
    team_blocks(n, [&](std::size_t k, std::size_t b, std::size_t e) {
      residual(m, matrix, h, r, z, scratch, k, b, e);
    });
    team_blocks(n, [&](std::size_t k, std::size_t b, std::size_t e) {
      matrix.precondition(scratch, scratch, b, e);  // z += omega P (r - A z); r.z per block
      double rz = 0.0, qz = 0.0;
      for (int a = 0; a < 3; ++a)
        for (std::size_t i = b; i < e; ++i) {
          z.axis(a)[i] += omega * scratch.axis(a)[i];
          rz += double(r.axis(a)[i]) * double(z.axis(a)[i]);
          if (q) qz += double(q->axis(a)[i]) * double(z.axis(a)[i]);
        }
      partials_[2 * k] = rz;
      partials_[2 * k + 1] = qz;
    });
  });
  Dots dots;
  for (long k = 0; k < blocks; ++k) {  // in block order
    dots.rz += partials_[2 * std::size_t(k)];
    dots.qz += partials_[2 * std::size_t(k) + 1];
  }
  return dots;
}

template <class T>
inline void MultigridPreconditioner<T>::add_springs(const NewtonMatrix<T>& matrix,
                                                    const std::vector<int>& start,
                                                    const std::vector<int>& spring, std::size_t g,
                                                    double* sum) {
  for (int k = start[g]; k < start[g + 1]; ++k) {
    const auto [alpha, ex, ey, ez] = matrix.spring_block(std::size_t(spring[std::size_t(k)]));
    sum[0] += double(alpha) + double(ex) * ex, sum[1] += double(ex) * ey;
    sum[2] += double(ex) * ez, sum[3] += double(alpha) + double(ey) * ey;
    sum[4] += double(ey) * ez, sum[5] += double(alpha) + double(ez) * ez;
  }
}

template <class T>
inline void MultigridPreconditioner<T>::residual(const Model<T>& m, const NewtonMatrix<T>& matrix,
                                                 T h, const Vec3Array<T>& r, const Vec3Array<T>& z,
                                                 Vec3Array<T>& out, std::size_t blk, std::size_t b,
                                                 std::size_t e) {
  matrix.apply_block(m, h, z, out, blk, b, e);
  for (int a = 0; a < 3; ++a)
    for (std::size_t i = b; i < e; ++i)
      out.axis(a)[i] = (r.axis(a)[i] - out.axis(a)[i]) * matrix.free(i);
}

template <class T>
inline void MultigridPreconditioner<T>::restrict_to(CoarseLevel& first, const Vec3Array<T>& fine,
                                                    std::size_t b, std::size_t e) const {
  for (int a = 0; a < 3; ++a)
    for (std::size_t c = b; c < e; ++c) {
      double sum = 0.0;
      for (int k = fine_.child_start[c]; k < fine_.child_start[c + 1]; ++k)
        sum += double(fine.axis(a)[std::size_t(fine_.child[std::size_t(k)])]);
      first.b[std::size_t(a) * first.n + c] = CoarseReal(sum);
    }
}

}  // namespace clothlab
