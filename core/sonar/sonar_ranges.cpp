#include "sonar/sonar_ranges.h"

#include <cmath>
#include <utility>

#include "common/number_text.h"

namespace sonarcarve {

std::optional<std::string> outsideRange(double value, const PhysicalRange& range) {
  const bool below_max = range.max_open ? value < range.max : value <= range.max;
  if (std::isfinite(value) && value >= range.min && below_max) {
    return std::nullopt;
  }
  const std::string unit = *range.unit == '\0' ? "" : std::string(" ") + range.unit;
  return "expected " + shortestNumber(range.min) + " to " + shortestNumber(range.max) +
         (range.max_open ? " (excluded)" : "") + unit + ", got " + shortestNumber(value);
}

std::optional<std::string> recordedGeometryProblem(const RecordedGeometry& g) {
  const std::pair<const RecordedQuantity*, const PhysicalRange*> checks[] = {
      {&g.near_range_m, &kNearRange},
      {&g.range_resolution_m, &kRangeResolution},
      {&g.field_of_view_deg, &kFieldOfView},
      {&g.vertical_aperture_deg, &kVerticalAperture}};
  for (const auto& [quantity, range] : checks) {
    if (quantity->field.empty()) {
      continue;  // not in the recording
    }
    if (const auto problem = outsideRange(quantity->value, *range)) {
      return quantity->field + ": " + *problem;
    }
  }
  const double far_m = g.near_range_m.value + g.bins * g.range_resolution_m.value;
  if (far_m > kMaxFarRange_m) {
    return g.range_resolution_m.field + ": the farthest range is " + shortestNumber(far_m) +
           " m (" + std::to_string(g.bins) + " bins from " + shortestNumber(g.near_range_m.value) +
           " m): expected at most " + shortestNumber(kMaxFarRange_m) + " m";
  }
  return std::nullopt;
}

}  // namespace sonarcarve
