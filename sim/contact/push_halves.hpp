// The two halves that triangle contact's pushes run on, one thread each
// (sim/contact/triangle_contact.cpp, push_sweeps). Each collection of pairs cuts the vertices by
// a plane across the axis along which they spread widest, at the median of their positions: a
// pair whose four vertices lie on one side shares no vertex with a pair of the other, and the two
// sides' Gauss-Seidel sweeps can run at once and give what running one after the other gives. The
// pairs across the cut run after both. The cut stays until the next collection: placed afresh
// each pass (at the median of the pairs to push, to balance the threads), it reordered the sweeps
// every pass and left the landed pile's layers closer (docs/contact.md section 7). Positions
// decide the halves, not vertex numbers, so a renumbered cloth gets the same pushes; the thread
// count decides nothing.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "sim/core/vec3_array.hpp"

namespace clothlab {

// What triangle contact's push sweeps keep within a pass (triangle_contact.cpp, push_sweeps).
template <class T>
struct PushSweeps {
  // Per vertex: the stamp of the last push that moved it in this pass (0: none yet).
  std::vector<std::uint64_t> pushed_at;
  // The vertices pushed in this pass, by the half whose sweep first pushed them (2: across the
  // cut); the caller keeps where they were before.
  std::array<std::vector<std::int32_t>, 3> moved;
  // A pair flagged hit, and the stamp that no push before its last try exceeds.
  struct Hit {
    std::uint32_t pair = 0;
    std::uint64_t tried = 0;
  };
  std::vector<Hit> hits;               // by half, each in pair order
  std::array<std::size_t, 4> begin{};  // where each half's hits begin (and where they end)
  std::vector<std::uint8_t> half;      // per pair of the list: its half (2: across the cut)
  // Per block of pairs: where its hits start in each half, counted from the half's begin.
  std::vector<std::array<std::size_t, 3>> block_start;
  std::vector<T> cut_values;  // scratch for the median
};

// The axis along which the positions spread widest.
template <class T>
int widest_axis(const Vec3Array<T>& x) {
  int widest = 0;
  T widest_extent = T(-1);
  for (int a = 0; a < 3 && x.size() > 0; ++a) {
    const auto [lo, hi] = std::minmax_element(x.axis(a).begin(), x.axis(a).end());
    if (*hi - *lo > widest_extent) {
      widest_extent = *hi - *lo;
      widest = a;
    }
  }
  return widest;
}

// The median of the values (reordered), NaN taken as +infinity: a diverged run, which the
// divergence monitor stops, must not break the ordering nth_element needs.
template <class T>
T median_of(std::vector<T>& values) {
  if (values.empty()) return T(0);
  for (T& v : values)
    if (std::isnan(v)) v = std::numeric_limits<T>::infinity();
  const auto middle = values.begin() + long(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// The pair's half: 0 when all four vertices lie below the cut, 1 when all lie on or above it, 2
// across it (a NaN coordinate counts as above, as in median_of).
template <class Coordinates, class T>
int pair_half(const std::array<std::int32_t, 4>& v, const Coordinates& coordinate, T cut) {
  const bool below = coordinate[std::size_t(v[0])] < cut;
  for (std::size_t k = 1; k < 4; ++k)
    if ((coordinate[std::size_t(v[k])] < cut) != below) return 2;
  return below ? 0 : 1;
}

}  // namespace clothlab
