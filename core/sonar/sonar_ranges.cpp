#include "sonar/sonar_ranges.h"

#include <cmath>

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

}  // namespace sonarcarve
