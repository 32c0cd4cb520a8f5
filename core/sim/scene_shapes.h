// Simple shapes as scenes, in the world NED frame (metres), for the demo scenes and the seabed
// field: capped tubes, spheres, boxes and a sloping square of seabed.
#pragma once

#include <Eigen/Core>

#include "geometry/scene.h"

namespace sonarcarve {

/// A capped cylinder of `radius` between the points `a` and `b`, with `sides` facets.
Scene tubeShape(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius, int sides,
                float reflectivity);
/// A sphere of `radius`, `around` facets around and half as many from pole to pole.
Scene sphereShape(const Eigen::Vector3d& centre, double radius, float reflectivity,
                  int around = 64);
/// A box of `size` (north, east, down extents) centred at `centre`, turned by `yaw_deg`.
Scene boxShape(const Eigen::Vector3d& centre, const Eigen::Vector3d& size, double yaw_deg,
               float reflectivity);
/// A square of seabed of side `size` centred under `centre`, sloping down towards north,
/// `resolution` cells a side.
Scene seabedSquare(const Eigen::Vector3d& centre, double size, double slope_deg, int resolution,
                   float reflectivity);

}  // namespace sonarcarve
