#include "sim/mesh/sdf_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/mesh/closest_point.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;

// The grid's points: origin + cell (i, j, k), count points along each axis.
struct Frame {
  V3 origin;
  double cell = 0.0;
  std::array<int, 3> count{};
  std::size_t size() const {
    return std::size_t(count[0]) * std::size_t(count[1]) * std::size_t(count[2]);
  }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i + count[0] * (j + count[1] * k));
  }
  V3 point(int i, int j, int k) const { return origin + cell * V3(i, j, k); }
  bool inside(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < count[0] && j < count[1] && k < count[2];
  }
};

// Unsigned distance and the closest triangle (-1: none yet) per grid point.
struct Closest {
  std::vector<double> dist;
  std::vector<int> nearest;
};

double distance_to(const TriangleMesh& mesh, const V3& p, int t) {
  const auto& tri = mesh.triangles[std::size_t(t)];
  return (p - closest_on_triangle(p, mesh.positions[std::size_t(tri[0])],
                                  mesh.positions[std::size_t(tri[1])],
                                  mesh.positions[std::size_t(tri[2])])
                  .point)
      .norm();
}

// Pass 1: exact distances in a band of two cells round each triangle's box.
void exact_band(const TriangleMesh& mesh, const Frame& f, Closest& c) {
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto& tri = mesh.triangles[std::size_t(t)];
    V3 tlo = mesh.positions[std::size_t(tri[0])], thi = tlo;
    for (int v : tri) {
      tlo = tlo.cwiseMin(mesh.positions[std::size_t(v)]);
      thi = thi.cwiseMax(mesh.positions[std::size_t(v)]);
    }
    std::array<int, 3> from{}, to{};
    for (int a = 0; a < 3; ++a) {
      from[a] = std::max(0, static_cast<int>(std::floor((tlo[a] - f.origin[a]) / f.cell)) - 2);
      to[a] = std::min(f.count[a] - 1,
                       static_cast<int>(std::ceil((thi[a] - f.origin[a]) / f.cell)) + 2);
    }
    for (int k = from[2]; k <= to[2]; ++k)
      for (int j = from[1]; j <= to[1]; ++j)
        for (int i = from[0]; i <= to[0]; ++i) {
          const double d = distance_to(mesh, f.point(i, j, k), t);
          const std::size_t g = f.index(i, j, k);
          if (d < c.dist[g]) c.dist[g] = d, c.nearest[g] = t;
        }
  }
}

// Pass 2: the closest triangles carried to every point by sweeps in the eight diagonal
// directions, twice; each point tries the closest triangles of its three upstream neighbours.
void propagate(const TriangleMesh& mesh, const Frame& f, Closest& c) {
  for (int pass = 0; pass < 2; ++pass)
    for (int dir = 0; dir < 8; ++dir) {
      const int si = dir & 1 ? -1 : 1, sj = dir & 2 ? -1 : 1, sk = dir & 4 ? -1 : 1;
      for (int kk = 0; kk < f.count[2]; ++kk)
        for (int jj = 0; jj < f.count[1]; ++jj)
          for (int ii = 0; ii < f.count[0]; ++ii) {
            const int i = si > 0 ? ii : f.count[0] - 1 - ii, j = sj > 0 ? jj : f.count[1] - 1 - jj,
                      k = sk > 0 ? kk : f.count[2] - 1 - kk;
            const std::size_t g = f.index(i, j, k);
            for (const auto& [di, dj, dk] :
                 {std::array<int, 3>{-si, 0, 0}, {0, -sj, 0}, {0, 0, -sk}}) {
              if (!f.inside(i + di, j + dj, k + dk)) continue;
              const int t = c.nearest[f.index(i + di, j + dj, k + dk)];
              if (t < 0 || t == c.nearest[g]) continue;
              const double d = distance_to(mesh, f.point(i, j, k), t);
              if (d < c.dist[g]) c.dist[g] = d, c.nearest[g] = t;
            }
          }
    }
}

// Where the ray along +x through (y, z) crosses the mesh: the sorted x of every crossing.
void ray_hits(const TriangleMesh& mesh, double y, double z, std::vector<double>& hits) {
  hits.clear();
  for (const auto& tri : mesh.triangles) {
    const V3 &a = mesh.positions[std::size_t(tri[0])], &b = mesh.positions[std::size_t(tri[1])],
             &c = mesh.positions[std::size_t(tri[2])];
    // Barycentric coordinates of (y, z) in the triangle projected on the y-z plane.
    const double det = (b.y() - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (b.z() - a.z());
    if (std::abs(det) < 1e-18) continue;  // edge-on to the ray
    const double u = ((y - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (z - a.z())) / det;
    const double v = ((b.y() - a.y()) * (z - a.z()) - (y - a.y()) * (b.z() - a.z())) / det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
    hits.push_back(a.x() + u * (b.x() - a.x()) + v * (c.x() - a.x()));
  }
  std::sort(hits.begin(), hits.end());
}

// Pass 3: signs by ray parity along +x for each (y, z) row, the rays nudged off the grid's
// planes by irrational fractions of a cell so no ray runs through an axis-aligned edge or vertex.
std::vector<double> signed_distances(const TriangleMesh& mesh, const Frame& f,
                                     const std::vector<double>& dist) {
  std::vector<double> phi(f.size(), 0.0);
  std::vector<double> hits;
  for (int k = 0; k < f.count[2]; ++k)
    for (int j = 0; j < f.count[1]; ++j) {
      ray_hits(mesh, f.origin.y() + f.cell * (j + 1.0e-4 * std::sqrt(2.0)),
               f.origin.z() + f.cell * (k + 1.0e-4 * std::sqrt(3.0)), hits);
      std::size_t crossed = 0;
      for (int i = 0; i < f.count[0]; ++i) {
        const double x = f.origin.x() + f.cell * i;
        while (crossed < hits.size() && hits[crossed] < x) ++crossed;
        const std::size_t g = f.index(i, j, k);
        phi[g] = (crossed % 2 == 1 ? -1.0 : 1.0) * dist[g];
      }
    }
  return phi;
}

}  // namespace

SdfGrid::SdfGrid(const TriangleMesh& mesh, int resolution, int margin) {
  V3 lo = V3::Constant(INFINITY), hi = V3::Constant(-INFINITY);
  for (const V3& p : mesh.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  cell_ = std::max((hi - lo).maxCoeff(), 1e-6) / resolution;
  origin_ = lo - V3::Constant(margin * cell_);
  for (int a = 0; a < 3; ++a)
    count_[a] = static_cast<int>(std::ceil((hi[a] - lo[a]) / cell_)) + 2 * margin + 1;
  const Frame frame{origin_, cell_, count_};
  Closest closest{std::vector<double>(frame.size(), INFINITY), std::vector<int>(frame.size(), -1)};
  exact_band(mesh, frame, closest);
  propagate(mesh, frame, closest);
  phi_ = signed_distances(mesh, frame, closest.dist);
}

double SdfGrid::distance(const V3& p, V3* gradient) const {
  // Clamp into the grid; outside it, add the distance to the clamped point.
  const V3 hi_corner = hi();
  const V3 q = p.cwiseMax(origin_).cwiseMin(hi_corner);
  const double outside = (p - q).norm();
  const V3 f = (q - origin_) / cell_;
  std::array<int, 3> c{};
  std::array<double, 3> t{};
  for (int a = 0; a < 3; ++a) {
    c[a] = std::min(static_cast<int>(std::floor(f[a])), count_[a] - 2);
    t[a] = f[a] - c[a];
  }
  const double c000 = at(c[0], c[1], c[2]), c100 = at(c[0] + 1, c[1], c[2]),
               c010 = at(c[0], c[1] + 1, c[2]), c110 = at(c[0] + 1, c[1] + 1, c[2]),
               c001 = at(c[0], c[1], c[2] + 1), c101 = at(c[0] + 1, c[1], c[2] + 1),
               c011 = at(c[0], c[1] + 1, c[2] + 1), c111 = at(c[0] + 1, c[1] + 1, c[2] + 1);
  const double x0 = c000 + t[0] * (c100 - c000), x1 = c010 + t[0] * (c110 - c010),
               x2 = c001 + t[0] * (c101 - c001), x3 = c011 + t[0] * (c111 - c011);
  const double y0 = x0 + t[1] * (x1 - x0), y1 = x2 + t[1] * (x3 - x2);
  const double value = y0 + t[2] * (y1 - y0);
  if (gradient) {
    // The trilinear interpolant's own derivatives; outside the grid, away from the box.
    V3 g;
    g.x() = ((1 - t[1]) * (1 - t[2]) * (c100 - c000) + t[1] * (1 - t[2]) * (c110 - c010) +
             (1 - t[1]) * t[2] * (c101 - c001) + t[1] * t[2] * (c111 - c011));
    g.y() = ((1 - t[2]) * (x1 - x0) + t[2] * (x3 - x2));
    g.z() = (y1 - y0);
    if (outside > 0.0) g += (p - q) / outside * cell_;
    const double len = g.norm();
    *gradient = len > 1e-12 ? V3(g / len) : V3::UnitY();
  }
  return value + outside;
}

}  // namespace clothlab
