// MapFit: the model-based fit of a map to the frames (issue 41; docs/model.md, "The fit").
// Starting from the carved band (fit/initial_grid.h), it adjusts every band voxel's occupancy
// logit and reflectance so that the forward model (model/forward_model.h) predicts the
// observed frames, by maximum likelihood under fully developed speckle (exponential intensity
// about the predicted mean, model/speckle_likelihood.h). The sonar's gain is set once from
// the frames' energy; the background per range bin starts from the noise model's mean, raised
// to a floor so that every predicted mean is positive; the elevation profile starts from the
// declared beam; both are then fitted with the map (fit/beam_background_fit.h). Optimiser: Adam,
// one step every few frames, the learning rate falling over the passes; reflectance is fitted as
// its logarithm, so it stays positive.
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "common/progress.h"
#include "common/thread_pool.h"
#include "fit/initial_grid.h"
#include "fit/map_fit_params.h"
#include "model/elevation_profile.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

struct MapFitFrame {
  std::size_t index = 0;  ///< in the mission
  Eigen::Isometry3d T_world_sonar = Eigen::Isometry3d::Identity();
};

/// A frame's image (CV_32F power, the sonar's rows x cols) by its index in the mission.
using FrameImageLoader = std::function<cv::Mat(std::size_t index)>;

/// How well the map explains the frames, on up to 16 frames spread over the mission.
struct FitPassFigures {
  double nll_per_pixel = 0.0;  ///< mean speckle NLL per pixel
  /// Sum of |observed - predicted| over the sum of |observed - background|: the share of the
  /// frames' returns the map does not explain (0: all of it).
  double unexplained = 0.0;
};

struct MapFitSummary {
  double gain = 1.0;
  /// The elevation profile declared (the start) and fitted (the same when not fitted).
  std::optional<ElevationProfile> declared_profile;
  std::optional<ElevationProfile> fitted_profile;
  /// Mean background per range bin at the start (the noise model's, floored) and fitted.
  double declared_background = 0.0;
  double fitted_background = 0.0;
  double background_floor = 0.0;
  std::size_t band_voxels = 0;
  FitPassFigures before;  ///< the carved band as it started
  FitPassFigures after;   ///< the fitted band
};

/// The elevation profile the fit starts from: the sonar's declared beam (sinc^2 with its first
/// side lobes for a main-lobe sonar, the main lobe alone for a clipped one).
ElevationProfile declaredProfile(const SonarModel& sonar);

class MapFit {
 public:
  /// `sonar` and `pool` must outlive the fit.
  MapFit(const SonarModel& sonar, MapFitParams params, ThreadPool& pool);

  /// Fits `fit`'s band to `frames`; `background` has one value per range bin (empty: none).
  /// Reports progress as "fit"; throws Cancelled when it is cancelled.
  MapFitSummary run(FitGrid& fit, const std::vector<MapFitFrame>& frames,
                    const FrameImageLoader& load, std::vector<double> background,
                    Progress& progress) const;

 private:
  const SonarModel& sonar_;
  MapFitParams params_;
  ThreadPool& pool_;
};

}  // namespace sonarcarve
