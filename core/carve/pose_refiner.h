// PoseRefiner: measures where a frame sits against a COMPLETE map, carved from every frame of
// the mission (issue 15; the carving stage's post-processing refinement,
// pipeline/track_refinement.h). Minimum carving needs every view to agree to the voxel: a
// frame placed a centimetre off by drifting navigation carves true surface away.
// The refiner predicts the frame's leading edges from the map: for a candidate pose, each
// beam's nearest shell voxel (occupied, with a face neighbour that is not) inside the carved
// elevation lobe is where that beam's first return should begin. It compares them with the
// frame's measured leading edges (the first lit range bin of each beam), two-sided: the cost
// is the sum over beams of the squared difference, capped at a robust scale (the map's
// expected error), and a beam where only one of the two has a return costs the cap (a
// structure's silhouette across the beams). The search is a pattern search over the three
// position axes (world) and the three rotations about the sonar's own axes, coarse to fine,
// inside a bounded window around the navigation. Its result is a measurement: the best
// correction and its information (how sharply the cost rises around it, per axis and between
// axes: a direction the frame does not observe, down along a vertical pipe, gets none), which
// the track smoother (carve/track_smoother.h) combines over all frames.
// The map must not change while the refiner lives; one measure() at a time (its costs run on
// the pool).
#pragma once

#include <Eigen/Geometry>
#include <limits>
#include <opencv2/core.hpp>
#include <vector>

#include "carve/carve_params.h"
#include "carve/carving_geometry.h"
#include "carve/voxel_map.h"
#include "common/angles.h"
#include "common/thread_pool.h"

namespace sonarcarve {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct PoseRefinementParams {
  /// Whether the carving stage refines poses at all. Off by default: it improves drifted
  /// missions but costs 0.005 F on the riser and 0.033 on the jacket node without drift
  /// (docs/navigation.md).
  bool enabled = false;
  /// The search window around the navigation, on each axis: no refined pose leaves it.
  double max_translation_m = 0.5;
  double max_rotation_rad = degToRad(5.0);
  /// The navigation's error model, a random walk: how far it is expected to drift from one
  /// frame to the next (one standard deviation, on each axis).
  double step_sigma_m = 0.02;
  double step_sigma_rad = degToRad(0.2);
  /// The first alignment map is carved from frames whose lit returns are widened by this much
  /// in range and across beams, so that true surface survives views this far off each other:
  /// about 2.5 times the relative drift of the frames that see one voxel (a 1 cm random walk
  /// over the ~36 frames 10 cm apart that see a voxel 4.5 m off inside the main lobe: 6 cm).
  double first_pass_tolerance_m = 0.16;
  /// Alignment passes (carve, align every frame, smooth the track), before the final carving.
  int passes = 2;
  /// Fewer shell voxels in view: the frame gives no measurement (the track carries it).
  std::size_t min_voxels = 200;
  /// At most this many shell voxels are scored (evenly thinned beyond).
  std::size_t max_voxels = 20000;
  /// Only shell voxels inside +-aperture/2 of at least this many frames predict edges
  /// (keepVoxelsSeenBy), as occlusion resolution takes surface points only among voxels that
  /// many frames see.
  std::size_t min_views = 5;
};

/// The correction of one frame: its sonar's position moved by `translation_world_m` and its
/// attitude turned by `rotation_sonar_rad` (roll, pitch, yaw about the sonar's own x, y, z).
struct PoseCorrection {
  Eigen::Vector3d translation_world_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation_sonar_rad = Eigen::Vector3d::Zero();
  bool aligned = false;    ///< false: no measurement (too few voxels or no agreement)
  std::size_t voxels = 0;  ///< shell voxels scored
  /// Agreement of the frame with the map: 1 - the mean over beams with a return of the squared
  /// difference of predicted and measured leading edges, capped, over the cap (1: every edge
  /// predicted exactly); at the navigation's pose and at the chosen correction.
  double score_before = 0.0;
  double score_after = 0.0;

  Eigen::Isometry3d applied(const Eigen::Isometry3d& T_world_sonar_prior) const;
  Vector6d vector() const;
  static PoseCorrection of(const Vector6d& x);
};

/// How far the frames that carved the map had their lit returns widened (grey dilation): a
/// frame's measured leading edges are widened alike before they are compared with it.
struct EdgeWidening {
  int bins = 0;   ///< range bins nearer
  int beams = 0;  ///< beams either side
};

/// One frame against the map: the best correction in the window and its information (the
/// inverse covariance; metres and radians; positive semi-definite, zero when not aligned).
struct PoseMeasurement {
  PoseCorrection correction;
  Matrix6d information = Matrix6d::Zero();
};

class PoseRefiner {
 public:
  /// Gathers the map's shell voxels once. Throws Error on a negative window.
  PoseRefiner(const VoxelMap& map, const SonarModel& sonar, const CarveParams& carve,
              PoseRefinementParams params, ThreadPool& pool);

  /// Where the frame (CV_32F, the sonar's rows x cols, as given to the carver) seen from the
  /// navigation's `T_world_sonar_nav` best meets the map, searched from `start` (a correction
  /// of the navigation) with residuals capped at `scale_m` (the map's expected error); never
  /// outside the window. `widening`: that of the frames that carved the map.
  PoseMeasurement measure(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar_nav,
                          const Vector6d& start, double scale_m,
                          const EdgeWidening& widening = {}) const;
  /// The cost per beam with a return of `correction` (what measure() minimises, for tests).
  double meanCostOf(const cv::Mat& image, const Eigen::Isometry3d& T_world_sonar_nav,
                    const PoseCorrection& correction, double scale_m) const;
  /// Behind a detector: per pixel (CV_32F, the sonar's rows x cols), the level over which a
  /// pixel of a measured frame is taken for a return, and over which a voxel's value times
  /// the beam's power predicts one (never under the carving's own level). A detector lets some
  /// background through; a leading edge must stand clear of it, or every beam begins at a
  /// false alarm. With a level a frame must also agree with the map in more of its beams to
  /// be measured. Empty (the default): the carving's level alone.
  void setEdgeLevel(cv::Mat level);
  /// Keeps only the shell voxels that at least `params.min_views` of the frames placed at
  /// `T_world_sonar` see inside +-aperture/2 (the range window and the field of view).
  void keepVoxelsSeenBy(const std::vector<Eigen::Isometry3d>& T_world_sonar);
  /// A correction clamped into the window.
  Vector6d clamped(Vector6d x) const;
  std::size_t shellVoxels() const { return shell_.size(); }

 private:
  static constexpr float kNoReturn = std::numeric_limits<float>::infinity();
  /// Range of each beam's first return (near edge of its first lit bin), kNoReturn where the
  /// beam is dark or near the fan's edges; widened as `widening` says.
  std::vector<float> leadingEdges(const cv::Mat& image, const EdgeWidening& widening) const;
  /// Shell voxels inside the view from `T_world_sonar` (with margins) and no deeper than
  /// `keep_behind_m` behind the nearest of their beam, in the frame of `T_world_frame`.
  std::vector<Eigen::Vector4f> voxelsInView(const Eigen::Isometry3d& T_world_sonar,
                                            const Eigen::Isometry3d& T_world_frame,
                                            double keep_behind_m) const;
  double keepBehind(double scale_m) const;
  /// The intensity over which a pixel is lit, as carving keeps it.
  float litLevel() const;
  /// Sum over beams of the squared difference between predicted and measured leading edges,
  /// each capped at scale^2 (a beam where only one has a return costs scale^2).
  double cost(const std::vector<float>& measured, const std::vector<Eigen::Vector4f>& q_sonar,
              const Eigen::Isometry3d& T_world_sonar_nav, const Vector6d& x, double scale_m) const;

  CarvingGeometry geometry_;
  CarveParams carve_;
  PoseRefinementParams params_;
  ThreadPool& pool_;
  double voxel_size_m_;
  std::vector<Eigen::Vector3f> shell_;  // world
  std::vector<float> shell_values_;     // their on-axis values
  static constexpr std::size_t kPowerTable = 1024;
  std::vector<float> power_;  // the beam's power over |sin(elevation)|
  float max_sin_elevation_ = 0.0f;
  cv::Mat edge_level_;  // per pixel, at least litLevel(); empty: litLevel() everywhere
};

}  // namespace sonarcarve
