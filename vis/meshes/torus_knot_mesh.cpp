// (p, q) torus knot tube. The ring frames come from a rotation-minimising frame computed by the
// double reflection method (W. Wang, B. Juettler, D. Zheng, Y. Liu, "Computation of Rotation
// Minimizing Frames", ACM Transactions on Graphics 27(1), 2008, algorithm 1). After one loop
// such a frame comes back rotated about the tangent by the curve's total torsion-like twist
// angle alpha; rotating ring i by -alpha * i / N closes the tube without a seam twist.
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "vis/meshes/shapes.hpp"

namespace clothlab::vis {
namespace {

// Rotates v (perpendicular to unit axis k) by `angle` about k (Rodrigues, k . v = 0).
glm::dvec3 rotate_perp(const glm::dvec3& v, const glm::dvec3& k, double angle) {
  return v * std::cos(angle) + glm::cross(k, v) * std::sin(angle);
}

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The knot's centre line sampled at n + 1 points (the last repeats the first) with unit
// tangents: on a torus of radii R and R/2, r(t) = R/2 (2 + cos q t) around z.
struct CentreLine {
  std::vector<glm::dvec3> x, t;
};

CentreLine knot_centre_line(int p, int q, double R, int n) {
  CentreLine c{std::vector<glm::dvec3>(std::size_t(n) + 1),
               std::vector<glm::dvec3>(std::size_t(n) + 1)};
  for (int i = 0; i < n; ++i) {
    const double s = kTwoPi * double(i) / double(n);
    const double r = 0.5 * R * (2.0 + std::cos(q * s));
    const double dr = -0.5 * R * q * std::sin(q * s);
    c.x[std::size_t(i)] =
        glm::dvec3(r * std::cos(p * s), r * std::sin(p * s), 0.5 * R * std::sin(q * s));
    c.t[std::size_t(i)] = glm::normalize(glm::dvec3(dr * std::cos(p * s) - r * p * std::sin(p * s),
                                                    dr * std::sin(p * s) + r * p * std::cos(p * s),
                                                    0.5 * R * q * std::cos(q * s)));
  }
  c.x[std::size_t(n)] = c.x[0];
  c.t[std::size_t(n)] = c.t[0];
  return c;
}

// Ring normals r[i] along the centre line: double reflection (reflect (r, t) in the bisector
// plane of x[i], x[i+1], then in the plane that maps the reflected tangent onto t[i+1]), then the
// twist accumulated over the loop spread back over the rings so the tube closes.
std::vector<glm::dvec3> rotation_minimising_normals(const CentreLine& c) {
  const std::size_t n = c.x.size() - 1;
  const auto& x = c.x;
  const auto& t = c.t;
  std::vector<glm::dvec3> r(n + 1);
  // Initial normal: any unit vector perpendicular to t[0].
  const glm::dvec3 a = std::abs(t[0].z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  r[0] = glm::normalize(a - t[0] * glm::dot(a, t[0]));
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 v1 = x[i + 1] - x[i];
    const double c1 = glm::dot(v1, v1);
    const glm::dvec3 rl = r[i] - (2.0 / c1) * glm::dot(v1, r[i]) * v1;
    const glm::dvec3 tl = t[i] - (2.0 / c1) * glm::dot(v1, t[i]) * v1;
    const glm::dvec3 v2 = t[i + 1] - tl;
    const double c2 = glm::dot(v2, v2);
    glm::dvec3 next = c2 > 1e-30 ? rl - (2.0 / c2) * glm::dot(v2, rl) * v2 : rl;
    next -= t[i + 1] * glm::dot(next, t[i + 1]);  // guard against drift
    r[i + 1] = glm::normalize(next);
  }
  // Twist accumulated over the loop: r[n] = rotate(r[0], alpha) about t[0].
  const double alpha = std::atan2(glm::dot(glm::cross(r[0], r[n]), t[0]), glm::dot(r[0], r[n]));
  for (std::size_t i = 0; i < n; ++i)
    r[i] = rotate_perp(r[i], t[i], -alpha * double(i) / double(n));
  r[n] = r[0];  // exactly closed
  return r;
}

// The tube of radius `tube_radius` round the centre line, `sides` around (plus a seam copy).
Mesh tube_round(const CentreLine& c, const std::vector<glm::dvec3>& r, float tube_radius,
                int sides) {
  const int n = static_cast<int>(c.x.size()) - 1;
  Mesh mesh;
  const int ring = sides + 1;
  mesh.positions.reserve(std::size_t(n + 1) * ring);
  for (int i = 0; i <= n; ++i) {
    const auto ui = std::size_t(i);
    const glm::dvec3 b = glm::cross(c.t[ui], r[ui]);
    for (int j = 0; j <= sides; ++j) {
      const double a = kTwoPi * double(j % sides) / double(sides);
      // Around the tube against the right-hand sense about t, so dP/du x dP/dv points outward.
      const glm::dvec3 nrm = glm::normalize(std::cos(a) * r[ui] - std::sin(a) * b);
      mesh.positions.push_back(glm::vec3(c.x[ui] + double(tube_radius) * nrm));
      mesh.normals.push_back(glm::vec3(nrm));
      mesh.uvs.emplace_back(float(i) / float(n), float(j) / float(sides));
    }
  }
  const auto v = [&](int i, int j) { return std::uint32_t(i * ring + j); };
  auto& idx = mesh.indices;
  idx.reserve(std::size_t(n) * sides * 6);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < sides; ++j)
      for (std::uint32_t k :
           {v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j), v(i + 1, j + 1), v(i, j + 1)})
        idx.push_back(k);
  return mesh;
}

}  // namespace

Mesh make_torus_knot(int p, int q, float radius, float tube_radius, int segments, int sides) {
  if (!(radius > 0.0f) || !(tube_radius > 0.0f))
    throw std::invalid_argument("make_torus_knot: radius and tube_radius must be > 0");
  if (p < 1 || q < 1 || std::gcd(p, q) != 1)
    throw std::invalid_argument("make_torus_knot: p and q must be coprime and >= 1");
  if (segments < 3 || sides < 3)
    throw std::invalid_argument("make_torus_knot: need segments >= 3 and sides >= 3");
  const CentreLine line = knot_centre_line(p, q, radius, segments);
  Mesh mesh = tube_round(line, rotation_minimising_normals(line), tube_radius, sides);
  compute_tangents(mesh);
  return mesh;
}

}  // namespace clothlab::vis
