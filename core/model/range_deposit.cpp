#include "model/range_deposit.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sonarcarve {

void spreadOverRange(float r0, float r1, float energy, const RangeBins& bins, float* column) {
  if (r1 < r0) {
    std::swap(r0, r1);
  }
  const auto first = static_cast<double>(r0);
  const auto last = static_cast<double>(r1);
  const double span = last - first;
  const double res = bins.resolution_m;
  if (span < 1e-6 * res) {
    depositAtRange(0.5 * (first + last), energy, bins, column);
    return;
  }
  // One division per spread, not one per bin: the same floats but for a last-bit tie in one
  // value of billions (double rounding before the cast to float).
  const double per_metre = energy / span;
  const int b0 = std::max(0, static_cast<int>(std::floor((first - bins.min_m) / res)));
  const int b1 = std::min(bins.count - 1, static_cast<int>(std::floor((last - bins.min_m) / res)));
  for (int b = b0; b <= b1; ++b) {
    const double lo = std::max(first, bins.min_m + b * res);
    const double hi = std::min(last, bins.min_m + (b + 1) * res);
    if (hi > lo) {
      column[b] += static_cast<float>(per_metre * (hi - lo));
    }
  }
}

}  // namespace sonarcarve
