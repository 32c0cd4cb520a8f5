// ReferenceCarver: the seed paper's carving, faithfully, as the yardstick for correctness.
// For every pixel (range bin, beam) a spherical arc is cast across the vertical aperture at
// the elevation step (default 0.2 degrees); every arc point updates the voxel it falls in
// with the pixel's intensity, keeping per voxel the minimum over all views. The map is an
// OctoMap octree with a float payload (OcTreeDataNode<float>), pruned where children agree.
// Unknown voxels have no node. Single-threaded and slow by design (about 32 million arc
// points per frame at the paper's parameters): restrict it with CarveParams::region.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "carve/carve_params.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

class MinIntensityOcTree;

class ReferenceCarver {
 public:
  ReferenceCarver(const SonarModel& sonar, const CarveParams& params);
  ~ReferenceCarver();

  void integrate(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar);

  /// Global voxel indices (same grid as VoxelMap) of every occupied voxel (0 < value < inf).
  std::vector<Eigen::Vector3i> occupiedVoxels() const;
  /// The value of a voxel, +inf if never observed.
  float value(const Eigen::Vector3i& voxel) const;
  std::size_t nodeCount() const;
  std::size_t memoryBytes() const;
  const MinIntensityOcTree& tree() const { return *tree_; }

 private:
  const SonarModel& sonar_;
  CarveParams params_;
  std::unique_ptr<MinIntensityOcTree> tree_;
  std::vector<double> arc_cos_, arc_sin_;
  std::size_t frames_ = 0;
};

}  // namespace sonarcarve
