#include "vis/textures/cloth_tangents.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace clothlab {
namespace {

struct V3 {
  double x, y, z;
};

V3 operator-(V3 a, V3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V3 operator*(double s, V3 a) {
  return {s * a.x, s * a.y, s * a.z};
}
double dot(V3 a, V3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
V3 cross(V3 a, V3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

V3 load(const float* p, std::size_t v) {
  return {p[3 * v], p[3 * v + 1], p[3 * v + 2]};
}

// Difference along one grid direction at index k of count vertices (stride apart): central
// inside, one-sided at the ends; scaled to per-UV-unit (the scale does not change directions).
V3 difference(const float* positions, std::size_t base, std::size_t stride, int k, int count) {
  if (count < 2) return {0.0, 0.0, 0.0};
  const int lo = k > 0 ? k - 1 : 0, hi = k + 1 < count ? k + 1 : count - 1;
  const V3 d = load(positions, base + std::size_t(hi) * stride) -
               load(positions, base + std::size_t(lo) * stride);
  return (double(count - 1) / double(hi - lo)) * d;
}

// The same along a closed ring of count vertices: central everywhere, across the seam too.
V3 ring_difference(const float* positions, std::size_t base, int k, int count) {
  if (count < 3) return {0.0, 0.0, 0.0};
  const int lo = k > 0 ? k - 1 : count - 1, hi = k + 1 < count ? k + 1 : 0;
  const V3 d = load(positions, base + std::size_t(hi)) - load(positions, base + std::size_t(lo));
  return (0.5 * double(count)) * d;
}

// The part of a orthogonal to unit n, normalised; false when it is (relatively) negligible.
bool orthogonal_unit(V3 a, V3 n, V3& out) {
  const V3 t = a - dot(n, a) * n;
  const double len2 = dot(t, t), a2 = dot(a, a);
  if (!(len2 > 1e-12 * a2) || !(len2 > 1e-300)) return false;
  out = (1.0 / std::sqrt(len2)) * t;
  return true;
}

// A unit vector orthogonal to unit n, a continuous function of n except across n.z = 0 (Duff,
// Burgess, Christensen, Hery, Kensler, Liani and Villemin, JCGT 6(1), 2017).
V3 any_orthogonal(V3 n) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  return {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

// T and w (see the header) at a vertex with normal n (any length) and surface derivatives.
void write_frame(V3 n, V3 dpdu, V3 dpdv, float* out) {
  const double n_len = std::sqrt(dot(n, n));
  if (!(n_len > 0.0) || !std::isfinite(n_len)) {
    out[0] = 1.0f, out[1] = 0.0f, out[2] = 0.0f, out[3] = 1.0f;
    return;
  }
  n = (1.0 / n_len) * n;
  V3 t;
  if (!orthogonal_unit(dpdu, n, t) && !orthogonal_unit(cross(dpdv, n), n, t)) t = any_orthogonal(n);
  out[0] = float(t.x);
  out[1] = float(t.y);
  out[2] = float(t.z);
  out[3] = dot(cross(dpdu, dpdv), n) < 0.0 ? -1.0f : 1.0f;
}

}  // namespace

void compute_grid_tangent_row(int nu, int nv, int j, const float* positions, const float* normals,
                              float* tangents, bool wrap_u) {
  if (nu < 1 || nv < 1 || j < 0 || j >= nv) return;
  const std::size_t row = std::size_t(j) * std::size_t(nu);
  for (int i = 0; i < nu; ++i) {
    const std::size_t v = row + std::size_t(i);
    const V3 dpdu =
        wrap_u ? ring_difference(positions, row, i, nu) : difference(positions, row, 1, i, nu);
    const V3 dpdv = difference(positions, std::size_t(i), std::size_t(nu), j, nv);
    write_frame(load(normals, v), dpdu, dpdv, tangents + 4 * v);
  }
}

void compute_grid_tangents(int nu, int nv, const float* positions, const float* normals,
                           float* tangents, bool wrap_u) {
  if (nu < 1 || nv < 1) return;
  for (int j = 0; j < nv; ++j)
    compute_grid_tangent_row(nu, nv, j, positions, normals, tangents, wrap_u);
}

void compute_mesh_tangents(int first, int last, const std::vector<std::array<int, 3>>& triangles,
                           const float* positions, const float* normals, const float* uvs,
                           float* tangents, std::vector<float>& scratch) {
  if (last <= first) return;
  const auto count = static_cast<std::size_t>(last - first);
  if (scratch.size() < 6 * count) scratch.resize(6 * count);
  std::fill_n(scratch.begin(), 6 * count, 0.0f);
  for (const auto& t : triangles) {
    if (t[0] < first || t[0] >= last) continue;
    const auto a = std::size_t(t[0]), b = std::size_t(t[1]), c = std::size_t(t[2]);
    const V3 e1 = load(positions, b) - load(positions, a),
             e2 = load(positions, c) - load(positions, a);
    const double du1 = uvs[2 * b] - uvs[2 * a], dv1 = uvs[2 * b + 1] - uvs[2 * a + 1];
    const double du2 = uvs[2 * c] - uvs[2 * a], dv2 = uvs[2 * c + 1] - uvs[2 * a + 1];
    const double det = du1 * dv2 - du2 * dv1;
    if (det == 0.0) continue;  // no UV area: no direction to give
    // [dP/du dP/dv] = [e1 e2] [du1 du2; dv1 dv2]^-1, weighted by the triangle's UV area.
    const double sign = det > 0.0 ? 1.0 : -1.0;
    const V3 dpdu = sign * ((dv2)*e1 - (dv1)*e2), dpdv = sign * ((du1)*e2 - (du2)*e1);
    for (std::size_t v : {a, b, c}) {
      float* acc = scratch.data() + 6 * (v - std::size_t(first));
      acc[0] += float(dpdu.x), acc[1] += float(dpdu.y), acc[2] += float(dpdu.z);
      acc[3] += float(dpdv.x), acc[4] += float(dpdv.y), acc[5] += float(dpdv.z);
    }
  }
  for (std::size_t k = 0; k < count; ++k) {
    const float* acc = scratch.data() + 6 * k;
    const std::size_t v = std::size_t(first) + k;
    write_frame(load(normals, v), {acc[0], acc[1], acc[2]}, {acc[3], acc[4], acc[5]},
                tangents + 4 * v);
  }
}

}  // namespace clothlab
