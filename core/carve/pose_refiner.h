// PoseRefiner: aligns each frame to the map carved so far, before the frame carves it (issue
// 15). Minimum carving needs every view to agree to the voxel: a frame placed a centimetre
// off by drifting navigation carves true surface away. The refiner scores a candidate pose by
// where the map's settled voxels (occupied, observed by several views from both sides of their
// axes, so that the sonar's axis has passed over them, well inside the view at the
// search's start: the same voxels for every candidate) fall in the frame:
//   +1 on a lit pixel at the leading edge of a return (the first lit range bins after dark
//      water along the beam: where a surface facing the sonar shows itself),
//   -1 on the dark pixels just before a leading edge (water in front of a surface),
//    0 elsewhere: deeper in a return (the far part of an elevation arc) and in dark water
//      away from any return (where the map's ghosts lie, which this frame will carve: they
//      must not pull the frame to where they would be lit),
// smoothed over a range bin, and searches a bounded window around the
// navigation prior for the best score: a pattern search over the three position axes (world)
// and the three rotations about the sonar's own axes, coarse to fine (two voxels to half a
// voxel). The prior along the track: each frame starts from the previous frame's correction
// (navigation drifts as a random walk) and pays for every change from it in proportion to its
// square over the expected drift per frame. A frame with too few settled voxels in view keeps the
// carried correction. Works on the fast engine's VoxelMap; not thread safe (the carving stage calls
// it between frames), the scoring runs on the pool.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "carve/carve_params.h"
#include "carve/carving_geometry.h"
#include "carve/voxel_map.h"
#include "common/angles.h"
#include "common/thread_pool.h"

namespace sonarcarve {

struct PoseRefinementParams {
  /// Whether the carving stage refines poses at all. Experimental, off by default: on the
  /// simulated drifted missions it does not yet beat carving at the navigation's poses
  /// (docs/navigation.md).
  bool enabled = false;
  /// The search window around the navigation prior, on each axis.
  double max_translation_m = 0.5;
  double max_rotation_rad = degToRad(5.0);
  /// The prior along the track: how far navigation is expected to drift from one frame to
  /// the next (one standard deviation, on each axis).
  double step_sigma_m = 0.02;
  double step_sigma_rad = degToRad(0.2);
  /// A voxel takes part once this many views (at most 63) have observed it, from both sides
  /// of their axes, and it is still occupied.
  int settled_views = 8;
  /// Fewer settled voxels in view: the frame is not aligned (it keeps the carried correction).
  std::size_t min_settled_voxels = 200;
  /// At most this many settled voxels are scored (evenly thinned beyond).
  std::size_t max_voxels = 30000;
};

/// The correction of one frame: its sonar's position moved by `translation_world_m` and its
/// attitude turned by `rotation_sonar_rad` (roll, pitch, yaw about the sonar's own x, y, z).
struct PoseCorrection {
  Eigen::Vector3d translation_world_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation_sonar_rad = Eigen::Vector3d::Zero();
  bool aligned = false;       ///< false: too few settled voxels in view; carried over
  std::size_t voxels = 0;     ///< settled voxels scored
  double score_before = 0.0;  ///< score per scored voxel at the carried correction
  double score_after = 0.0;   ///< at the chosen one

  Eigen::Isometry3d applied(const Eigen::Isometry3d& T_world_sonar_prior) const;
};

class PoseRefiner {
 public:
  PoseRefiner(const VoxelMap& map, const SonarModel& sonar, const CarveParams& carve,
              PoseRefinementParams params, ThreadPool& pool);

  /// The correction of a frame (CV_32F, the sonar's rows x cols, as given to the carver) seen
  /// from `T_world_sonar_prior`, starting from the previous frame's correction; never outside
  /// the window.
  PoseCorrection refine(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar_prior);
  /// The score per voxel of `correction` for a frame: the voxels are those well inside the
  /// view from the prior (what refine() maximises, for diagnostics and tests).
  double scoreOf(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar_prior,
                 const PoseCorrection& correction) const;

 private:
  struct Candidate {
    Eigen::Matrix<double, 6, 1> x;  // translation (world), rotation (sonar axes)
    double score = 0.0;
  };
  cv::Mat edgeField(const cv::Mat& image) const;
  /// Settled voxels well inside the view from `T_world_sonar`, in the frame of `T_world_frame`.
  std::vector<Eigen::Vector3f> settledVoxels(const Eigen::Isometry3d& T_world_sonar,
                                             const Eigen::Isometry3d& T_world_frame) const;
  double score(const cv::Mat& field, const std::vector<Eigen::Vector3f>& q_sonar,
               const Eigen::Isometry3d& T_world_sonar_prior,
               const Eigen::Matrix<double, 6, 1>& x) const;
  Eigen::Matrix<double, 6, 1> clamped(Eigen::Matrix<double, 6, 1> x) const;

  const VoxelMap& map_;
  CarvingGeometry geometry_;
  CarveParams carve_;
  PoseRefinementParams params_;
  ThreadPool& pool_;
  Eigen::Matrix<double, 6, 1> carried_ = Eigen::Matrix<double, 6, 1>::Zero();
};

}  // namespace sonarcarve
