// ModelGradient: d(loss)/d(every parameter of the forward model) for one frame, from
// d(loss)/d(predicted pixel) (model/forward_model.h). The pose's is over a twist
// xi = (v, omega) of the sonar frame: T_world_sonar * Exp(xi), v the translation (metres) and
// omega the rotation vector (radians), both in the sonar frame.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace sonarcarve {

using Twist = Eigen::Matrix<double, 6, 1>;

struct ModelGradient {
  std::vector<double> logits;       ///< per voxel, the grid's layout (model/block_grid.h)
  std::vector<double> reflectance;  ///< per voxel
  std::vector<double> knots_db;     ///< per knot of the elevation profile
  double gain = 0.0;
  std::vector<double> background;  ///< per range bin
  Twist twist = Twist::Zero();

  /// Zeros of the sizes of a grid, a profile and a range axis.
  ModelGradient(std::size_t voxels, std::size_t knots, std::size_t bins);
  /// Adds another gradient of the same sizes.
  void add(const ModelGradient& other);
};

/// T_world_sonar * Exp(xi), xi = (v, omega) (ModelGradient).
Eigen::Isometry3d applyTwist(const Eigen::Isometry3d& T_world_sonar, const Twist& xi);

}  // namespace sonarcarve
