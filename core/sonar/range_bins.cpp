#include "sonar/range_bins.h"

#include <cmath>

namespace sonarcarve {

std::optional<int> RangeBins::binOf(double range_m) const {
  const double index = std::floor((range_m - min_m) / resolution_m);
  if (!(index >= 0.0) || index >= count) {
    return std::nullopt;
  }
  return static_cast<int>(index);
}

}  // namespace sonarcarve
