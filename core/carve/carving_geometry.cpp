#include "carve/carving_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/error.h"
#include "common/number_text.h"
#include "sonar/beam_pattern.h"

namespace sonarcarve {

namespace {

// Why the ranges carved are empty, naming where each end comes from: the parameters when they
// were set, the sonar's own declaration otherwise.
std::string emptyRangeWindow(const RangeBins& sonar, const CarveParams& params) {
  const std::string sonar_ranges = "the sonar's ranges " + shortestNumber(sonar.min_m) + " to " +
                                   shortestNumber(sonar.maxRange()) + " m";
  const bool min_set = params.range_min_m > sonar.min_m;
  const bool max_set = params.range_max_m > 0.0;
  if (!min_set && !max_set) {
    return sonar_ranges +
           " (min_m + bins x resolution_m) hold no range: expected a sonar "
           "whose bins span some distance";
  }
  std::string given;
  if (min_set) {
    given = "range_min_m " + shortestNumber(params.range_min_m);
  }
  if (max_set) {
    given += (given.empty() ? "" : " and ") + std::string("range_max_m ") +
             shortestNumber(params.range_max_m);
  }
  return "with " + given + ", nothing is left of " + sonar_ranges +
         ": expected range_min_m below range_max_m, both within the sonar's ranges (0 = the "
         "sonar's own)";
}

}  // namespace

bool carvesMainLobe(const SonarModel& sonar, const CarveParams& params) {
  return params.beam_aware && sonar.elevationBeam() == ElevationBeam::MainLobe;
}

CarvingGeometry::CarvingGeometry(const SonarModel& sonar, const CarveParams& params)
    : sonar_(sonar) {
  range_min_ = std::max(params.range_min_m, sonar.range().min_m);
  range_max_ = params.range_max_m > 0.0 ? std::min(params.range_max_m, sonar.range().maxRange())
                                        : sonar.range().maxRange();
  if (!(range_max_ > range_min_)) {
    throw Error("parameters", "range window", emptyRangeWindow(sonar.range(), params));
  }
  range_min_sq_ = static_cast<float>(range_min_ * range_min_);
  range_max_sq_ = static_cast<float>(range_max_ * range_max_);
  const double s = std::sin(0.5 * sonar.verticalAperture());
  sin_half_aperture_sq_ = static_cast<float>(s * s);
  sin_half_aperture_ = s;
  cos_half_aperture_ = std::cos(0.5 * sonar.verticalAperture());
  const SincSquaredBeam elevation_beam(sonar.verticalAperture());
  const bool main_lobe = carvesMainLobe(sonar, params);
  carved_half_elevation_ = 0.5 * sonar.verticalAperture();
  if (main_lobe) {
    carved_half_elevation_ = sonar.mainLobeReach();
  }
  if (carved_half_elevation_ >= 0.5 * std::numbers::pi) {
    throw Error("carving", "vertical aperture",
                "the beam's main lobe must stay within 90 degrees of its axis");
  }
  if (main_lobe) {
    const double sin_carved = std::sin(carved_half_elevation_);
    constexpr int kGainSamples = 2048;
    inverse_gain_.resize(kGainSamples);
    for (int i = 0; i < kGainSamples; ++i) {
      const double elevation = std::asin((i + 0.5) / kGainSamples * sin_carved);
      inverse_gain_[static_cast<std::size_t>(i)] =
          static_cast<float>(1.0 / std::max(elevation_beam.power(elevation), 1e-6));
    }
    inverse_gain_scale_ = static_cast<float>(kGainSamples / sin_carved);
  } else {
    inverse_gain_.assign(1, 1.0f);
  }
  if (sonar.bearings().fieldOfView() >= std::numbers::pi) {
    throw Error("carving", "field of view",
                "fields of view of 180 degrees or more are not supported");
  }
  const double left = sonar.bearings().leftEdge();
  const double right = sonar.bearings().rightEdge();
  left_normal_ = Eigen::Vector3d(-std::sin(left), std::cos(left), 0.0);
  right_normal_ = Eigen::Vector3d(std::sin(right), -std::cos(right), 0.0);

  const BearingTable& b = sonar.bearings();
  double narrowest = b.fieldOfView();
  for (int j = 0; j < b.count(); ++j) {
    narrowest = std::min(narrowest, b.edges()[static_cast<std::size_t>(j) + 1] -
                                        b.edges()[static_cast<std::size_t>(j)]);
  }
  // Uniform tables: one cell per beam is exact. Explicit ones: 16 cells per narrowest beam.
  const double step = b.isUniform() ? b.fieldOfView() / b.count() : narrowest / 16.0;
  const auto cells = static_cast<std::size_t>(std::ceil(b.fieldOfView() / step));
  lut_.resize(cells);
  for (std::size_t i = 0; i < cells; ++i) {
    const auto beam = b.beamOf(b.leftEdge() + (static_cast<double>(i) + 0.5) * step);
    lut_[i] = static_cast<std::int16_t>(beam ? *beam : -1);
  }
  lut_left_ = static_cast<float>(b.leftEdge());
  lut_inv_step_ = static_cast<float>(1.0 / step);
}

Eigen::AlignedBox3d CarvingGeometry::frustumBounds(const Eigen::Isometry3d& T_world_sonar,
                                                   double half_elevation) const {
  Eigen::AlignedBox3d box;
  const double half = half_elevation >= 0.0 ? half_elevation : carved_half_elevation_;
  const double left = sonar_.bearings().leftEdge();
  const double right = sonar_.bearings().rightEdge();
  const int steps =
      std::max(2, static_cast<int>(std::ceil((right - left) / (std::numbers::pi / 36))));
  const int elevation_steps =
      std::max(2, static_cast<int>(std::ceil(2.0 * half / (std::numbers::pi / 36))));
  for (double r : {range_min_, range_max_}) {
    for (int i = 0; i <= steps; ++i) {
      const double bearing = left + (right - left) * i / steps;
      for (int k = 0; k <= elevation_steps; ++k) {
        const double elevation = -half + 2.0 * half * k / elevation_steps;
        box.extend(T_world_sonar * pointFromPolar({r, bearing, elevation}));
      }
    }
  }
  // Arcs between the samples bulge by at most r (1 - cos(2.5 deg)) < 1 % of the range.
  const double pad = 0.01 * range_max_;
  box.min().array() -= pad;
  box.max().array() += pad;
  return box;
}

bool CarvingGeometry::sphereMayTouchFrustum(const Eigen::Vector3d& c, double radius,
                                            double sin_half, double cos_half) const {
  // Signed distances to the frustum's bounding surfaces, without trigonometry: this runs for
  // every block of a frame's bounding box.
  const double d2 = c.squaredNorm();
  if (d2 > (range_max_ + radius) * (range_max_ + radius)) {
    return false;
  }
  const double d = std::sqrt(d2);
  if (d + radius < range_min_) {
    return false;
  }
  if (d <= radius) {
    return true;
  }
  // Bearing wedge [left, right] (narrower than 180 degrees): inside both boundary planes.
  if (left_normal_.dot(c) < -radius || right_normal_.dot(c) < -radius) {
    return false;
  }
  // Elevation: distance to the cone |theta| = carved half elevation.
  const double horizontal = std::hypot(c.x(), c.y());
  return std::abs(c.z()) * cos_half - horizontal * sin_half <= radius;
}

}  // namespace sonarcarve
