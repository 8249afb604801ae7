#include "vis/render/cloth_detail.hpp"

#include <algorithm>
#include <cmath>

namespace clothlab::vis {
namespace {

bool coarsened(const ClothRange& c) {
  return !c.mesh && !c.wrap_u && c.nu > 1 && c.nv > 1;
}

// The largest power-of-two stride that leaves cloth c kDetailMinCells cells a side.
int stride_limit(const ClothRange& c) {
  const int cells = std::min(c.nu, c.nv) - 1;
  int s = 1;
  while (cells / (2 * s) >= kDetailMinCells) s *= 2;
  return s;
}

double rest_spacing(const ClothLayout& l, std::size_t a, std::size_t b) {
  const float* rest = l.fixed.data() + 2 * l.render_vertices();
  double s = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    const double d = double(rest[3 * a + k]) - double(rest[3 * b + k]);
    s += d * d;
  }
  return std::sqrt(s);
}

// Cloth c's quads between the kept rows and columns, wound as the solver's (grid_cloth.cpp).
void append_grid(const ClothRange& c, int stride, std::vector<std::uint32_t>& out) {
  const std::vector<int> cols = detail_lines(c.nu, stride), rows = detail_lines(c.nv, stride);
  const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(c.offset + j * c.nu + i); };
  for (std::size_t r = 0; r + 1 < rows.size(); ++r)
    for (std::size_t k = 0; k + 1 < cols.size(); ++k) {
      const std::uint32_t a = at(cols[k], rows[r]), b = at(cols[k + 1], rows[r]),
                          d = at(cols[k], rows[r + 1]), e = at(cols[k + 1], rows[r + 1]);
      out.insert(out.end(), {a, b, e, a, e, d});
    }
}

}  // namespace

std::vector<int> detail_lines(int n, int stride) {
  std::vector<int> lines;
  for (int i = 0; i < n - 1; i += stride) lines.push_back(i);
  if (n > 0) lines.push_back(n - 1);
  return lines;
}

ClothDetail make_cloth_detail(const ClothLayout& l) {
  ClothDetail d;
  int top = 1;
  std::vector<char> in_grid(l.render_vertices(), 0);
  for (const ClothRange& c : l.cloths) {
    if (!coarsened(c)) continue;
    top = std::max(top, stride_limit(c));
    const auto o = static_cast<std::size_t>(c.offset);
    d.cell = std::max({d.cell, rest_spacing(l, o, o + 1),
                       rest_spacing(l, o, o + static_cast<std::size_t>(c.nu))});
    std::fill_n(in_grid.begin() + c.offset, std::size_t(c.nu) * std::size_t(c.nv), char(1));
  }
  for (int s = 2; s <= top; s *= 2) {
    DetailLevel level{s, d.indices.size(), 0};
    for (const ClothRange& c : l.cloths)
      if (coarsened(c)) append_grid(c, std::min(s, stride_limit(c)), d.indices);
    for (std::size_t t = 0; t + 2 < l.triangles.size(); t += 3)
      if (!in_grid[l.triangles[t]])
        d.indices.insert(d.indices.end(), l.triangles.begin() + std::ptrdiff_t(t),
                         l.triangles.begin() + std::ptrdiff_t(t + 3));
    level.count = d.indices.size() - level.first;
    d.levels.push_back(level);
  }
  return d;
}

int detail_stride(const ClothDetail& detail, double pixels_per_metre) {
  int stride = 1;
  for (const DetailLevel& level : detail.levels)
    if (level.stride * detail.cell * pixels_per_metre <= kDetailCellPixels) stride = level.stride;
  return stride;
}

std::string detail_note(int stride) {
  if (stride <= 1) return "";
  const bool nd = stride % 10 == 2 && stride % 100 != 12;
  return "every " + std::to_string(stride) + (nd ? "nd" : "th") + " vertex";
}

double pixels_per_metre(glm::vec3 eye, glm::vec3 lo, glm::vec3 hi, float fov_deg, int height) {
  const double d = glm::length(eye - glm::clamp(eye, lo, hi));
  const double half = std::tan(0.5 * double(glm::radians(fov_deg)));
  return d > 0.0 && half > 0.0 ? double(height) / (2.0 * d * half) : INFINITY;
}

}  // namespace clothlab::vis
