// The q-quantile of a sample by partial sorting (std::nth_element, O(n)): the automatic ranges
// of the force arrows and of mode 1's strain colours use a robust top instead of the largest
// value, so a few outliers (the pins' neighbours) do not squeeze everything else.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace clothlab::vis {

// The element of rank q (size - 1), rounded down; reorders `values`. `values` must not be empty
// and q must lie in [0, 1].
template <class T>
T quantile(std::vector<T>& values, double q) {
  const auto k = values.begin() + static_cast<std::ptrdiff_t>(q * double(values.size() - 1));
  std::nth_element(values.begin(), k, values.end());
  return *k;
}

}  // namespace clothlab::vis
