#include "sim/integrators/newton/multigrid_hierarchy.hpp"

#include <algorithm>

#include "sim/core/parallel.hpp"
#include "sim/core/symmetric3.hpp"

namespace clothlab {
namespace {

// Levels below this many vertices are refreshed on one thread: a parallel region costs more.
constexpr std::size_t kParallelLevel = 8192;
// A level whose edges span at most this many index offsets stores its rows by offset.
constexpr std::size_t kMaxShifts = 16;
// A coarsest level above this many vertices (no coarsening found) is smoothed, not factorised.
constexpr std::size_t kMaxDense = 1500;
constexpr int kCoarsestSweeps = 30;

int level_threads(const CoarseLevel& level, int threads) {
  return level.n >= kParallelLevel ? threads : 1;
}

// fn(begin, end) over the blocks of [0, n), shared among the enclosing region's threads.
template <class Fn>
void team_for(std::size_t n, Fn&& fn) {
  team_blocks(n, [&](std::size_t, std::size_t b, std::size_t e) { fn(b, e); });
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

void allocate(CoarseLevel& level) {
  const std::size_t n = level.n;
  level.edge_block.assign(6 * level.edges.size(), 0.0);
  level.diag.assign(6 * n, 0.0);
  level.diag_by_axis.assign(6 * n, 0.0f);
  level.inv.assign(6 * n, 0.0f);
  for (auto* v : {&level.x, &level.b, &level.r, &level.kb, &level.kc, &level.kv})
    v->assign(3 * n, 0.0f);
  level.partials.assign(3 * block_count(n), 0.0);
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
  // Slots by index offset when the offsets are few (a grid's levels), else by position in the row.
  std::vector<long> shifts;
  for (std::size_t v = 0; v < n; ++v)
    for (auto k = std::size_t(level.adj_start[v]); k < std::size_t(level.adj_start[v + 1]); ++k)
      shifts.push_back(long(level.adj_vertex[k]) - long(v));
  std::sort(shifts.begin(), shifts.end());
  shifts.erase(std::unique(shifts.begin(), shifts.end()), shifts.end());
  level.adj_slot.assign(level.adj_vertex.size(), 0);
  level.shift.clear();
  level.row_vertex.clear();
  if (shifts.size() <= kMaxShifts) {
    level.shift = shifts;
    level.slots = shifts.size();
    for (std::size_t v = 0; v < n; ++v)
      for (auto k = std::size_t(level.adj_start[v]); k < std::size_t(level.adj_start[v + 1]); ++k)
        level.adj_slot[k] = int(
            std::lower_bound(shifts.begin(), shifts.end(), long(level.adj_vertex[k]) - long(v)) -
            shifts.begin());
  } else {
    level.slots = 0;
    for (std::size_t v = 0; v < n; ++v)
      level.slots = std::max(level.slots, std::size_t(level.adj_start[v + 1] - level.adj_start[v]));
    level.row_vertex.assign(level.slots * n, 0);
    for (std::size_t v = 0; v < n; ++v)
      for (std::size_t k = 0; k < level.slots; ++k) {
        const auto at = std::size_t(level.adj_start[v]) + k;
        const bool real = at < std::size_t(level.adj_start[v + 1]);
        level.row_vertex[k * n + v] = real ? level.adj_vertex[at] : int(v);
        if (real) level.adj_slot[at] = int(k);
      }
  }
  level.row_block.assign(6 * level.slots * n, 0.0f);
}

}  // namespace

void group_by(const std::vector<int>& of, std::size_t count, std::vector<int>& start,
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
  group_by(map.of, map.count, map.child_start, map.child);
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
    // One factorisation now sizes the factors' buffers (later ones reuse them, without
    // allocation) and sets their state: a moved-in LDLT(size) leaves its info uninitialised.
    dense_.setIdentity(Eigen::Index(3 * n), Eigen::Index(3 * n));
    ldlt_.compute(dense_);
    rhs_.setZero(Eigen::Index(3 * n));
  }
}

void CoarseHierarchy::finish_refresh(int threads) {
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    CoarseLevel& level = levels_[l];
    for (std::size_t v = 0; v < level.n; ++v)
      if (!level.live[v]) {  // only pinned vertices below: decoupled, solved as x = b = 0
        double* d = &level.diag[6 * v];
        d[0] = d[3] = d[5] = 1.0, d[1] = d[2] = d[4] = 0.0;
      }
    const std::size_t n = level.n;
    for_each_block(n, level_threads(level, threads), [&](std::size_t b, std::size_t e) {
      for (std::size_t v = b; v < e; ++v) {
        double block[6], inverse[6];
        std::copy_n(&level.diag[6 * v], 6, block);
        for (auto c = std::size_t(0); c < 6; ++c)
          level.diag_by_axis[c * n + v] = CoarseReal(block[c]);
        const auto first = std::size_t(level.adj_start[v]);
        for (auto k = first; k < std::size_t(level.adj_start[v + 1]); ++k) {
          const double* edge = &level.edge_block[6 * std::size_t(level.adj_edge[k])];
          for (std::size_t c = 0; c < 6; ++c) {
            level.row_block[(std::size_t(level.adj_slot[k]) * 6 + c) * n + v] = CoarseReal(edge[c]);
            block[c] += edge[c];
          }
        }
        invert(block, inverse);
        for (std::size_t c = 0; c < 6; ++c) level.inv[c * n + v] = CoarseReal(inverse[c]);
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

void apply_level(const CoarseLevel& level, const std::vector<CoarseReal>& x,
                 std::vector<CoarseReal>& y) {
  const std::size_t n = level.n;
  const CoarseReal *x0 = x.data(), *x1 = x0 + n, *x2 = x1 + n;
  CoarseReal *y0 = y.data(), *y1 = y0 + n, *y2 = y1 + n;
  team_for(n, [&](std::size_t b, std::size_t e) {
    const CoarseReal* d = level.diag_by_axis.data();
#pragma omp simd
    for (std::size_t i = b; i < e; ++i) {
      y0[i] = d[i] * x0[i] + d[n + i] * x1[i] + d[2 * n + i] * x2[i];
      y1[i] = d[n + i] * x0[i] + d[3 * n + i] * x1[i] + d[4 * n + i] * x2[i];
      y2[i] = d[2 * n + i] * x0[i] + d[4 * n + i] * x1[i] + d[5 * n + i] * x2[i];
    }
    for (std::size_t k = 0; k < level.slots; ++k) {  // y += B (x_i - x_w), one slot at a time
      const CoarseReal* __restrict m = level.row_block.data() + 6 * k * n;
      if (!level.shift.empty()) {  // w = i + shift, for the i that have a w in the level
        const long s = level.shift[k];
        const auto lo = std::size_t(std::max(long(b), -s)),
                   hi = std::size_t(std::min(long(e), long(n) - s));
#pragma omp simd
        for (std::size_t i = lo; i < hi; ++i) {
          const auto o = std::size_t(long(i) + s);
          const CoarseReal a0 = x0[i] - x0[o], a1 = x1[i] - x1[o], a2 = x2[i] - x2[o];
          y0[i] += m[i] * a0 + m[n + i] * a1 + m[2 * n + i] * a2;
          y1[i] += m[n + i] * a0 + m[3 * n + i] * a1 + m[4 * n + i] * a2;
          y2[i] += m[2 * n + i] * a0 + m[4 * n + i] * a1 + m[5 * n + i] * a2;
        }
        continue;
      }
      const int* __restrict w = level.row_vertex.data() + k * n;
#pragma omp simd
      for (std::size_t i = b; i < e; ++i) {
        const auto o = std::size_t(w[i]);
        const CoarseReal a0 = x0[i] - x0[o], a1 = x1[i] - x1[o], a2 = x2[i] - x2[o];
        y0[i] += m[i] * a0 + m[n + i] * a1 + m[2 * n + i] * a2;
        y1[i] += m[n + i] * a0 + m[3 * n + i] * a1 + m[4 * n + i] * a2;
        y2[i] += m[2 * n + i] * a0 + m[4 * n + i] * a1 + m[5 * n + i] * a2;
      }
    }
  });
}

namespace {

// x = (from_zero ? 0 : x) + omega D^-1 (b - (from_zero ? 0 : r)) on vertices [b, e) (by axis).
void jacobi(CoarseLevel& level, bool from_zero, CoarseReal omega, std::size_t b, std::size_t e) {
  const std::size_t n = level.n;
  const CoarseReal* p = level.inv.data();
  CoarseReal *x0 = level.x.data(), *x1 = x0 + n, *x2 = x1 + n;
  const CoarseReal *b0 = level.b.data(), *b1 = b0 + n, *b2 = b1 + n;
  const CoarseReal *r0 = level.r.data(), *r1 = r0 + n, *r2 = r1 + n;
  const CoarseReal keep = from_zero ? 0.0f : 1.0f;
#pragma omp simd
  for (std::size_t i = b; i < e; ++i) {
    const CoarseReal d0 = b0[i] - keep * r0[i], d1 = b1[i] - keep * r1[i],
                     d2 = b2[i] - keep * r2[i];
    x0[i] = keep * x0[i] + omega * (p[i] * d0 + p[n + i] * d1 + p[2 * n + i] * d2);
    x1[i] = keep * x1[i] + omega * (p[n + i] * d0 + p[3 * n + i] * d1 + p[4 * n + i] * d2);
    x2[i] = keep * x2[i] + omega * (p[2 * n + i] * d0 + p[4 * n + i] * d1 + p[5 * n + i] * d2);
  }
}

// Each block's share of up to three dot products over a level's vectors, then their sums in block
// order, the same on every thread (a barrier before the partials are written again).
template <std::size_t K, class Fn>
std::array<double, K> team_dots(CoarseLevel& level, Fn&& fn) {
  team_for(level.n, [&](std::size_t b, std::size_t e) {
    std::array<double, K> sum{};
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t i = a * level.n + b; i < a * level.n + e; ++i) fn(i, sum);
    std::copy(sum.begin(), sum.end(), &level.partials[K * (b / kBlockSize)]);
  });
  std::array<double, K> total{};
  for (std::size_t k = 0; k < block_count(level.n); ++k)
    for (std::size_t c = 0; c < K; ++c) total[c] += level.partials[K * k + c];
#pragma omp barrier
  return total;
}

// fn(i) for every entry i of a level's vectors (3 n), in the team's blocks.
template <class Fn>
void team_each(const CoarseLevel& level, Fn&& fn) {
  team_for(level.n, [&](std::size_t b, std::size_t e) {
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t i = a * level.n + b; i < a * level.n + e; ++i) fn(i);
  });
}

}  // namespace

// level.x from level.b by at most two steps of flexible CG preconditioned by cycle(l) (Notay &
// Vassilevski 2008, "Recursive Krylov-based multigrid cycles", Numer. Linear Algebra Appl. 15,
// Algorithm 2.1): c1 = B b, x = (c1.b / c1.A c1) c1; if that leaves more than kKrylovThreshold of
// |b|, c2 = B r~ and x is the A-orthogonal combination of c1 and c2 minimising the error's energy.
// Every thread of the team takes the same branches: the dots are summed in block order by each.
void CoarseHierarchy::krylov(std::size_t l) {
  CoarseLevel& L = levels_[l];
  if (l + 1 == levels_.size()) return cycle(l);  // the direct solve
  team_each(L, [&](std::size_t i) { L.kb[i] = L.b[i]; });
  cycle(l);
  apply_level(L, L.x, L.kv);
  const auto [rho1, alpha1] = team_dots<2>(L, [&](std::size_t i, std::array<double, 2>& d) {
    L.kc[i] = L.x[i];
    d[0] += double(L.x[i]) * L.kv[i], d[1] += double(L.x[i]) * L.kb[i];
  });
  if (!(rho1 > 0.0)) return team_each(L, [&](std::size_t i) { L.x[i] = 0.0f; });
  const double a1 = alpha1 / rho1;
  const auto [bb, rr] = team_dots<2>(L, [&](std::size_t i, std::array<double, 2>& d) {
    L.b[i] = CoarseReal(L.kb[i] - a1 * L.kv[i]);
    d[0] += double(L.kb[i]) * L.kb[i], d[1] += double(L.b[i]) * L.b[i];
  });
  if (rr <= kKrylovThreshold * kKrylovThreshold * bb)
    return team_each(L, [&](std::size_t i) { L.x[i] = CoarseReal(a1 * L.kc[i]); });
  cycle(l);  // x = c2 = B r~; then A c2 in r
  apply_level(L, L.x, L.r);
  const auto [gamma, beta, alpha2] = team_dots<3>(L, [&](std::size_t i, std::array<double, 3>& d) {
    d[0] += double(L.x[i]) * L.kv[i], d[1] += double(L.x[i]) * L.r[i],
        d[2] += double(L.x[i]) * L.b[i];
  });
  const double rho2 = beta - gamma * gamma / rho1;
  if (!(rho2 > 0.0)) return team_each(L, [&](std::size_t i) { L.x[i] = CoarseReal(a1 * L.kc[i]); });
  const double w1 = a1 - gamma * alpha2 / (rho1 * rho2), w2 = alpha2 / rho2;
  team_each(L, [&](std::size_t i) { L.x[i] = CoarseReal(w1 * L.kc[i] + w2 * L.x[i]); });
}

// The coarsest level: x from b by the dense factors (interleaved x y z per vertex there; one
// thread, the others wait at the single's barrier), or by damped block-Jacobi sweeps where no
// coarsening was found and the level is too large for them.
void CoarseHierarchy::solve_coarsest() {
  CoarseLevel& level = levels_.back();
  const std::size_t n = level.n;
  if (dense_.rows() > 0) {
#pragma omp single
    {
      for (std::size_t v = 0; v < n; ++v)
        for (std::size_t a = 0; a < 3; ++a) rhs_(Eigen::Index(3 * v + a)) = level.b[a * n + v];
      rhs_ = ldlt_.solve(rhs_);
      for (std::size_t v = 0; v < n; ++v)
        for (std::size_t a = 0; a < 3; ++a)
          level.x[a * n + v] = CoarseReal(rhs_(Eigen::Index(3 * v + a)));
    }
    return;
  }
  team_for(n, [&](std::size_t b, std::size_t e) { jacobi(level, true, CoarseReal(kOmega), b, e); });
  for (int s = 1; s < kCoarsestSweeps; ++s) {
    apply_level(level, level.x, level.r);
    team_for(n,
             [&](std::size_t b, std::size_t e) { jacobi(level, false, CoarseReal(kOmega), b, e); });
  }
}

// One cycle on level l: x from b (a pre-smoothing from zero, the coarse correction by the next
// level's K-cycle, a post-smoothing; the same damped block Jacobi both ways).
void CoarseHierarchy::cycle(std::size_t l) {
  if (l + 1 == levels_.size()) return solve_coarsest();
  CoarseLevel& level = levels_[l];
  CoarseLevel& next = levels_[l + 1];
  const std::size_t n = level.n, nn = next.n;
  team_for(n, [&](std::size_t b, std::size_t e) { jacobi(level, true, CoarseReal(kOmega), b, e); });
  apply_level(level, level.x, level.r);
  team_for(nn, [&](std::size_t b, std::size_t e) {
    for (std::size_t a = 0; a < 3; ++a)  // the residual restricted: each aggregate's sum
      for (std::size_t c = b; c < e; ++c) {
        double sum = 0.0;
        for (int k = level.child_start[c]; k < level.child_start[c + 1]; ++k) {
          const std::size_t v = a * n + std::size_t(level.child[std::size_t(k)]);
          sum += double(level.b[v]) - double(level.r[v]);
        }
        next.b[a * nn + c] = CoarseReal(sum);
      }
  });
  krylov(l + 1);
  team_for(n, [&](std::size_t b, std::size_t e) {
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t v = b; v < e; ++v)
        level.x[a * n + v] += next.x[a * nn + std::size_t(level.to_coarse[v])];
  });
  apply_level(level, level.x, level.r);
  team_for(n,
           [&](std::size_t b, std::size_t e) { jacobi(level, false, CoarseReal(kOmega), b, e); });
}

}  // namespace clothlab
