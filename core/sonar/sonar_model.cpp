#include "sonar/sonar_model.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "common/error.h"
#include "common/input_limits.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {

Eigen::Vector3d pointFromPolar(const Polar& polar) {
  const double c = std::cos(polar.elevation_rad);
  return polar.range_m * Eigen::Vector3d(c * std::cos(polar.bearing_rad),
                                         c * std::sin(polar.bearing_rad),
                                         -std::sin(polar.elevation_rad));
}

Polar polarFromPoint(const Eigen::Vector3d& p_sonar) {
  Polar polar;
  polar.range_m = p_sonar.norm();
  if (polar.range_m == 0.0) {
    return polar;
  }
  polar.bearing_rad = std::atan2(p_sonar.y(), p_sonar.x());
  polar.elevation_rad = std::asin(std::clamp(-p_sonar.z() / polar.range_m, -1.0, 1.0));
  return polar;
}

SonarModel::SonarModel(std::string id, RangeBins range, BearingTable bearings,
                       double vertical_aperture_rad)
    : id_(std::move(id)),
      range_(range),
      bearings_(std::move(bearings)),
      beam_pattern_(vertical_aperture_rad) {
  if (range_.count < 1) {
    throw Error("sonar model", "range", "expected at least one range bin");
  }
  if (range_.count > kMaxRangeBins) {
    throw Error("sonar model", "range",
                std::to_string(range_.count) + " range bins: expected at most " +
                    std::to_string(kMaxRangeBins));
  }
  if (std::int64_t{range_.count} * cols() > kMaxFramePixels) {
    throw Error("sonar model", "range",
                std::to_string(range_.count) + " bins x " + std::to_string(cols()) +
                    " beams: expected at most " + std::to_string(kMaxFramePixels) +
                    " pixels per frame");
  }
  if (!(range_.resolution_m > 0.0) || !std::isfinite(range_.resolution_m)) {
    throw Error("sonar model", "range", "expected a positive range resolution");
  }
  if (!(range_.min_m >= 0.0) || !std::isfinite(range_.min_m)) {
    throw Error("sonar model", "range", "expected a minimum range >= 0");
  }
  if (bearings_.leftEdge() <= -std::numbers::pi || bearings_.rightEdge() >= std::numbers::pi) {
    throw Error("sonar model", "bearings", "field of view must lie within (-180, 180) degrees");
  }
}

const char* elevationBeamName(ElevationBeam beam) {
  return beam == ElevationBeam::Clipped ? "clipped" : "sinc";
}

SonarModel SonarModel::withHorizontalBeamWidth(double width_rad) const {
  if (!(width_rad >= 0.0) || !std::isfinite(width_rad) || width_rad >= bearings_.fieldOfView()) {
    throw Error("sonar model", "horizontal beam width",
                "expected an angle >= 0 and under the field of view");
  }
  SonarModel other = *this;
  other.horizontal_beam_width_rad_ = width_rad;
  return other;
}

Polar SonarModel::pixelCentre(const Pixel& pixel) const {
  return Polar{range_.centre(pixel.row), bearings_.centre(pixel.col), 0.0};
}

std::optional<Pixel> SonarModel::pixelOf(const Polar& polar) const {
  if (std::abs(polar.elevation_rad) > 0.5 * verticalAperture()) {
    return std::nullopt;
  }
  const auto row = range_.binOf(polar.range_m);
  const auto col = bearings_.beamOf(polar.bearing_rad);
  if (!row || !col) {
    return std::nullopt;
  }
  return Pixel{*row, *col};
}

std::optional<Pixel> SonarModel::pixelOf(const Eigen::Vector3d& p_sonar) const {
  return pixelOf(polarFromPoint(p_sonar));
}

double SonarModel::mainLobeReach() const {
  const double null = SincSquaredBeam(verticalAperture()).null(1);
  return elevation_reach_rad_ > 0.0
             ? std::clamp(elevation_reach_rad_, 0.5 * verticalAperture(), null)
             : null;
}

}  // namespace sonarcarve
