#include "vis/render/arrow_field.hpp"

#include <algorithm>
#include <cmath>

#include "sim/solver.hpp"
#include "vis/render/quantile.hpp"

namespace clothlab::vis {
namespace {

glm::vec3 at(const std::vector<float>& xyz, int v) {
  const auto i = 3 * static_cast<std::size_t>(v);
  return {xyz[i], xyz[i + 1], xyz[i + 2]};
}

// Indices 0, s, 2s, ... and n - 1 (once).
std::vector<int> sampled(int n, int stride) {
  std::vector<int> out;
  for (int k = 0; k < n; k += stride) out.push_back(k);
  if (n > 0 && out.back() != n - 1) out.push_back(n - 1);
  return out;
}

}  // namespace

int arrow_stride(const SolverState& solver, int stride) {
  if (stride > 0) return stride;
  int s = 1;
  for (const ClothRange& c : solver.cloths()) {
    // A mesh cloth's vertices have no rows: as many arrows as a square grid of its size.
    const int side =
        c.mesh ? static_cast<int>(std::ceil(std::sqrt(double(c.nu)))) : std::max(c.nu, c.nv);
    s = std::max(s, (side + kAutoArrowsPerSide - 1) / kAutoArrowsPerSide);
  }
  return s;
}

ArrowLayout arrow_layout(const SolverState& solver, int stride) {
  ArrowLayout layout;
  layout.stride = arrow_stride(solver, stride);
  std::vector<float> rest(3 * solver.vertex_count());
  solver.copy_rest_positions(rest.data());
  double spacing = 0.0;
  long gaps = 0;
  for (const ClothRange& c : solver.cloths()) {
    if (c.mesh) {
      // Every stride^2-th vertex (as a grid's stride keeps one vertex in stride^2); spacing from
      // the mean length of its triangles' edges, times the stride.
      const int every = layout.stride * layout.stride;
      for (int v = c.offset; v < c.offset + c.nu; v += every) layout.vertices.push_back(v);
      for (const auto& t : solver.triangles()) {
        if (t[0] < c.offset || t[0] >= c.offset + c.nu) continue;
        for (int k = 0; k < 3; ++k, ++gaps)
          spacing += layout.stride * glm::length(at(rest, t[k]) - at(rest, t[(k + 1) % 3]));
      }
      continue;
    }
    const std::vector<int> is = sampled(c.nu, layout.stride), js = sampled(c.nv, layout.stride);
    for (int j : js) {
      for (int i : is) layout.vertices.push_back(c.offset + i + j * c.nu);
      for (std::size_t k = 1; k < is.size(); ++k, ++gaps)
        spacing += glm::length(at(rest, c.offset + is[k] + j * c.nu) -
                               at(rest, c.offset + is[k - 1] + j * c.nu));
    }
    for (int i : is)
      for (std::size_t k = 1; k < js.size(); ++k, ++gaps)
        spacing += glm::length(at(rest, c.offset + i + js[k] * c.nu) -
                               at(rest, c.offset + i + js[k - 1] * c.nu));
  }
  layout.spacing = gaps > 0 ? static_cast<float>(spacing / double(gaps)) : 0.1f;
  return layout;
}

ScalarRange arrow_range(const SolverState& solver, const ArrowLayout& layout,
                        const std::vector<float>& vectors, RangeMode mode, ScalarRange fixed) {
  if (mode == RangeMode::fixed && fixed.max > fixed.min) return fixed;
  std::vector<double> magnitudes;
  magnitudes.reserve(layout.vertices.size());
  for (int v : layout.vertices) {
    if (solver.pinned(v)) continue;
    const double m = glm::length(at(vectors, v));
    if (std::isfinite(m)) magnitudes.push_back(m);
  }
  if (magnitudes.empty()) return {0.0, 1.0};
  // The kArrowRangeQuantile-th magnitude, not the largest: one vertex beside a pin (or a
  // contact) can carry ten times the rest and would shrink every other arrow below a pixel.
  double top = quantile(magnitudes, kArrowRangeQuantile);
  if (!(top > 0.0)) top = *std::max_element(magnitudes.begin(), magnitudes.end());
  // All arrows zero: any non-empty range draws them all at length 0.
  return {0.0, top > 0.0 ? top : 1.0};
}

bool total_near_zero(ScalarRange total, ScalarRange springs) {
  return total.max < kNearRestRatio * springs.max;
}

float arrow_length(float magnitude, ArrowScale scale, float max_length, ScalarRange range) {
  if (!(magnitude > 0.0f) || !std::isfinite(magnitude)) return 0.0f;
  const double top = range.max > 0.0 ? range.max : 1.0;
  double fraction = magnitude / top;
  if (scale == ArrowScale::log) fraction = 1.0 + std::log10(fraction) / 3.0;
  return max_length * static_cast<float>(std::clamp(fraction, 0.0, 1.0));
}

void build_force_arrows(const ArrowLayout& layout, const std::vector<float>& positions,
                        const std::vector<float>& vectors, ArrowScale scale, float max_length,
                        ScalarRange range, std::vector<ArrowInstance>& out) {
  out.resize(layout.vertices.size());
  for (std::size_t k = 0; k < layout.vertices.size(); ++k) {
    const int v = layout.vertices[k];
    const glm::vec3 f = at(vectors, v);
    const float m = glm::length(f);
    const float length = arrow_length(m, scale, max_length, range);
    const glm::vec3 direction = length > 0.0f ? f / m : glm::vec3(0.0f);
    const double u = normalise(m, range);
    const double t = std::isfinite(u) ? std::clamp(u, 0.0, 1.0) : 0.0;
    out[k] = {at(positions, v), direction * length, static_cast<float>(t)};
  }
}

void build_normal_arrows(const ArrowLayout& layout, const std::vector<float>& positions,
                         const std::vector<float>& normals, float length, glm::vec3 eye,
                         std::vector<ArrowInstance>& out) {
  out.resize(layout.vertices.size());
  for (std::size_t k = 0; k < layout.vertices.size(); ++k) {
    const int v = layout.vertices[k];
    const glm::vec3 p = at(positions, v), n = at(normals, v);
    // The side the camera sees, as mode 2 colours it: an arrow on the far side would hide
    // behind the cloth.
    out[k] = {p, (glm::dot(n, eye - p) < 0.0f ? -n : n) * length, 0.0f};
  }
}

}  // namespace clothlab::vis
