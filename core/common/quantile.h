// The q-quantile of a sample, as the element at index floor(q * (n - 1)) of its sorted order.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace sonarcarve {

/// Reorders `values` (nth_element); `values` must not be empty, 0 <= q <= 1.
template <typename T>
T quantile(std::vector<T>& values, double q) {
  const auto it =
      values.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), it, values.end());
  return *it;
}

}  // namespace sonarcarve
