// RangeBins: the range axis of a polar sonar image.
// Bin i covers [min_m + i * resolution_m, min_m + (i + 1) * resolution_m); its centre is the
// range a pixel of row i stands for. Row 0 is the nearest bin.
#pragma once

#include <cmath>
#include <optional>

namespace sonarcarve {

struct RangeBins {
  double min_m = 0.0;          ///< near edge of bin 0, metres
  double resolution_m = 0.02;  ///< bin width, metres
  int count = 500;             ///< number of bins (image rows)

  /// Far edge of the last bin, metres.
  double maxRange() const { return min_m + resolution_m * count; }
  /// Centre of bin `i`, metres.
  double centre(int i) const { return min_m + (i + 0.5) * resolution_m; }
  /// The bin that contains `range_m`, or nothing outside [min_m, maxRange()). Inline: the
  /// simulator asks it for every ray.
  std::optional<int> binOf(double range_m) const {
    const double index = std::floor((range_m - min_m) / resolution_m);
    if (!(index >= 0.0) || index >= count) {
      return std::nullopt;
    }
    return static_cast<int>(index);
  }
};

}  // namespace sonarcarve
