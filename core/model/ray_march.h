// RayMarch: one elevation ray of the forward model through the block grid. The ray samples
// the range axis on a fixed lattice, r_i = min + (i + 1/2) ds with ds = bin width /
// samples_per_bin, so that every range bin gets the same number of samples and a sample's
// bin never depends on the pose. It jumps over absent blocks and over the cells the reader
// says hold nothing that reaches min_alpha (model/active_cells.h); of the other samples it
// keeps those whose occupancy alpha = sigmoid(o) reaches min_alpha (the others are taken as
// empty: alpha = 0), with their transmittance T_i = prod over kept m < i of
// (1 - alpha_m), until T falls below min_transmittance.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/voxel_stencil.h"
#include "sonar/range_bins.h"

namespace sonarcarve {

/// What the prediction needs of a sample.
struct SampleValues {
  double range_m = 0.0;
  Eigen::Vector3d p_sonar;  ///< sample point in the sonar frame
  double alpha = 0.0;
  double transmittance = 0.0;
  double reflectance = 0.0;
  Eigen::Vector3d gradient;    ///< occupancy gradient (logit per metre), world frame
  double cos_incidence = 0.0;  ///< max(0, d . g / |g|)
};

/// And the gradient the voxels it read, 15 times as large.
struct RaySample : SampleValues {
  VoxelStencil stencil;
};

struct MarchLimits {
  RangeBins bins;
  int samples_per_bin = 2;
  double min_alpha = 1e-3;
  double min_transmittance = 1e-4;
};

/// Marches the ray from `origin` along the unit world `direction` (sonar-frame direction
/// `direction_sonar`), into `samples` (cleared first).
void marchRay(StencilReader& reader, double voxel_size, const Eigen::Vector3d& origin,
              const Eigen::Vector3d& direction, const Eigen::Vector3d& direction_sonar,
              const MarchLimits& limits, std::vector<RaySample>& samples);

/// Sigmoid, and d sigmoid / d o = alpha (1 - alpha).
inline double sigmoid(double o) {
  return 1.0 / (1.0 + std::exp(-o));
}

}  // namespace sonarcarve
