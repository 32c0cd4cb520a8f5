#include "pipeline/shadow_carving.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "pipeline/heading_sectors.h"

namespace sonarcarve {

double headingSpreadDeg(const std::vector<PosedFrame>& frames) {
  std::vector<double> headings;
  for (const PosedFrame& f : frames) {
    if (const std::optional<double> heading = lookHeadingDeg(f)) {
      headings.push_back(*heading);
    }
  }
  if (headings.size() < 2) {
    return 0.0;
  }
  std::sort(headings.begin(), headings.end());
  // The spread is the circle less its widest gap between neighbouring headings.
  double widest = headings.front() + 360.0 - headings.back();
  for (std::size_t i = 1; i < headings.size(); ++i) {
    widest = std::max(widest, headings[i] - headings[i - 1]);
  }
  return 360.0 - widest;
}

ShadowCarvingChoice chooseShadowCarving(ShadowCarving mode, const std::vector<PosedFrame>& frames) {
  ShadowCarvingChoice result;
  RunChoice& choice = result.choice;
  choice.name = "shadow-aware carving";
  if (mode != ShadowCarving::Auto) {
    result.on = mode == ShadowCarving::On;
    choice.value = result.on ? "on" : "off";
    choice.reason = "as the parameters set it";
    choice.detail =
        choice.value + " (shadow_aware_carving: " + (result.on ? "true" : "false") + ")";
    return result;
  }
  const double spread = headingSpreadDeg(frames);
  std::ostringstream detail;
  detail.precision(3);
  result.on = spread > kMultiAspectHeadingSpread_deg;
  choice.value = result.on ? "on" : "off";
  detail << choice.value << " (auto: the views' headings span " << spread << " degrees, "
         << (result.on ? "over " : "not over ") << kMultiAspectHeadingSpread_deg << ")";
  choice.detail = detail.str();
  choice.reason = result.on ? "the mission views the structure from several sides"
                            : "the mission views the structure from one side";
  return result;
}

}  // namespace sonarcarve
