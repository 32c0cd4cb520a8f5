// Parameters of space carving, with the seed paper's defaults. SI units; YAML in degrees.
#pragma once

#include <Eigen/Geometry>
#include <optional>

#include "common/angles.h"

namespace sonarcarve {

struct CarveParams {
  static constexpr double kDefaultVoxelSize_m = 0.02;
  static constexpr double kDefaultElevationStep_rad = degToRad(0.2);

  double voxel_size_m = kDefaultVoxelSize_m;
  /// Pixels at or below this intensity count as empty water and carve their arcs.
  double intensity_threshold = 0.0;
  /// Elevation step of the paper's arcs (reference engine) and of occlusion resolution.
  double elevation_step_rad = kDefaultElevationStep_rad;
  /// Range window used, metres; 0 means the sonar's own limit.
  double range_min_m = 0.0;
  double range_max_m = 0.0;
  /// Only this box of the world (NED, metres) is mapped; unset: everything the frames see.
  std::optional<Eigen::AlignedBox3d> region;
  /// How a voxel combines its views. Minimum: the seed paper's carving (the darkest view
  /// wins). LogOdds: pixels are detection probabilities p; a voxel sums, over its views, the
  /// evidence log(p / (1 - p)) - arc_prior (the prior that a voxel on a lit arc is not the
  /// one that returned), is occupied while the sum is positive and is carved for good once
  /// it falls below `carve_log_odds`. One dark speckle lowers the sum; it no longer carves.
  enum class Fusion { Minimum, LogOdds };
  Fusion fusion = Fusion::Minimum;
  double arc_prior = 2.0;
  double carve_log_odds = -4.0;
};

}  // namespace sonarcarve
