// Coarser drawings of large grid cloths (issue 54, docs/rendering.md section 9): level k draws
// every grid cloth as the grid of every 2^k-th vertex of each row and column (the last row and
// column always kept, so the outline stays where it is), with the solver's own vertices, normals
// and UVs; tubes and mesh cloths keep their triangles at every level. A renderer that
// rasterises on the CPU pays per triangle and per vertex: a 256 x 256 sheet seen across a room
// puts one or two pixels in each of its 130,000 triangles, and its shadow map as many again.
// The fast render quality draws the coarsest level whose cells still measure at most
// kDetailCellPixels on screen; full quality always draws every triangle. Plain data, no GL.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "vis/render/cloth_layout.hpp"

namespace clothlab::vis {

// The largest a coarse cell may appear (pixels along its side at the cloth's nearest point).
inline constexpr double kDetailCellPixels = 4.0;
// Levels stop where a grid cloth would keep fewer than this many cells along its shorter side.
inline constexpr int kDetailMinCells = 16;

struct DetailLevel {
  int stride = 1;         // every stride-th vertex of a row and of a column
  std::size_t first = 0;  // its first index in ClothDetail::indices
  std::size_t count = 0;  // its indices (3 a triangle)
};

struct ClothDetail {
  std::vector<std::uint32_t> indices;  // the coarse levels' triangles, one level after another
  std::vector<DetailLevel> levels;     // stride 2, 4, ...; empty when no cloth is large enough
  double cell = 0.0;                   // the largest rest spacing of a grid cloth's vertices (m)
};

// The rows or columns a level keeps of n: 0, stride, 2 stride, ... and n - 1.
std::vector<int> detail_lines(int n, int stride);

// The coarse levels of a layout (none for a scene without a grid cloth of at least
// 2 kDetailMinCells cells a side).
ClothDetail make_cloth_detail(const ClothLayout& layout);

// The stride to draw with when a metre at the cloth's nearest point covers pixels_per_metre
// pixels: the largest level's whose cells stay within kDetailCellPixels, else 1 (every vertex).
int detail_stride(const ClothDetail& detail, double pixels_per_metre);

// How a drawing at `stride` reads: "every 2nd vertex", "every 4th vertex", ...; empty at 1.
std::string detail_note(int stride);

// The pixels a metre covers at the point of the box [lo, hi] nearest the eye, seen with a
// vertical field of view of fov_deg over `height` pixels; infinite with the eye in the box.
double pixels_per_metre(glm::vec3 eye, glm::vec3 lo, glm::vec3 hi, float fov_deg, int height);

}  // namespace clothlab::vis
