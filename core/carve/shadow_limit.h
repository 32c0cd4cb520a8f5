// Shadow limits: how far a frame sees along each of its rays, so that a dark pixel in a
// structure's acoustic shadow is not taken for empty water.
//
// A pixel is dark where nothing returned at its range in its beam; at the elevations hidden
// behind a nearer surface that says nothing. From one vertical pass that matters little (the
// hidden faces are never seen), but a mission that views a structure from several sides (an
// orbit, a second descent, a lawnmower's return lines) would otherwise carve every face that
// one side sees with the other side's shadows.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "carve/carver.h"
#include "carve/carving_geometry.h"
#include "carve/voxel_map.h"
#include "common/thread_pool.h"

namespace sonarcarve {

/// What the limits are computed from, besides the frame and the map.
struct ShadowLimitSetup {
  double half_elevation_rad = 0.0;  ///< the rays cover +-this about the sonar's axis
  double elevation_step_rad = 0.0;  ///< one ray per this much elevation
  bool beam_aware = false;          ///< CarvingGeometry's inverse gain weighs the pixels
  float keep_level = 0.0f;          ///< beam-aware: bounds at or under it hold no surface
  /// Whether a voxel no view has reached yet may hide what lies behind it. True for exact
  /// pixels (no detector: a lit pixel proves a return on its arc). Behind a detector a lit
  /// pixel may be a false alarm, so only a voxel some view has kept (occupied) may hide: a
  /// noisy orbit of the riser gives F 0.328 with unknown voxels hiding (the water behind
  /// false alarms stays, p90 7 m) and 0.749 without; noise-free, 0.716 with and 0.558 without.
  bool unknown_may_hide = true;
};

/// The rays of one frame and how far each sees.
struct ShadowLimits {
  /// Per ray (beam b, elevation bin k; index b * elevation_bins + k, bin k centred at
  /// -half + (k + 0.5) step): the range of the nearest of its pixels that may hold a surface,
  /// or +inf.
  std::vector<float> first_return_m;
  int elevation_bins = 1;
  double elevation_step_rad = 0.0;  ///< 2 half / elevation_bins: at most setup's step
};

/// A pixel may hold a surface at an elevation where it is lit (after the threshold), bounds a
/// return above the keep level there (beam-aware) and its voxel is not carved in `map` (nor,
/// unless `unknown_may_hide`, unknown). The carving kernel leaves what lies behind
/// (VisibilityLimit). `pixels` is the thresholded CV_32F frame; `map`'s pages in the frame's
/// frustum must be held.
ShadowLimits shadowLimits(const cv::Mat& pixels, const Eigen::Isometry3d& T_world_sonar,
                          const VoxelMap& map, const CarvingGeometry& geometry,
                          const ShadowLimitSetup& setup, ThreadPool& pool);

}  // namespace sonarcarve
