#include "sim/integrators/multigrid_hierarchy.hpp"

#include <algorithm>

#include "sim/core/parallel.hpp"
#include "sim/core/symmetric3.hpp"

namespace clothlab {
namespace {

// Levels below this many vertices run on one thread: a parallel region costs more than them.
constexpr std::size_t kParallelLevel = 8192;
// A coarsest level above this many vertices (no coarsening found) is smoothed, not factorised.
constexpr std::size_t kMaxDense = 1500;
constexpr int kCoarsestSweeps = 30;

int level_threads(const CoarseLevel& level, int threads) {
  return level.n >= kParallelLevel ? threads : 1;
}

// fn(begin, end) over the blocks of [0, n): on one thread a plain loop, which may run inside
// another parallel region's `omp single` (for_each_block's orphaned `omp for` would bind to that
// region's team there and wait at its barrier for threads that never come).
template <class Fn>
void for_blocks(std::size_t n, int threads, Fn&& fn) {
  if (threads > 1) return for_each_block(n, threads, fn);
  for (std::size_t b = 0; b < n; b += kBlockSize) fn(b, std::min(n, b + kBlockSize));
}

// out = M v for a symmetric 3x3 block stored xx xy xz yy yz zz.
inline void multiply(const double* m, const double* v, double* out) {
  out[0] = m[0] * v[0] + m[1] * v[1] + m[2] * v[2];
  out[1] = m[1] * v[0] + m[3] * v[1] + m[4] * v[2];
  out[2] = m[2] * v[0] + m[4] * v[1] + m[5] * v[2];
}

// The inverse of a symmetric positive definite 3x3 block; 0 for a singular one.
void invert(const double* m, double* out) {
  const double det = symmetric3_adjugate(m, out);
  const double s = det > 0.0 ? 1.0 / det : 0.0;
  for (int c = 0; c < 6; ++c) out[c] *= s;
}

// A mesh cloth's vertices [offset, offset + count) greedily: a vertex whose neighbours are all
// free starts an aggregate with them; the rest join a neighbour's aggregate (Vanek et al. 1996,
// plain aggregation). Returns the number of aggregates, numbered from `first`.
int aggregate_mesh(int offset, int count, const std::vector<std::vector<int>>& adjacency,
                   const std::vector<char>& left_out, int first, std::vector<int>& of) {
  int next = first;
  for (int v = offset; v < offset + count; ++v) {
    if (left_out[v] || of[v] >= 0) continue;
    bool free = true;
    for (int w : adjacency[v]) free = free && (left_out[w] || of[w] < 0);
    if (!free) continue;
    of[v] = next;
    for (int w : adjacency[v])
      if (!left_out[w]) of[w] = next;
    ++next;
  }
  for (int v = offset; v < offset + count; ++v) {
    if (left_out[v] || of[v] >= 0) continue;
    for (int w : adjacency[v])
      if (of[w] >= 0) of[v] = of[w];
    if (of[v] < 0) of[v] = next++;
  }
  return next - first;
}

// The CSR of `of`'s inverse: each aggregate's vertices in index order.
void children(const std::vector<int>& of, std::size_t count, std::vector<int>& start,
              std::vector<int>& child) {
  start.assign(count + 1, 0);
  for (int a : of)
    if (a >= 0) ++start[std::size_t(a) + 1];
  for (std::size_t k = 0; k < count; ++k) start[k + 1] += start[k];
  child.assign(std::size_t(start[count]), 0);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t v = 0; v < of.size(); ++v)
    if (of[v] >= 0) child[std::size_t(fill[std::size_t(of[v])]++)] = int(v);
}

void allocate(CoarseLevel& level) {
  const std::size_t n = level.n;
  level.edge_block.assign(6 * level.edges.size(), 0.0);
  level.diag.assign(6 * n, 0.0);
  level.inv.assign(6 * n, 0.0);
  for (auto* v : {&level.x, &level.b, &level.r}) v->assign(3 * n, 0.0);
  level.adj_start.assign(n + 1, 0);
  for (const auto& [i, j] : level.edges) ++level.adj_start[i + 1], ++level.adj_start[j + 1];
  for (std::size_t k = 0; k < n; ++k) level.adj_start[k + 1] += level.adj_start[k];
  level.adj_vertex.assign(std::size_t(level.adj_start[n]), 0);
  level.adj_edge.assign(level.adj_vertex.size(), 0);
  std::vector<int> fill(level.adj_start.begin(), level.adj_start.end() - 1);
  for (std::size_t e = 0; e < level.edges.size(); ++e) {
    const auto [i, j] = level.edges[e];
    level.adj_vertex[std::size_t(fill[i])] = j, level.adj_edge[std::size_t(fill[i]++)] = int(e);
    level.adj_vertex[std::size_t(fill[j])] = i, level.adj_edge[std::size_t(fill[j]++)] = int(e);
  }
}

}  // namespace

CoarseMap coarsen(std::size_t n, const std::vector<std::array<int, 2>>& edges,
                  const std::vector<char>& left_out, const std::vector<LevelGrid>& grids) {
  CoarseMap map;
  map.of.assign(n, -1);
  std::vector<std::vector<int>> adjacency;
  if (std::any_of(grids.begin(), grids.end(), [](const LevelGrid& g) { return g.mesh; })) {
    adjacency.resize(n);
    for (const auto& [a, b] : edges) adjacency[a].push_back(b), adjacency[b].push_back(a);
  }
  int next = 0;
  for (const LevelGrid& g : grids) {
    LevelGrid coarse{next, 0, 1, g.mesh};
    if (g.mesh) {
      coarse.nu = aggregate_mesh(g.offset, g.nu, adjacency, left_out, next, map.of);
    } else {  // 2 x 2 vertices (a tube's odd last column alone)
      coarse.nu = (g.nu + 1) / 2, coarse.nv = (g.nv + 1) / 2;
      for (int j = 0; j < g.nv; ++j)
        for (int i = 0; i < g.nu; ++i) {
          const int v = g.offset + i + j * g.nu;
          if (!left_out[v]) map.of[v] = next + i / 2 + (j / 2) * coarse.nu;
        }
    }
    next += coarse.nu * coarse.nv;
    map.grids.push_back(coarse);
  }
  map.count = std::size_t(next);
  map.edge_target.assign(edges.size(), kInside);
  for (const auto& [a, b] : edges) {
    const int ca = map.of[a], cb = map.of[b];
    if (ca >= 0 && cb >= 0 && ca != cb) map.edges.push_back({std::min(ca, cb), std::max(ca, cb)});
  }
  std::sort(map.edges.begin(), map.edges.end());
  map.edges.erase(std::unique(map.edges.begin(), map.edges.end()), map.edges.end());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int ca = map.of[edges[e][0]], cb = map.of[edges[e][1]];
    if (ca < 0 && cb < 0) continue;
    if (ca < 0 || cb < 0) {
      map.edge_target[e] = diagonal_target(std::max(ca, cb));
    } else if (ca != cb) {
      const std::array<int, 2> key{std::min(ca, cb), std::max(ca, cb)};
      map.edge_target[e] =
          int(std::lower_bound(map.edges.begin(), map.edges.end(), key) - map.edges.begin());
    }
  }
  children(map.of, map.count, map.child_start, map.child);
  return map;
}

CoarseHierarchy::CoarseHierarchy(const CoarseMap& fine) {
  levels_.emplace_back();
  levels_[0].n = fine.count;
  levels_[0].edges = fine.edges;
  levels_[0].live.assign(fine.count, 0);
  for (std::size_t c = 0; c < fine.count; ++c)
    levels_[0].live[c] = fine.child_start[c + 1] > fine.child_start[c];
  std::vector<LevelGrid> grids = fine.grids;
  while (levels_.back().n > kCoarsest) {
    CoarseLevel& level = levels_.back();
    const std::vector<char> none(level.n, 0);
    CoarseMap map = coarsen(level.n, level.edges, none, grids);
    if (map.count * 10 >= level.n * 9) break;  // no real coarsening left
    level.to_coarse = std::move(map.of);
    level.edge_target = std::move(map.edge_target);
    level.child_start = std::move(map.child_start);
    level.child = std::move(map.child);
    grids = std::move(map.grids);
    CoarseLevel next;
    next.n = map.count;
    next.edges = std::move(map.edges);
    next.live.assign(next.n, 0);
    for (std::size_t v = 0; v < level.n; ++v)
      if (level.live[v]) next.live[std::size_t(level.to_coarse[v])] = 1;
    levels_.push_back(std::move(next));
  }
  for (CoarseLevel& level : levels_) allocate(level);
  const std::size_t n = levels_.back().n;
  if (n <= kMaxDense) {
    dense_.setZero(Eigen::Index(3 * n), Eigen::Index(3 * n));
    ldlt_ = Eigen::LDLT<Eigen::MatrixXd>(Eigen::Index(3 * n));
    rhs_.setZero(Eigen::Index(3 * n));
  }
}

void CoarseHierarchy::zero_first() {
  std::fill(first().diag.begin(), first().diag.end(), 0.0);
  std::fill(first().edge_block.begin(), first().edge_block.end(), 0.0);
}

void CoarseHierarchy::finish_refresh(int threads) {
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    CoarseLevel& level = levels_[l];
    for (std::size_t v = 0; v < level.n; ++v)
      if (!level.live[v]) {  // only pinned vertices below: decoupled, solved as x = b = 0
        double* d = &level.diag[6 * v];
        d[0] = d[3] = d[5] = 1.0, d[1] = d[2] = d[4] = 0.0;
      }
    for_blocks(level.n, level_threads(level, threads), [&](std::size_t b, std::size_t e) {
      for (std::size_t v = b; v < e; ++v) {
        double block[6];
        std::copy_n(&level.diag[6 * v], 6, block);
        for (int k = level.adj_start[v]; k < level.adj_start[v + 1]; ++k)
          for (int c = 0; c < 6; ++c)
            block[c] +=
                level.edge_block[6 * std::size_t(level.adj_edge[std::size_t(k)]) + std::size_t(c)];
        invert(block, &level.inv[6 * v]);
      }
    });
    if (l + 1 == levels_.size()) break;
    CoarseLevel& next = levels_[l + 1];
    std::fill(next.diag.begin(), next.diag.end(), 0.0);
    std::fill(next.edge_block.begin(), next.edge_block.end(), 0.0);
    for (std::size_t v = 0; v < level.n; ++v)
      if (level.live[v])
        for (int c = 0; c < 6; ++c)
          next.diag[6 * std::size_t(level.to_coarse[v]) + std::size_t(c)] +=
              level.diag[6 * v + std::size_t(c)];
    for (std::size_t e = 0; e < level.edges.size(); ++e) {
      const int t = level.edge_target[e];
      if (t < 0) continue;
      for (int c = 0; c < 6; ++c)
        next.edge_block[6 * std::size_t(t) + std::size_t(c)] +=
            level.edge_block[6 * e + std::size_t(c)];
    }
  }
  factorise_coarsest();
}

void CoarseHierarchy::factorise_coarsest() {
  const CoarseLevel& level = levels_.back();
  if (dense_.rows() == 0) return;
  dense_.setZero();
  auto add = [&](std::size_t i, std::size_t j, const double* m, double sign) {
    const int at[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        dense_(Eigen::Index(3 * i + r), Eigen::Index(3 * j + c)) += sign * m[at[r][c]];
  };
  for (std::size_t v = 0; v < level.n; ++v) add(v, v, &level.diag[6 * v], 1.0);
  for (std::size_t e = 0; e < level.edges.size(); ++e) {
    const auto i = std::size_t(level.edges[e][0]), j = std::size_t(level.edges[e][1]);
    const double* m = &level.edge_block[6 * e];
    add(i, i, m, 1.0), add(j, j, m, 1.0), add(i, j, m, -1.0), add(j, i, m, -1.0);
  }
  ldlt_.compute(dense_);
}

void apply_level(const CoarseLevel& level, const std::vector<double>& x, std::vector<double>& y,
                 int threads) {
  for_blocks(level.n, level_threads(level, threads), [&](std::size_t b, std::size_t e) {
    for (std::size_t v = b; v < e; ++v) {
      double* out = &y[3 * v];
      multiply(&level.diag[6 * v], &x[3 * v], out);
      for (int k = level.adj_start[v]; k < level.adj_start[v + 1]; ++k) {
        const auto w = std::size_t(level.adj_vertex[std::size_t(k)]);
        const double d[3] = {x[3 * v] - x[3 * w], x[3 * v + 1] - x[3 * w + 1],
                             x[3 * v + 2] - x[3 * w + 2]};
        double add[3];
        multiply(&level.edge_block[6 * std::size_t(level.adj_edge[std::size_t(k)])], d, add);
        out[0] += add[0], out[1] += add[1], out[2] += add[2];
      }
    }
  });
}

// One V(1,1)-cycle on level l: x from b (a pre-smoothing from zero, the coarse correction, a
// post-smoothing; the same damped block Jacobi both ways, so the cycle is symmetric and PCG may
// use it).
void CoarseHierarchy::cycle(std::size_t l, int threads) {
  CoarseLevel& level = levels_[l];
  const int t = level_threads(level, threads);
  if (l + 1 == levels_.size()) {
    if (dense_.rows() > 0) {
      rhs_ = Eigen::Map<const Eigen::VectorXd>(level.b.data(), Eigen::Index(level.b.size()));
      Eigen::Map<Eigen::VectorXd>(level.x.data(), Eigen::Index(level.x.size())) = ldlt_.solve(rhs_);
      return;
    }
    std::fill(level.x.begin(), level.x.end(), 0.0);
    for (int s = 0; s < kCoarsestSweeps; ++s) {
      apply_level(level, level.x, level.r, t);
      for (std::size_t v = 0; v < level.n; ++v) {
        double d[3] = {level.b[3 * v] - level.r[3 * v], level.b[3 * v + 1] - level.r[3 * v + 1],
                       level.b[3 * v + 2] - level.r[3 * v + 2]},
               dx[3];
        multiply(&level.inv[6 * v], d, dx);
        for (int a = 0; a < 3; ++a) level.x[3 * v + std::size_t(a)] += kOmega * dx[a];
      }
    }
    return;
  }
  CoarseLevel& next = levels_[l + 1];
  auto smooth = [&](bool from_zero) {  // x += omega D^-1 (b - A x)
    if (!from_zero) apply_level(level, level.x, level.r, t);
    for_blocks(level.n, t, [&](std::size_t b, std::size_t e) {
      for (std::size_t v = b; v < e; ++v) {
        double d[3], dx[3];
        for (int a = 0; a < 3; ++a)
          d[a] =
              level.b[3 * v + std::size_t(a)] - (from_zero ? 0.0 : level.r[3 * v + std::size_t(a)]);
        multiply(&level.inv[6 * v], d, dx);
        for (int a = 0; a < 3; ++a)
          level.x[3 * v + std::size_t(a)] =
              (from_zero ? 0.0 : level.x[3 * v + std::size_t(a)]) + kOmega * dx[a];
      }
    });
  };
  smooth(true);
  apply_level(level, level.x, level.r, t);
  for_blocks(next.n, level_threads(next, threads), [&](std::size_t b, std::size_t e) {
    for (std::size_t c = b; c < e; ++c) {
      double sum[3] = {0.0, 0.0, 0.0};
      for (int k = level.child_start[c]; k < level.child_start[c + 1]; ++k) {
        const auto v = std::size_t(level.child[std::size_t(k)]);
        for (int a = 0; a < 3; ++a)
          sum[a] += level.b[3 * v + std::size_t(a)] - level.r[3 * v + std::size_t(a)];
      }
      for (int a = 0; a < 3; ++a) next.b[3 * c + std::size_t(a)] = sum[a];
    }
  });
  cycle(l + 1, threads);
  for_blocks(level.n, t, [&](std::size_t b, std::size_t e) {
    for (std::size_t v = b; v < e; ++v) {
      const auto c = std::size_t(level.to_coarse[v]);
      for (int a = 0; a < 3; ++a) level.x[3 * v + std::size_t(a)] += next.x[3 * c + std::size_t(a)];
    }
  });
  smooth(false);
}

}  // namespace clothlab
