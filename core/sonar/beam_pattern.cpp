#include "sonar/beam_pattern.h"

#include <cmath>
#include <numbers>

#include "common/error.h"

namespace sonarcarve {

double sincMinus3dBArgument() {
  // sin(x)/x falls monotonically from 1 to 0 on (0, pi): bisect once and cache.
  static const double x3db = [] {
    const double target = std::pow(10.0, -0.3);
    double lo = 1e-9;
    double hi = std::numbers::pi;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (std::sin(mid) / mid > target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }();
  return x3db;
}

BeamPattern::BeamPattern(double aperture_rad) : aperture_rad_(aperture_rad) {
  if (!(aperture_rad > 0.0) || !std::isfinite(aperture_rad)) {
    throw Error("sonar model", "vertical aperture", "expected a positive finite aperture");
  }
  k_ = sincMinus3dBArgument() / (0.5 * aperture_rad);
}

double BeamPattern::weight(double elevation_rad) const {
  const double x = std::abs(k_ * elevation_rad);
  if (x < 1e-12) {
    return 1.0;
  }
  if (x >= std::numbers::pi) {
    return 0.0;
  }
  return std::sin(x) / x;
}

double BeamPattern::firstNull() const {
  return std::numbers::pi / k_;
}

}  // namespace sonarcarve
