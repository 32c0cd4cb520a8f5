// Small analytic scenes for simulator and carving tests.
#pragma once

#include <utility>
#include <vector>

#include "geometry/scene.h"

namespace sonarcarve::test {

/// A square plate of side `size` centred at `centre`, facing along `normal`.
Scene plate(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, double size,
            float reflectivity);
/// A patch of the sphere of radius `range` around the origin, between two bearings and two
/// elevations (sonar conventions, radians), facing the origin: a sonar at the origin meets it
/// at normal incidence. Vertices every `step_rad` or finer in both angles.
Scene sphericalPatch(double range, double bearing_lo, double bearing_hi, double elevation_lo,
                     double elevation_hi, double step_rad, float reflectivity);
/// Spheres (centre, radius), reflectivity 0.8.
Scene sphereScene(const std::vector<std::pair<Eigen::Vector3d, double>>& spheres);

}  // namespace sonarcarve::test
