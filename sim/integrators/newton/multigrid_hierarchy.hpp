// The coarse levels of the multigrid preconditioner for the implicit integrators' Newton systems
// (multigrid.hpp). Every level's operator has the form of the finest one (newton_matrix.hpp):
//   (A u)_I = D_I u_I + sum over edges e = (I, J) of B_e (u_I - u_J),
// with 3x3 symmetric blocks D_I (mass, drag, and springs to pinned vertices) and B_e (springs).
// Coarsening is by aggregation: 2 x 2 vertices of a grid or tube cloth (a mesh cloth's vertices
// greedily with their neighbours) become one coarse vertex, and prolongation P copies a coarse
// vertex's value to its aggregate (piecewise constant). The Galerkin operator P^T A P is then of
// the same form and is summed without a product: a spring inside one aggregate drops out, a
// spring between two aggregates adds its block to their coarse edge, a spring to a pinned vertex
// adds its block to the diagonal (Vanek, Mandel & Brezina 1996, "Algebraic multigrid by smoothed
// aggregation", Computing 56, with the smoothing of P left out: the measured prototype needed
// 1.1-1.6x the cycles of bilinear prolongation for a tenth of the Galerkin work, docs/solver.md).
// Coarse operators are summed in double and applied in float; the topology is built once per scene,
// the values refreshed per Newton iteration without allocation; the coarsest level is factorised
// (Eigen's LDLT).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>
#include <vector>

namespace clothlab {

// One coarse level: its operator, vectors and the map to the next coarser level. Vectors are
// stored by axis (x of every vertex, then y, then z: v[a * n + i]); the operator's edge blocks are
// also kept in `slots` padded rows, slot-major (row_block[(k * 6 + c) * n + i] is component c of
// vertex i's edge in slot k, zero where it has none), so the product runs as one vectorised loop
// per slot. On a grid's levels every edge joins vertices a few fixed index offsets apart, and
// slot k holds the edges to vertex i + shift[k] (read as a contiguous run, as the fine matrix
// does); elsewhere (a mesh's levels, many offsets) slot k is a vertex's k-th edge and
// row_vertex[k * n + i] its other end (a gather; padding points at i itself).
// The cycle's working precision on the coarse levels: a preconditioner needs no more (PCG and
// the Newton residual run in the scene's precision), and float halves the products' memory
// traffic and doubles their vector width. The Galerkin sums and the coarsest factors are double.
using CoarseReal = float;

struct CoarseLevel {
  std::size_t n = 0, slots = 0;
  std::vector<std::array<int, 2>> edges;             // (I, J), I < J
  std::vector<double> edge_block;                    // 6 per edge: xx xy xz yy yz zz
  std::vector<double> diag;                          // 6 per vertex: D_I
  std::vector<char> live;                            // has a free fine vertex below it
  std::vector<int> adj_start, adj_vertex, adj_edge;  // CSR: the edges at each vertex
  std::vector<long> shift;                           // per slot, where the offsets are few
  std::vector<int> row_vertex;                       // slots x n, where they are not
  std::vector<int> adj_slot;                         // per CSR entry: its slot
  std::vector<CoarseReal> row_block, diag_by_axis;   // 6 x slots x n; 6 x n (D_I)
  std::vector<CoarseReal> inv;                       // 6 x n: (D_I + sum of its B_e)^-1
  std::vector<CoarseReal> x, b, r;                   // 3 x n
  std::vector<CoarseReal> kb, kc, kv;  // the K-cycle's right side, first direction, its product
  std::vector<double> partials;        // dot products, up to 3 per vertex block
  // Into the next coarser level (empty at the coarsest): each vertex's aggregate, each edge's
  // target (fine_edge_target's encoding) and each coarse vertex's children (CSR).
  std::vector<int> to_coarse, edge_target, child_start, child;
};

// A cloth's vertices at one level, for aggregation: a grid of nu x nv from `offset`, or `nu`
// vertices of a mesh.
struct LevelGrid {
  int offset = 0, nu = 0, nv = 0;
  bool mesh = false;
};

// Where a fine edge's block goes in the next level: an edge index (>= 0), nowhere (kInside: both
// ends in one aggregate or both left out), or the diagonal of coarse vertex I (-2 - I: one end
// left out, a pinned vertex).
inline constexpr int kInside = -1;
inline int diagonal_target(int coarse_vertex) {
  return -2 - coarse_vertex;
}

// The aggregation of one level and the topology of the next.
struct CoarseMap {
  std::vector<int> of;  // per vertex: its aggregate; -1 for a left-out vertex
  std::size_t count = 0;
  std::vector<LevelGrid> grids;           // the next level's cloths
  std::vector<std::array<int, 2>> edges;  // the next level's edges
  std::vector<int> edge_target;           // per edge of this level
  std::vector<int> child_start, child;    // per aggregate: its vertices (not the left-out ones)
};

// The CSR of `of`'s inverse: for each of `count` groups, the indices v with of[v] equal to it, in
// index order (of[v] < 0: in none).
void group_by(const std::vector<int>& of, std::size_t count, std::vector<int>& start,
              std::vector<int>& child);

CoarseMap coarsen(std::size_t n, const std::vector<std::array<int, 2>>& edges,
                  const std::vector<char>& left_out, const std::vector<LevelGrid>& grids);

class CoarseHierarchy {
 public:
  static constexpr std::size_t kCoarsest = 64;  // vertices solved directly
  // Damped block Jacobi's weight on every level. Measured (docs/solver.md, "Multigrid
  // preconditioner"): 0.6 / 0.8 / 0.9 take 46 / 41 / 40 iterations on the 32^2 falling sheet and
  // 62 / 53 / 51 on the 128^2 one; above 0.8 the gain is within the noise while the margin to
  // the smoother's bound (omega < 2 / lambda_max(D^-1 A), about 1 on these stencils) shrinks.
  static constexpr double kOmega = 0.8;
  // The K-cycle's second step is taken when the first left more than this of the residual
  // (Notay & Vassilevski 2008, t = 0.25).
  static constexpr double kKrylovThreshold = 0.25;

  // From the finest level's coarse map (coarsen() of the springs and pinned vertices).
  explicit CoarseHierarchy(const CoarseMap& fine);

  // Level 1, whose diag and edge_block the caller fills from the fine operator before
  // finish_refresh().
  CoarseLevel& first() { return levels_.front(); }
  // The coarser levels' operators, every level's inverse diagonal and the coarsest factors.
  void finish_refresh(int threads);
  // first().x from first().b: the K-cycle (Krylov-accelerated: up to two flexible CG steps per
  // level, each preconditioned by a cycle whose coarse solve is again a K-cycle). Every thread
  // of the enclosing parallel region calls it (its loops are orphaned `omp for`s), or one
  // thread outside any.
  void solve() { krylov(0); }
  std::size_t levels() const { return levels_.size(); }

 private:
  void cycle(std::size_t l);
  void krylov(std::size_t l);
  void solve_coarsest();
  void factorise_coarsest();

  std::vector<CoarseLevel> levels_;
  Eigen::MatrixXd dense_;
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
  Eigen::VectorXd rhs_;
};

// y = A x on a level (vectors by axis), shared among the enclosing parallel region's threads.
void apply_level(const CoarseLevel& level, const std::vector<CoarseReal>& x,
                 std::vector<CoarseReal>& y);

}  // namespace clothlab
