// Seabed explanation: what a flat seabed puts into a frame through the whole elevation beam,
// so that the water over it can be carved.
//
// A flat seabed fills the beam's main lobe at every range it spans, so every voxel of water
// within about a quarter of the sonar's height above it shares a lit pixel with it in every
// view: no rule on a voxel's own bound can carve it (docs/validation.md, "A seabed survey").
// Given the seabed's plane, the frame's image of it is predicted from the beam pattern and
// Lambert's law, scaled to the frame, and taken out of the pixels: what is left bounds the
// other voxels on each arc. The seabed itself (and what lies under it) is left to the views,
// through a visibility limit along each ray.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "common/thread_pool.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// A plane of the seabed, world NED: points x with normal.dot(x) = offset, normal pointing up
/// into the water (its z negative).
struct SeabedPlane {
  Eigen::Vector3d normal{0.0, 0.0, -1.0};
  double offset = -20.0;
  static SeabedPlane level(double depth_m) { return {Eigen::Vector3d(0, 0, -1), -depth_m}; }
  /// depth = depth_m + slope_north (north - at.x) + slope_east (east - at.y).
  static SeabedPlane sloped(const Eigen::Vector3d& at, double depth_m, double slope_north,
                            double slope_east);
  /// Its depth under a horizontal position (north, east).
  double depthAt(double north, double east) const;
};

struct SeabedSurface;  // carve/seabed_heightfield.h: a plane and, where known, the relief

/// The seabed's image in one frame, up to a scale: per pixel, the sum over elevation of the
/// beam's power, the ray's solid angle and cos(incidence) for the rays that meet the plane in
/// that pixel's range bin and beam. CV_32F, the sonar's rows x cols.
/// Its beams run on `pool` where given.
cv::Mat predictSeabedImage(const SeabedPlane& plane, const Eigen::Isometry3d& T_world_sonar,
                           const SonarModel& sonar, ThreadPool* pool = nullptr);
/// The same over a seabed with relief where it is known.
cv::Mat predictSeabedImage(const SeabedSurface& surface, const Eigen::Isometry3d& T_world_sonar,
                           const SonarModel& sonar, ThreadPool* pool = nullptr);

/// The range along a ray (sonar frame, unit `direction`) at which it meets the plane, or +inf.
double seabedRange(const SeabedPlane& plane, const Eigen::Isometry3d& T_world_sonar,
                   const Eigen::Vector3d& direction_sonar);

/// The plane that best explains a frame and how well: the normalised correlation of the
/// frame's pixels with the plane's predicted image, over every fourth beam, leaving out the
/// pixels the plane does not explain (structure over 1.5 times its prediction, shadows under
/// two thirds of it).
struct SeabedFit {
  SeabedPlane plane;
  double correlation = 0.0;  ///< in [0, 1]; 0: no plane meets the beam in range
  /// Behind a detector (fitSeabedInNoise): the matched filter's signal to noise, the
  /// prediction's weighted projection over its noise (0 for fitSeabed).
  double significance = 0.0;
  bool explains = false;  ///< whether the plane explains the frame (SeabedTracker's test)
};

/// Fits a plane to one frame: from `prior` (the previous frame's plane) by a pattern search of
/// its depth and slopes, moving at most 2 cm and 0.11 degree, or with no prior by a scan of
/// level planes under the sonar first. Beams run on `pool` where given.
SeabedFit fitSeabed(const cv::Mat& pixels, const Eigen::Isometry3d& T_world_sonar,
                    const SonarModel& sonar, const SeabedFit* prior, ThreadPool* pool = nullptr);

/// A frame before its detector, for fitting a seabed behind one: its pixels less the noise
/// model's mean (signed, CV_32F) and the background's standard deviation per pixel. A seabed
/// is often under the detection level pixel by pixel (the manifold's: 10 to 20 counts under a
/// background of 80), so the detector's output holds sparse false alarms of it; the frame as
/// a whole still holds it far above the noise.
struct BeforeDetection {
  cv::Mat excess;
  cv::Mat sigma;
};

/// Whether `before` holds a frame before its detector (a Z-test ran): empty otherwise.
inline bool behindDetector(const BeforeDetection* before) {
  return before != nullptr && !before->excess.empty();
}

/// Fits a plane to a frame with a background: the plane that maximises the matched filter's
/// signal to noise (the excess weighted by 1 / sigma^2, clipped at 3 sigma so that bright
/// structure does not pull it), with the same search and bounds as fitSeabed. It explains the
/// frame when the signal to noise is at least kMinSignificance and its amplitude, fitted
/// over each of 16 cells on its own (an eighth of the fan's beams, its near or far half of
/// the prediction), agrees with the whole's: a seabed spans the fan and its ranges, structure
/// that a plane happens to cross does not.
SeabedFit fitSeabedInNoise(const BeforeDetection& frame, const Eigen::Isometry3d& T_world_sonar,
                           const SonarModel& sonar, const SeabedFit* prior,
                           ThreadPool* pool = nullptr);

/// What the seabed's predicted image leaves of `pixels` (>= 0), the prediction scaled by the
/// median ratio of lit pixels to it where it is strong. Each pixel may hold up to `headroom`
/// times the largest prediction within `slack_bins` range bins of it (the fit's error in
/// range) and be the seabed's alone.
cv::Mat explainSeabed(const cv::Mat& pixels, const cv::Mat& predicted, int slack_bins,
                      double headroom);

/// Where the seabed lies along a frame's rays: for ray (beam b, elevation bin k of `bins`,
/// bin k centred at -half + (k + 0.5) step; index b * bins + k), the ranges between which a
/// voxel may hold the seabed (`voxel_size` either side of the plane along the ray), +inf
/// where the ray misses it.
struct SeabedBands {
  std::vector<float> from;
  std::vector<float> to;
  std::vector<float> doubt_from;  ///< from, less `doubt_m` over the plane along the ray
};
SeabedBands seabedBands(const SeabedPlane& plane, const Eigen::Isometry3d& T_world_sonar,
                        const SonarModel& sonar, int bins, double half, double step,
                        double voxel_size, double doubt_m = 0.0);
/// The same over a seabed with relief where it is known (the band's width along each ray from
/// the relief's own normal there).
SeabedBands seabedBands(const SeabedSurface& surface, const Eigen::Isometry3d& T_world_sonar,
                        const SonarModel& sonar, int bins, double half, double step,
                        double voxel_size, double doubt_m = 0.0);

/// Follows the seabed from frame to frame: each frame's plane is fitted from the last one's,
/// or, while none is found, scanned for afresh every few frames.
class SeabedTracker {
 public:
  /// A plane explains a frame where its prediction correlates with the pixels this well: a
  /// noise-free seabed gives 0.92 to 0.99 over the manifold's survey (its objects and their
  /// shadows are what it misses), a frame with no seabed in view under 0.3.
  static constexpr double kMinCorrelation = 0.8;
  /// Behind a detector, a plane explains a frame where the matched filter's signal to noise
  /// is at least this. Over background alone it is a standard normal at any one plane, and
  /// the search's best stays under 5 (the noisy riser's and jacket node's frames, no seabed in
  /// view: at most 4.3); the manifold's seabed gives 19 to 26.
  static constexpr double kMinSignificance = 8.0;
  /// While no seabed is found, every this many frames are scanned for one.
  static constexpr int kScanEvery = 8;

  /// This frame's seabed, if one explains it.
  /// With `before` (a detector ran), the plane is fitted to the frame before it, and a frame
  /// it does not explain keeps the last plane as the prior for up to kScanEvery frames.
  std::optional<SeabedPlane> track(const cv::Mat& pixels, const Eigen::Isometry3d& T_world_sonar,
                                   const SonarModel& sonar, ThreadPool* pool = nullptr,
                                   const BeforeDetection* before = nullptr);
  /// Frames a seabed explained so far.
  std::size_t framesFound() const { return found_; }

 private:
  std::optional<SeabedFit> last_;
  int since_scan_ = 0;
  int misses_ = 0;
  std::size_t found_ = 0;
};

}  // namespace sonarcarve
