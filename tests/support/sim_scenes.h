// Small analytic scenes for simulator and carving tests.
#pragma once

#include <utility>
#include <vector>

#include "geometry/scene.h"

namespace sonarcarve::test {

/// A square plate of side `size` centred at `centre`, facing along `normal`.
Scene plate(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, double size,
            float reflectivity);
/// Spheres (centre, radius), reflectivity 0.8.
Scene sphereScene(const std::vector<std::pair<Eigen::Vector3d, double>>& spheres);

}  // namespace sonarcarve::test
