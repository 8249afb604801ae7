#include "sim/contact/patch_topology.hpp"

#include <algorithm>

namespace clothlab {
namespace {

// Counts and marks over the whole mesh, reset after each node.
struct Scratch {
  std::vector<std::uint8_t> edge_count;   // per edge: how many of the node's triangles have it
  std::vector<std::int32_t> vertex_mark;  // per vertex: the last node that counted it, plus one
  std::vector<std::uint8_t> rim_degree;   // per vertex: rim edges at it
  std::vector<std::int32_t> root;         // per vertex: union-find parent (itself when unused)
};

std::int32_t find(std::vector<std::int32_t>& root, std::int32_t v) {
  while (root[std::size_t(v)] != v) {
    root[std::size_t(v)] = root[std::size_t(root[std::size_t(v)])];  // path halving
    v = root[std::size_t(v)];
  }
  return v;
}

// Whether the triangles [begin, end) form one piece (joined through shared vertices).
bool connected(const int* begin, const int* end, const SurfaceFeatures& f, Scratch& s) {
  for (const int* t = begin; t != end; ++t) {
    const auto& v = f.triangles[std::size_t(*t)];
    for (int k = 1; k < 3; ++k) {
      const std::int32_t a = find(s.root, v[0]), b = find(s.root, v[std::size_t(k)]);
      if (a != b) s.root[std::size_t(std::max(a, b))] = std::min(a, b);
    }
  }
  const std::int32_t first = find(s.root, f.triangles[std::size_t(*begin)][0]);
  bool one = true;
  for (const int* t = begin; t != end; ++t)
    for (int v : f.triangles[std::size_t(*t)]) one = one && find(s.root, v) == first;
  for (const int* t = begin; t != end; ++t)
    for (int v : f.triangles[std::size_t(*t)]) s.root[std::size_t(v)] = v;
  return one;
}

struct NodeShape {
  bool manifold =
      true;        // no edge borders more than two triangles; two rim edges at each rim vertex
  long euler = 0;  // V - E + F
  std::vector<std::array<std::int32_t, 2>> rim;
};

NodeShape node_shape(const int* begin, const int* end, int node, const SurfaceFeatures& f,
                     Scratch& s) {
  NodeShape out;
  long vertices = 0, edges = 0;
  for (const int* t = begin; t != end; ++t)
    for (int k = 0; k < 3; ++k) {
      const auto v = std::size_t(f.triangles[std::size_t(*t)][std::size_t(k)]);
      if (s.vertex_mark[v] != node + 1) {
        s.vertex_mark[v] = node + 1;
        ++vertices;
      }
      std::uint8_t& c =
          s.edge_count[std::size_t(f.triangle_edges[std::size_t(*t)][std::size_t(k)])];
      if (c == 0) ++edges;
      if (c < 3) ++c;
    }
  for (const int* t = begin; t != end; ++t)
    for (int k = 0; k < 3; ++k) {
      const auto e = std::size_t(f.triangle_edges[std::size_t(*t)][std::size_t(k)]);
      if (s.edge_count[e] > 2) out.manifold = false;
      if (s.edge_count[e] != 1) continue;
      const std::array<int, 2>& ab = f.edges[e];
      out.rim.push_back({ab[0], ab[1]});
      ++s.rim_degree[std::size_t(ab[0])];
      ++s.rim_degree[std::size_t(ab[1])];
    }
  for (const auto& ab : out.rim)
    for (std::int32_t v : ab) {
      if (s.rim_degree[std::size_t(v)] != 2) out.manifold = false;
    }
  for (const auto& ab : out.rim)
    s.rim_degree[std::size_t(ab[0])] = s.rim_degree[std::size_t(ab[1])] = 0;
  for (const int* t = begin; t != end; ++t)
    for (int k = 0; k < 3; ++k)
      s.edge_count[std::size_t(f.triangle_edges[std::size_t(*t)][std::size_t(k)])] = 0;
  out.euler = vertices - edges + long(end - begin);
  return out;
}

}  // namespace

PatchTopology patch_topology(const TriangleBvh& bvh, const SurfaceFeatures& f,
                             std::size_t vertex_count) {
  const std::size_t nodes = bvh.node_count();
  PatchTopology out;
  out.disk.assign(nodes, 0);
  Scratch s{std::vector<std::uint8_t>(f.edges.size(), 0),
            std::vector<std::int32_t>(vertex_count, 0), std::vector<std::uint8_t>(vertex_count, 0),
            std::vector<std::int32_t>(vertex_count)};
  for (std::size_t v = 0; v < vertex_count; ++v) s.root[v] = std::int32_t(v);
  std::vector<std::vector<std::array<std::int32_t, 2>>> rims(nodes);
  for (std::size_t k = 0; k < nodes; ++k) {
    const int n = int(k);
    if (!connected(bvh.triangles_begin(n), bvh.triangles_end(n), f, s)) continue;
    NodeShape shape = node_shape(bvh.triangles_begin(n), bvh.triangles_end(n), n, f, s);
    if (!shape.manifold || shape.euler != 1 || shape.rim.empty()) continue;
    out.disk[k] = 1;
    rims[k] = std::move(shape.rim);
  }
  out.rim_begin.assign(nodes + 1, 0);
  for (std::size_t k = 0; k < nodes; ++k)
    out.rim_begin[k + 1] = out.rim_begin[k] + std::int32_t(rims[k].size());
  out.rim.reserve(std::size_t(out.rim_begin.back()));
  for (const auto& rim : rims) out.rim.insert(out.rim.end(), rim.begin(), rim.end());
  return out;
}

}  // namespace clothlab
