// The 2/2 twill's geometry, shared by the fabric albedo (fabric_texture.cpp) and the weave maps
// (weave_maps.cpp) so that colour, bumps and thread masks line up texel for texel. Warp threads
// run down the image (one per column band), weft threads across it (one per row band); in cell
// (i, j) the warp lies on top where (i + j) mod 4 < 2, which steps the floats by one thread per
// row and gives the diagonal rib of denim or gabardine.
#pragma once

#include <cmath>

namespace clothlab::twill {

inline constexpr float kThreadWidth = 0.86f;  // fraction of a cell a thread covers; rest is gap

// Whether warp thread `i` lies above weft thread `j` (indices wrap at the tile, whose thread
// count is a multiple of 4).
inline bool warp_on_top(int i, int j) {
  return ((i + j) & 3) < 2;
}

inline float smoothstep(float t) {
  return t * t * (3.0f - 2.0f * t);
}

// Elevation (-1 under .. +1 over) of a thread along its length at coordinate `along` (in cells),
// blending the over/under state of the two nearest cell centres with a smoothstep.
template <class OnTop>
float thread_height(float along, OnTop on_top) {
  const float s = along - 0.5f;
  const float c0 = std::floor(s);
  const float t = smoothstep(s - c0);
  const int j = static_cast<int>(c0);
  const float h0 = on_top(j) ? 1.0f : -1.0f;
  const float h1 = on_top(j + 1) ? 1.0f : -1.0f;
  return h0 + (h1 - h0) * t;
}

// Cross-section of a round thread: the cosine of the surface normal to the viewer for a
// cylinder of width kThreadWidth centred in the cell, 0 outside it (the gap between threads).
inline float thread_profile(float across) {
  const float d = (across - 0.5f) / (0.5f * kThreadWidth);
  return d * d < 1.0f ? std::sqrt(1.0f - d * d) : 0.0f;
}

}  // namespace clothlab::twill
