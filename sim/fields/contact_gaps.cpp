#include "sim/fields/contact_gaps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <omp.h>

#include "sim/contact/primitive_distance.hpp"
#include "sim/core/parallel.hpp"
#include "sim/solver.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;

std::vector<V3> rest_positions(const SolverState& solver) {
  std::vector<V3> rest(solver.vertex_count());
  for (std::size_t v = 0; v < rest.size(); ++v) {
    const Vec3d p = solver.rest_position(int(v));
    rest[v] = {p[0], p[1], p[2]};
  }
  return rest;
}

// The cloth of each triangle (of its first vertex).
std::vector<int> triangle_cloths(const SolverState& solver) {
  const std::vector<std::int32_t> vertex_cloth =
      vertex_cloths(solver.cloths(), solver.vertex_count());
  std::vector<int> out;
  for (const auto& t : solver.triangles()) out.push_back(vertex_cloth[std::size_t(t[0])]);
  return out;
}

// The largest and the least distance between a point of box a and a point of box b.
double farthest(const Box3& a, const Box3& b) {
  return (a.hi - b.lo).cwiseAbs().cwiseMax((b.hi - a.lo).cwiseAbs()).norm();
}
double nearest(const Box3& a, const Box3& b) {
  return (a.lo - b.hi).cwiseMax(b.lo - a.hi).cwiseMax(0.0).norm();
}

// Skips the nodes, and pairs of nodes, of one cloth whose every point lay within `range` of every
// other at rest: none of their pairs counts.
struct NearAtRest {
  const std::vector<Box3>& rest;
  const std::vector<int>& cloth;  // per node: its cloth, or -1 for several
  double range;
  bool self(int n) const {
    const Box3& b = rest[std::size_t(n)];
    return cloth[std::size_t(n)] >= 0 && (b.hi - b.lo).norm() < range;
  }
  bool pair(int a, int b) const {
    return cloth[std::size_t(a)] >= 0 && cloth[std::size_t(a)] == cloth[std::size_t(b)] &&
           farthest(rest[std::size_t(a)], rest[std::size_t(b)]) < range;
  }
};

}  // namespace

ContactGaps::ContactGaps(const SolverState& solver)
    : x_(rest_positions(solver)),
      crossings_(solver.triangles(), x_),
      triangle_cloth_(triangle_cloths(solver)),
      bvh_(triangle_centroids(solver.triangles(), x_), triangle_cloth_),
      tasks_(bvh_.tasks(kTaskDepth)) {
  fill_triangle_boxes(solver.triangles(), x_, 0.0, bvh_.leaf_boxes());
  rest_triangle_boxes_ = bvh_.leaf_boxes();
  bvh_.refit();
  rest_boxes_.resize(bvh_.node_count());
  node_cloth_.resize(bvh_.node_count());
  for (std::size_t n = 0; n < bvh_.node_count(); ++n) {
    rest_boxes_[n] = bvh_.node_box(int(n));
    const int* first = bvh_.triangles_begin(int(n));
    const int cloth = triangle_cloth_[std::size_t(*first)];
    const bool one = std::all_of(first, bvh_.triangles_end(int(n)),
                                 [&](int t) { return triangle_cloth_[std::size_t(t)] == cloth; });
    node_cloth_[n] = one ? cloth : -1;
  }
}

void ContactGaps::per_vertex(const std::vector<float>& xyz, double range, int threads,
                             std::vector<float>& out) {
  for (std::size_t v = 0; v < x_.size(); ++v) x_[v] = {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
  const std::size_t teams = std::size_t(std::max(1, threads));
  if (nearest_.size() < teams) nearest_.resize(teams);
  for (std::size_t k = 0; k < teams; ++k) nearest_[k].assign(x_.size(), float(range));
  nearest_pairs(range, int(teams));
  out.resize(x_.size());
  for (std::size_t v = 0; v < x_.size(); ++v) {
    out[v] = nearest_[0][v];
    for (std::size_t k = 1; k < teams; ++k) out[v] = std::min(out[v], nearest_[k][v]);
  }
  crossings_.count(x_, &crossing_);
  const SurfaceFeatures& f = crossings_.features();
  constexpr float kCrossed = std::numeric_limits<float>::quiet_NaN();
  for (const Crossing& c : crossing_) {
    for (int v : f.edges[std::size_t(c.edge)]) out[std::size_t(v)] = kCrossed;
    for (int v : f.triangles[std::size_t(c.triangle)]) out[std::size_t(v)] = kCrossed;
  }
}

// The tree's pieces run on `threads` threads, each thread taking the least distance into its own
// array (the least of them is the same for any thread count).
void ContactGaps::nearest_pairs(double range, int threads) {
  const SurfaceFeatures& f = crossings_.features();
  // Two primitives nearer than `range` lie in triangles whose boxes, grown by half of it, meet.
  fill_triangle_boxes(f.triangles, x_, 0.5 * range, bvh_.leaf_boxes());
  bvh_.refit();
  const double range2 = range * range;
  const NearAtRest cull{rest_boxes_, node_cloth_, range};
  for_each_index(int(tasks_.size()), threads, [&](int task) {
    std::vector<float>& out = nearest_[std::size_t(omp_get_thread_num())];
    const auto near = [&](double now2, std::initializer_list<int> vertices) {
      if (now2 >= range2) return;
      const float d = float(std::sqrt(now2));
      for (int v : vertices) out[std::size_t(v)] = std::min(out[std::size_t(v)], d);
    };
    const auto vertices_against = [&](int owner, int other) {
      const std::array<int, 3>& t = f.triangles[std::size_t(other)];
      for (int k = 0; k < 3; ++k) {
        if (!(f.owned_vertices[std::size_t(owner)] & (1u << k))) continue;
        const int v = f.triangles[std::size_t(owner)][std::size_t(k)];
        if (shares_vertex(t, v)) continue;
        near(point_triangle_dist2(x_[std::size_t(v)], x_[std::size_t(t[0])], x_[std::size_t(t[1])],
                                  x_[std::size_t(t[2])]),
             {v, t[0], t[1], t[2]});
      }
    };
    const auto edges_against = [&](int ta, int tb) {
      for (int i = 0; i < 3; ++i) {
        if (!(f.owned_edges[std::size_t(ta)] & (1u << i))) continue;
        const std::array<int, 2>& e = f.edges[std::size_t(f.triangle_edges[std::size_t(ta)][i])];
        for (int j = 0; j < 3; ++j) {
          if (!(f.owned_edges[std::size_t(tb)] & (1u << j))) continue;
          const std::array<int, 2>& g = f.edges[std::size_t(f.triangle_edges[std::size_t(tb)][j])];
          if (shares_vertex(e, g)) continue;
          near(edge_edge_dist2(x_[std::size_t(e[0])], x_[std::size_t(e[1])], x_[std::size_t(g[0])],
                               x_[std::size_t(g[1])]),
               {e[0], e[1], g[0], g[1]});
        }
      }
    };
    bvh_.run(tasks_[std::size_t(task)], cull, [&](int ta, int tb) {
      if (triangle_cloth_[std::size_t(ta)] == triangle_cloth_[std::size_t(tb)] &&
          nearest(rest_triangle_boxes_[std::size_t(ta)], rest_triangle_boxes_[std::size_t(tb)]) <
              range)
        return true;  // neighbours in the cloth
      vertices_against(ta, tb);
      vertices_against(tb, ta);
      edges_against(ta, tb);
      return true;
    });
  });
}

}  // namespace clothlab
