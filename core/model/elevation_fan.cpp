#include "model/elevation_fan.h"

#include <algorithm>
#include <cmath>

#include "sonar/sonar_model.h"

namespace sonarcarve {

ElevationFan elevationFan(double half_rad, double nominal_step_rad) {
  ElevationFan fan;
  fan.half_rad = half_rad;
  const double traced = 2.0 * half_rad;
  fan.count = std::max(2, static_cast<int>(std::ceil(traced / nominal_step_rad)));
  fan.step_rad = traced / fan.count;
  return fan;
}

double solidAngleWeight(double power, double elevation_rad) {
  return power * std::cos(elevation_rad);
}

double elevationSampleScale(double gain, double step_rad, double aperture_rad, int rays) {
  return gain * step_rad / (aperture_rad * rays);
}

Eigen::Vector3d rayDirection(double bearing_rad, double elevation_rad) {
  return pointFromPolar({1.0, bearing_rad, elevation_rad});
}

}  // namespace sonarcarve
