// Procedural scenery meshes (vis/meshes): watertight, outward-facing, analytic volumes, unit
// outward normals, no degenerate triangles, orthonormal tangents.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "vis/meshes/mesh.hpp"
#include "vis/meshes/shapes.hpp"

namespace clothlab::vis {
namespace {

// Welded vertex ids: vertices closer than `eps` share an id (union-find over a sweep in x).
std::vector<std::uint32_t> weld(const Mesh& mesh, float eps = 1e-6f) {
  const std::size_t n = mesh.positions.size();
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&](std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return mesh.positions[a].x < mesh.positions[b].x;
  });
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      const glm::vec3& pa = mesh.positions[order[a]];
      const glm::vec3& pb = mesh.positions[order[b]];
      if (pb.x - pa.x >= eps) break;
      if (glm::distance(pa, pb) < eps) parent[find(order[a])] = find(order[b]);
    }
  }
  std::vector<std::uint32_t> id(n);
  for (std::size_t i = 0; i < n; ++i) id[i] = find(std::uint32_t(i));
  return id;
}

// Every undirected (welded) edge is used by exactly two triangles, once in each direction
// (closed, consistently oriented 2-manifold edges). Returns the number of boundary edges
// (used once) and fails on anything else.
int check_edges(const Mesh& mesh, bool expect_closed) {
  const auto id = weld(mesh);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = id[mesh.indices[k + e]], b = id[mesh.indices[k + (e + 1) % 3]];
      EXPECT_NE(a, b) << "triangle " << k / 3 << " has a collapsed edge";
      ++directed[{a, b}];
    }
  }
  int boundary = 0, bad = 0;
  for (const auto& [edge, count] : directed) {
    const auto rev = directed.find({edge.second, edge.first});
    const int back = rev == directed.end() ? 0 : rev->second;
    if (count == 1 && back == 1) continue;
    if (count == 1 && back == 0) {
      ++boundary;
      continue;
    }
    ++bad;
  }
  EXPECT_EQ(bad, 0) << "non-manifold or inconsistently oriented edges";
  if (expect_closed) {
    EXPECT_EQ(boundary, 0) << "open edges";
  }
  return boundary;
}

// Shared per-vertex checks: array sizes, unit normals pointing to the side the triangle faces,
// no degenerate triangles, unit tangents orthogonal to the normals with |w| = 1.
void check_attributes(const Mesh& mesh, double min_area) {
  const std::size_t n = mesh.positions.size();
  ASSERT_GT(n, 0u);
  ASSERT_EQ(mesh.normals.size(), n);
  ASSERT_EQ(mesh.uvs.size(), n);
  ASSERT_EQ(mesh.tangents.size(), n);
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
  for (std::uint32_t i : mesh.indices) ASSERT_LT(i, n);
  double worst_normal = 0.0, worst_tangent_dot = 0.0, worst_tangent_len = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    worst_normal = std::max(worst_normal, std::abs(double(glm::length(mesh.normals[i])) - 1.0));
    const glm::vec3 t(mesh.tangents[i]);
    worst_tangent_len = std::max(worst_tangent_len, std::abs(double(glm::length(t)) - 1.0));
    worst_tangent_dot = std::max(worst_tangent_dot, std::abs(double(glm::dot(t, mesh.normals[i]))));
    EXPECT_EQ(std::abs(mesh.tangents[i].w), 1.0f) << "vertex " << i;
    EXPECT_TRUE(std::isfinite(mesh.uvs[i].x) && std::isfinite(mesh.uvs[i].y));
  }
  EXPECT_LT(worst_normal, 1e-5);
  EXPECT_LT(worst_tangent_len, 1e-5);
  EXPECT_LT(worst_tangent_dot, 1e-5);
  double smallest_area = 1e300, smallest_dot = 1e300;
  for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[k]]), b(mesh.positions[mesh.indices[k + 1]]),
        c(mesh.positions[mesh.indices[k + 2]]);
    const glm::dvec3 cr = glm::cross(b - a, c - a);
    const double area = 0.5 * glm::length(cr);
    smallest_area = std::min(smallest_area, area);
    if (area <= 0.0) continue;
    const glm::dvec3 fn = cr / (2.0 * area);
    for (int e = 0; e < 3; ++e)
      smallest_dot =
          std::min(smallest_dot, glm::dot(fn, glm::dvec3(mesh.normals[mesh.indices[k + e]])));
  }
  EXPECT_GT(smallest_area, min_area) << "degenerate triangle";
  EXPECT_GT(smallest_dot, 0.0) << "a vertex normal points away from its triangle's face";
  std::printf("  smallest area %.3g, smallest dot(vertex normal, face normal) %.4f\n",
              smallest_area, smallest_dot);
}

// Length of the torus knot centre line (as documented in shapes.hpp), fine polyline.
double torus_knot_length(int p, int q, double radius) {
  const int n = 200000;
  double len = 0.0;
  glm::dvec3 prev;
  for (int i = 0; i <= n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    const double r = 0.5 * radius * (2.0 + std::cos(q * t));
    const glm::dvec3 x(r * std::cos(p * t), r * std::sin(p * t), 0.5 * radius * std::sin(q * t));
    if (i > 0) len += glm::distance(prev, x);
    prev = x;
  }
  return len;
}

TEST(MeshesTest, SphereIsClosedOutwardAndHasTheRightVolume) {
  const float r = 1.5f;
  const Mesh m = make_uv_sphere(r, 64, 32);
  check_attributes(m, 1e-6);
  check_edges(m, true);
  const double v = signed_volume(m), exact = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  std::printf("sphere 64x32: volume %.6f, analytic %.6f, rel error %.4f%%\n", v, exact,
              100.0 * (v - exact) / exact);
  EXPECT_GT(v, 0.0);
  EXPECT_NEAR(v / exact, 1.0, 0.01);
  // Normals are radial.
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    EXPECT_NEAR(glm::dot(m.normals[i], m.positions[i] / r), 1.0f, 1e-5f);
  const Bounds b = mesh_bounds(m);
  EXPECT_NEAR(b.max.y, r, 1e-6f);
  EXPECT_NEAR(b.min.y, -r, 1e-6f);
  // Coarsest allowed sphere is still closed.
  const Mesh small = make_uv_sphere(1.0f, 3, 2);
  check_attributes(small, 1e-3);
  check_edges(small, true);
  EXPECT_GT(signed_volume(small), 0.0);
}

TEST(MeshesTest, SphereUvsAndTangentsFollowLongitudeAndLatitude) {
  const Mesh m = make_uv_sphere(1.0f, 32, 16);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_GE(m.uvs[i].x, 0.0f);
    EXPECT_LE(m.uvs[i].x, 1.0f);
    EXPECT_NEAR(m.uvs[i].y,
                1.0f - std::acos(std::clamp(m.positions[i].y, -1.0f, 1.0f)) / std::numbers::pi,
                1e-5);
    // u increases eastwards seen from outside: handedness +1 everywhere.
    EXPECT_EQ(m.tangents[i].w, 1.0f);
    const glm::vec3 p = m.positions[i];
    if (std::hypot(p.x, p.z) > 0.1f) {
      // The tangent runs along the parallel, eastwards: d/dtheta of (cos, -sin) = (-sin, -cos).
      // (Lengyel's per-triangle dP/du of the triangulated quads tilts it slightly.)
      const glm::vec3 east = glm::normalize(glm::vec3(-p.z, 0.0f, p.x)) * -1.0f;
      EXPECT_GT(glm::dot(glm::vec3(m.tangents[i]), east), 0.9999f) << "vertex " << i;
    }
  }
  // Lengyel's tangents agree with the analytic ones up to the tilt of the triangulation.
  Mesh lengyel = m;
  compute_tangents(lengyel);
  double worst = 1.0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    worst =
        std::min(worst, double(glm::dot(glm::vec3(m.tangents[i]), glm::vec3(lengyel.tangents[i]))));
    EXPECT_EQ(lengyel.tangents[i].w, 1.0f);
  }
  std::printf("sphere 32x16: worst cos(analytic, Lengyel tangent) %.5f\n", worst);
  EXPECT_GT(worst, 0.98);
}

TEST(MeshesTest, BoxIsExact) {
  const glm::vec3 h(0.5f, 1.0f, 2.0f);
  const Mesh m = make_box(h);
  EXPECT_EQ(m.positions.size(), 24u);
  EXPECT_EQ(m.triangle_count(), 12u);
  check_attributes(m, 1e-3);
  check_edges(m, true);
  const double v = signed_volume(m), exact = 8.0 * h.x * h.y * h.z;
  std::printf("box: volume %.9f, analytic %.9f\n", v, exact);
  EXPECT_NEAR(v, exact, 1e-9);
  // Flat face normals: every vertex normal equals its face's geometric normal.
  for (std::size_t k = 0; k < m.indices.size(); k += 3) {
    const glm::vec3 a = m.positions[m.indices[k]], b = m.positions[m.indices[k + 1]],
                    c = m.positions[m.indices[k + 2]];
    const glm::vec3 fn = glm::normalize(glm::cross(b - a, c - a));
    for (int e = 0; e < 3; ++e) EXPECT_NEAR(glm::dot(fn, m.normals[m.indices[k + e]]), 1.0f, 1e-6f);
  }
  const Bounds bb = mesh_bounds(m);
  EXPECT_EQ(bb.min, -h);
  EXPECT_EQ(bb.max, h);
}

TEST(MeshesTest, CylinderAlongXIsClosedWithCapsAndOpenWithout) {
  const float r = 0.05f, len = 2.0f;
  const Mesh m = make_cylinder(r, len, 64, true);
  check_attributes(m, 1e-9);
  check_edges(m, true);
  const double v = signed_volume(m), exact = std::numbers::pi * r * r * len;
  std::printf("cylinder 64 slices with caps: volume %.8f, analytic %.8f, rel error %.4f%%\n", v,
              exact, 100.0 * (v - exact) / exact);
  EXPECT_GT(v, 0.0);
  EXPECT_NEAR(v / exact, 1.0, 0.01);
  const Bounds b = mesh_bounds(m);
  EXPECT_FLOAT_EQ(b.min.x, 0.0f);
  EXPECT_FLOAT_EQ(b.max.x, len);
  EXPECT_NEAR(b.max.y, r, 1e-6f);
  // Smooth side normals: perpendicular to the axis, radial.
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3 n = m.normals[i];
    if (std::abs(n.x) < 0.5f) {
      EXPECT_NEAR(n.x, 0.0f, 1e-6f);
      EXPECT_NEAR(glm::dot(n, glm::vec3(0.0f, m.positions[i].y, m.positions[i].z) / r), 1.0f,
                  1e-5f);
    }
  }
  const Mesh open = make_cylinder(r, len, 16, false);
  check_attributes(open, 1e-9);
  EXPECT_EQ(check_edges(open, false), 2 * 16);  // two open rims
}

TEST(MeshesTest, TorusKnotTubeIsClosedAndHasTubeVolume) {
  const int p = 2, q = 3;
  const float radius = 1.0f, tube = 0.1f;
  const Mesh m = make_torus_knot(p, q, radius, tube, 512, 32);
  check_attributes(m, 1e-8);
  check_edges(m, true);
  const double v = signed_volume(m);
  const double curve = torus_knot_length(p, q, radius);
  const double exact = std::numbers::pi * tube * tube * curve;
  std::printf("torus knot (2,3) 512x32: volume %.7f, pi t^2 L %.7f (L = %.5f), rel error %.4f%%\n",
              v, exact, curve, 100.0 * (v - exact) / exact);
  EXPECT_GT(v, 0.0);
  EXPECT_NEAR(v / exact, 1.0, 0.02);
  // The welded edge check above needs the last ring to coincide with the first: the tube
  // closes without a twist. A (3, 7) knot too.
  const Mesh m2 = make_torus_knot(3, 7, 2.0f, 0.08f, 600, 32);
  check_attributes(m2, 1e-8);
  check_edges(m2, true);
  const double v2 = signed_volume(m2);
  const double exact2 = std::numbers::pi * 0.08 * 0.08 * torus_knot_length(3, 7, 2.0);
  std::printf("torus knot (3,7) 600x32: rel volume error %.4f%%\n", 100.0 * (v2 - exact2) / exact2);
  EXPECT_NEAR(v2 / exact2, 1.0, 0.02);
}

TEST(MeshesTest, TorusKnotFrameHasNoTwistJump) {
  // Rotation-minimising frame with the twist spread evenly: the normal of vertex j in ring i
  // turns by about the same small angle from ring to ring, including across the u seam.
  const int segments = 256, sides = 16;
  const Mesh m = make_torus_knot(2, 3, 1.0f, 0.1f, segments, sides);
  const int ring = sides + 1;
  double worst = 0.0, mean = 0.0;
  for (int i = 0; i < segments; ++i) {
    const glm::vec3 a = m.normals[std::size_t(i * ring)];
    const glm::vec3 b = m.normals[std::size_t((i + 1) * ring)];
    const double ang = std::acos(std::clamp(double(glm::dot(a, b)), -1.0, 1.0));
    worst = std::max(worst, ang);
    mean += ang / segments;
  }
  std::printf("torus knot ring-to-ring normal turn: mean %.4f rad, max %.4f rad\n", mean, worst);
  EXPECT_LT(worst, 3.0 * mean + 1e-3);
  // Last ring == first ring exactly (same positions and normals).
  for (int j = 0; j <= sides; ++j) {
    EXPECT_EQ(m.positions[std::size_t(j)], m.positions[std::size_t(segments * ring + j)]);
    EXPECT_EQ(m.normals[std::size_t(j)], m.normals[std::size_t(segments * ring + j)]);
  }
}

TEST(MeshesTest, TransformKeepsMeshOutwardAndTangentsOrthonormal) {
  Mesh m = make_uv_sphere(1.0f, 24, 12);
  transform_mesh(m, glm::mat4(glm::vec4(2, 0, 0, 0), glm::vec4(0, 0.5f, 0, 0),
                              glm::vec4(0, 0, 1, 0), glm::vec4(1, 2, 3, 1)));
  check_attributes(m, 1e-6);
  check_edges(m, true);
  const double scaled = signed_volume(make_uv_sphere(1.0f, 24, 12)) * 2.0 * 0.5;
  EXPECT_NEAR(signed_volume(m), scaled, 1e-4);  // translation-invariant, scaled by det = 1
  // Mirror: still outward after the winding flip.
  Mesh mirrored = make_box(glm::vec3(1.0f));
  transform_mesh(mirrored, glm::mat4(glm::vec4(-1, 0, 0, 0), glm::vec4(0, 1, 0, 0),
                                     glm::vec4(0, 0, 1, 0), glm::vec4(0, 0, 0, 1)));
  check_attributes(mirrored, 1e-3);
  EXPECT_NEAR(signed_volume(mirrored), 8.0, 1e-6);
}

TEST(MeshesTest, ComputeTangentsFollowsUAndHandedness) {
  // A single quad in the xy plane with u along +x, v along +y: T = +x, w = +1; with v along -y
  // the handedness flips.
  Mesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.normals.assign(4, glm::vec3(0, 0, 1));
  quad.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  compute_tangents(quad);
  for (const glm::vec4& t : quad.tangents) {
    EXPECT_NEAR(t.x, 1.0f, 1e-6f);
    EXPECT_EQ(t.w, 1.0f);
  }
  quad.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  compute_tangents(quad);
  for (const glm::vec4& t : quad.tangents) {
    EXPECT_NEAR(t.x, 1.0f, 1e-6f);
    EXPECT_EQ(t.w, -1.0f);
  }
}

TEST(MeshesTest, GeneratorsRejectBadArguments) {
  EXPECT_THROW(make_uv_sphere(0.0f, 8, 8), std::invalid_argument);
  EXPECT_THROW(make_uv_sphere(1.0f, 2, 8), std::invalid_argument);
  EXPECT_THROW(make_box(glm::vec3(1, 0, 1)), std::invalid_argument);
  EXPECT_THROW(make_cylinder(1.0f, -1.0f, 8, true), std::invalid_argument);
  EXPECT_THROW(make_torus_knot(2, 4, 1.0f, 0.1f, 64, 8), std::invalid_argument);
  EXPECT_THROW(make_torus_knot(2, 3, 1.0f, 0.1f, 2, 8), std::invalid_argument);
}

}  // namespace
}  // namespace clothlab::vis
