// HoloOcean's frames and ours (docs/conventions.md, "HoloOcean / NeuSIS datasets").
//
// HoloOcean's world is right-handed with x forward, y left and z up; a sensor's frame is x
// forward, y left (port), z up. Ours are NED and the sonar's x forward, y starboard, z down. The
// world x axis is taken as north: north = x, east = -y, down = -z, a half turn about x (D =
// diag(1, -1, -1)), and the same half turn takes the sensor's frame to ours:
//   R_ned_sonar = D * R_holo * D,   p_ned = D * p_holo.
// A HoloOcean ImagingSonar image is RangeBins x AzimuthBins, row i covering ranges
// [RangeMin + i * res, RangeMin + (i + 1) * res), column j the azimuths
// [-Azimuth/2 + j * ares, -Azimuth/2 + (j + 1) * ares) measured towards port (y, left): column 0
// is the starboard edge. Our columns run port to starboard, so column j is ours W - 1 - j.
#pragma once

#include <Eigen/Geometry>

#include "sonar/nav_track.h"

namespace sonarcarve {

/// HoloOcean's world-from-sensor pose (a PoseSensor matrix) as our world NED sonar pose.
Eigen::Isometry3d nedPoseFromHoloOcean(const Eigen::Matrix4d& T_holo);
/// Our world NED sonar pose as HoloOcean's 4 x 4 world-from-sensor matrix.
Eigen::Matrix4d holoOceanPoseFromNed(const Eigen::Isometry3d& T_ned_sonar);

}  // namespace sonarcarve
