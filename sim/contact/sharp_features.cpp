#include "sim/contact/sharp_features.hpp"

#include <map>
#include <numbers>
#include <utility>

#include "sim/mesh/triangle_mesh.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;

// Points strictly between a and b, at most `spacing` apart (the ends are features of their own),
// and no more than kMaxEdgePoints of them: a box kilometres long against a metre of cloth gets
// them further apart rather than millions of points.
constexpr int kMaxEdgePoints = 4096;
void add_edge_points(SharpFeatures& f, const V3& a, const V3& b, const V3& outward,
                     double spacing) {
  const int gaps = static_cast<int>(
      std::clamp(std::ceil((b - a).norm() / spacing), 1.0, double(kMaxEdgePoints)));
  for (int k = 1; k < gaps; ++k) {
    f.points.push_back(a + (b - a) * (double(k) / gaps));
    f.outward.push_back(outward);
  }
}

// A box of half extents h rounded by r (the Minkowski sum of the box h - r and a ball of r, as
// Collider's distance): its corners and edges on the rounded surface, where the direction
// between the faces meets it.
void box_features(SharpFeatures& f, const V3& h, double r, double spacing) {
  const V3 inner = (h - V3::Constant(r)).cwiseMax(0.0);
  for (int k = 0; k < 8; ++k) {
    const V3 s(k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0);
    const V3 out = s.normalized();
    f.points.push_back(s.cwiseProduct(inner) + r * out);
    f.outward.push_back(out);
  }
  // The four edges along each axis a, at the signs (sb, sc) of the other two.
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < 4; ++k) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      V3 side = V3::Zero();
      side[b] = k & 1 ? 1.0 : -1.0;
      side[c] = k & 2 ? 1.0 : -1.0;
      const V3 out = side.normalized();
      V3 end = side.cwiseProduct(inner) + r * out;
      V3 from = end, to = end;
      from[a] = -inner[a];
      to[a] = inner[a];
      add_edge_points(f, from, to, out, spacing);
    }
}

V3 face_normal(const TriangleMesh& mesh, const std::array<int, 3>& t) {
  const V3 &a = mesh.positions[std::size_t(t[0])], &b = mesh.positions[std::size_t(t[1])],
           &c = mesh.positions[std::size_t(t[2])];
  const V3 n = (b - a).cross(c - a);
  const double len = n.norm();
  return len > 0.0 ? V3(n / len) : V3::Zero();
}

// A closed mesh's creases (two faces at more than kCreaseDegrees) and the vertices on them, each
// vertex's outward direction its angle-weighted normal (Thuermer & Wuethrich 1998), a crease's
// the mean of its two faces' normals.
void mesh_features(SharpFeatures& f, const TriangleMesh& mesh, double spacing) {
  const double crease_cos = std::cos(SharpFeatures::kCreaseDegrees * std::numbers::pi / 180.0);
  const std::size_t nv = mesh.positions.size();
  std::vector<V3> normal(nv, V3::Zero());
  std::vector<char> sharp(nv, 0);
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const V3 n = face_normal(mesh, tri);
    for (int e = 0; e < 3; ++e) {
      const int i = tri[std::size_t(e)], j = tri[std::size_t((e + 1) % 3)],
                k = tri[std::size_t((e + 2) % 3)];
      const V3 u = mesh.positions[std::size_t(j)] - mesh.positions[std::size_t(i)],
               w = mesh.positions[std::size_t(k)] - mesh.positions[std::size_t(i)];
      const double angle = std::atan2(u.cross(w).norm(), u.dot(w));
      normal[std::size_t(i)] += angle * n;
      edge_faces[{std::min(i, j), std::max(i, j)}].push_back(int(t));
    }
  }
  for (const auto& [edge, faces] : edge_faces) {
    if (faces.size() != 2) continue;  // a border or a non-manifold edge has no one dihedral
    const V3 n0 = face_normal(mesh, mesh.triangles[std::size_t(faces[0])]),
             n1 = face_normal(mesh, mesh.triangles[std::size_t(faces[1])]);
    if (n0.dot(n1) >= crease_cos) continue;
    sharp[std::size_t(edge.first)] = sharp[std::size_t(edge.second)] = 1;
    const V3 mean = n0 + n1;
    if (mean.norm() < 1e-9) continue;  // a knife edge folded flat: no outward side
    add_edge_points(f, mesh.positions[std::size_t(edge.first)],
                    mesh.positions[std::size_t(edge.second)], mean.normalized(), spacing);
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (sharp[v] && normal[v].norm() > 1e-9) {
      f.points.push_back(mesh.positions[v]);
      f.outward.push_back(normal[v].normalized());
    }
}

// The near cells: every cell of the grown grid within kNearCells (in each axis) of one that
// holds a point.
void mark_near_cells(SharpFeatures& f) {
  constexpr int pad = SharpFeatures::kNearCells;
  for (int d = 0; d < 3; ++d) f.near_dims[std::size_t(d)] = f.dims[std::size_t(d)] + 2 * pad;
  const auto [nx, ny, nz] = f.near_dims;
  f.near_cells.assign(std::size_t(nx) * std::size_t(ny) * std::size_t(nz), 0);
  for (int k = 0; k < f.dims[2]; ++k)
    for (int j = 0; j < f.dims[1]; ++j)
      for (int i = 0; i < f.dims[0]; ++i) {
        const auto c = std::size_t(i + f.dims[0] * (j + f.dims[1] * k));
        if (f.start[c] == f.start[c + 1]) continue;
        for (int z = k; z <= k + 2 * pad; ++z)
          for (int y = j; y <= j + 2 * pad; ++y)
            for (int x = i; x <= i + 2 * pad; ++x)
              f.near_cells[std::size_t(x + nx * (y + ny * z))] = 1;
      }
}

// The uniform grid over the points: cells of `cell` m, at most 64 along an axis.
void build_grid(SharpFeatures& f, double cell) {
  if (f.points.empty()) return;
  V3 lo = f.points.front(), hi = lo;
  for (const V3& p : f.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  f.cell = std::max({cell, (hi - lo).maxCoeff() / 63.0, 1e-6});
  f.lo = lo;
  f.hi = hi;
  for (int d = 0; d < 3; ++d) f.dims[std::size_t(d)] = int((hi[d] - lo[d]) / f.cell) + 1;
  auto cell_of = [&](const V3& p) {
    std::array<int, 3> c{};
    for (int d = 0; d < 3; ++d)
      c[std::size_t(d)] = std::min(f.dims[std::size_t(d)] - 1, int((p[d] - lo[d]) / f.cell));
    return std::size_t(c[0] + f.dims[0] * (c[1] + f.dims[1] * c[2]));
  };
  // Counting sort of the points by cell.
  f.start.assign(std::size_t(f.dims[0]) * std::size_t(f.dims[1]) * std::size_t(f.dims[2]) + 1, 0);
  for (const V3& p : f.points) ++f.start[cell_of(p) + 1];
  for (std::size_t c = 1; c < f.start.size(); ++c) f.start[c] += f.start[c - 1];
  f.items.assign(f.points.size(), 0);
  std::vector<int> next(f.start.begin(), f.start.end() - 1);
  for (std::size_t i = 0; i < f.points.size(); ++i)
    f.items[std::size_t(next[cell_of(f.points[i])]++)] = int(i);
  mark_near_cells(f);
}

}  // namespace

SharpFeatures sharp_features(const ColliderSpec& spec, double spacing) {
  SharpFeatures f;
  if (spec.kind == ColliderKind::box)
    box_features(f, V3(spec.half_extents[0], spec.half_extents[1], spec.half_extents[2]),
                 spec.rounding, spacing);
  if (spec.kind == ColliderKind::mesh && spec.mesh) mesh_features(f, *spec.mesh, spacing);
  build_grid(f, spacing);
  return f;
}

}  // namespace clothlab
