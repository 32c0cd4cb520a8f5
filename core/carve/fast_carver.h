// FastCarver: the fast carving engine. Same semantics as the paper's arc casting (each voxel
// keeps the minimum intensity over every view that observed it; one view of empty water
// carves it for good), computed voxel-centrically: every voxel centre inside a frame's frustum
// is projected to the pixel that sees it (range bin, beam; its elevation inside the aperture)
// and takes that pixel's intensity. Unlike arc sampling this leaves no holes at long range
// and carves free space under dark pixels. Free blocks are skipped; blocks are shared among
// the pool's threads. integrate() must not run concurrently with itself on one map.
#pragma once

#include <optional>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "carve/carve_params.h"
#include "carve/carver.h"
#include "carve/carving_geometry.h"
#include "carve/seabed_model.h"
#include "carve/voxel_map.h"
#include "common/thread_pool.h"

namespace sonarcarve {

struct IntegrateStats {
  std::size_t blocks_visited = 0;  ///< blocks of the frustum's box that were not yet free
  std::size_t blocks_changed = 0;
  std::size_t voxels_observed = 0;  ///< not yet carved voxels inside the frustum
};

class FastCarver {
 public:
  FastCarver(VoxelMap& map, const SonarModel& sonar, const CarveParams& params, ThreadPool& pool);

  /// Carves one frame (CV_32F polar image) seen from `T_world_sonar`. Changed blocks get
  /// `stamp` (use the frame number + 1).
  IntegrateStats integrate(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar,
                           std::uint32_t stamp, const VisibilityLimit& visibility = {},
                           const BeforeDetection* before = nullptr);
  /// Seabed-aware carving: the frames a seabed explained so far.
  std::size_t seabedFrames() const { return seabed_.framesFound(); }

 private:
  VoxelMap& map_;
  CarveParams params_;
  CarvingGeometry geometry_;
  ThreadPool& pool_;
  SeabedTracker seabed_;
};

}  // namespace sonarcarve
