// Which vertices carry arrow glyphs and what each arrow shows: the CPU half of the arrow views
// (F force arrows, N normal arrows), plain data for ArrowPass to draw and for tests to check.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "vis/colormap/colormap.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab {
class SolverState;
}

namespace clothlab::vis {

// With stride 0, at most about this many arrows along each side of a grid cloth.
inline constexpr int kAutoArrowsPerSide = 24;

// One arrow: from `base` along `vector` (its displayed length, m); `value` in [0, 1] is the
// colour map coordinate (force arrows; normal arrows are coloured by direction).
struct ArrowInstance {
  glm::vec3 base;
  glm::vec3 vector;
  float value;
};

struct ArrowLayout {
  int stride = 1;
  std::vector<int> vertices;  // the shown vertices, solver indices
  float spacing = 0.0f;       // m: mean built distance between neighbouring shown vertices
};

// The stride `stride` > 0 asks for, or (0) the smallest one that keeps both sides of every
// grid cloth at or below kAutoArrowsPerSide arrows.
int arrow_stride(const SolverState& solver, int stride);
// Every stride-th vertex along i and j of each cloth, starting at (0, 0), plus the last row and
// column so the free edges show.
ArrowLayout arrow_layout(const SolverState& solver, int stride);

// The automatic range's top: this quantile of the shown free vertices' magnitudes.
inline constexpr double kArrowRangeQuantile = 0.9;

// The range force arrows are sized and coloured by: [0, the kArrowRangeQuantile quantile of the
// magnitudes over the shown free vertices] (the largest when that quantile is 0), or `fixed`.
// A robust top rather than the largest: near rest a few vertices (beside the pins, at a
// contact) carry most of the force and would shrink every other arrow to nothing. Pinned
// vertices are left out (their force is the support's reaction). Arrows above the top
// saturate at the longest length, and the legend's bar ends there. Never empty.
ScalarRange arrow_range(const SolverState& solver, const ArrowLayout& layout,
                        const std::vector<float>& vectors, RangeMode mode, ScalarRange fixed);

// The total force counts as near zero (a cloth at rest: every vertex's springs balance its
// weight) when its range's top is below this share of the springs' force's top. Measured on
// the default sheet: 0.07 settled without wind, 0.36 in its gusts.
inline constexpr double kNearRestRatio = 0.15;
bool total_near_zero(ScalarRange total, ScalarRange springs);

// Length of a force arrow of magnitude m for the longest length `max_length` at range.max:
// linear max_length * m / max; log max_length * (1 + log10(m / max) / 3), clamped to [0, 1] of
// max_length (three decades below the top of the range stay visible).
float arrow_length(float magnitude, ArrowScale scale, float max_length, ScalarRange range);

// Force arrows for `vectors` (3 floats per solver vertex) at `positions` (likewise).
void build_force_arrows(const ArrowLayout& layout, const std::vector<float>& positions,
                        const std::vector<float>& vectors, ArrowScale scale, float max_length,
                        ScalarRange range, std::vector<ArrowInstance>& out);
// Unit normals drawn at a constant length, each turned to the side that faces `eye` (the camera).
void build_normal_arrows(const ArrowLayout& layout, const std::vector<float>& positions,
                         const std::vector<float>& normals, float length, glm::vec3 eye,
                         std::vector<ArrowInstance>& out);

}  // namespace clothlab::vis
