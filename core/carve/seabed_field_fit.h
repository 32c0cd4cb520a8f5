// The seabed's relief fitted to the frames (docs/reconstruction.md, "A seabed with relief"):
// a heightfield (carve/seabed_heightfield.h) started from the planes each frame fitted, then
// moved so that its predicted images (the beam pattern, Lambert's law, the range bins: the
// prediction seabed-aware carving takes out of the pixels) match every frame that a seabed
// explains. Each point of the seabed is seen by many frames at many elevations, so the beam
// pattern's shape (its main lobe, nulls and side lobes) pins its depth where one frame's
// plane cannot follow the relief.
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "carve/seabed_heightfield.h"
#include "common/progress.h"
#include "common/thread_pool.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// A frame that a seabed plane explains, as the fit sees it.
struct SeabedFrame {
  Eigen::Isometry3d T_world_sonar = Eigen::Isometry3d::Identity();
  SeabedPlane plane;
};

/// The heightfield's grid (nodes every `cell_m`) over where the frames' beams meet their
/// planes inside the -3 dB aperture and the range window, each node the mean of those planes'
/// depths there weighted by the beam's power; nodes that no frame's main lobe reached stay
/// unknown.
SeabedHeightfield fuseSeabedPlanes(const std::vector<SeabedFrame>& frames, const SonarModel& sonar,
                                   double cell_m);

/// How far the relief departs from a frame's plane where the frame's main lobe meets it: the
/// root mean square of their depths' difference, weighted by the beam's power (0 where the
/// relief is not known there).
double reliefDeparture(const SeabedFrame& frame, const SeabedHeightfield& field,
                       const SonarModel& sonar);

/// How far a frame's pixels are from the surface's predicted image: on every fourth beam, each
/// beam's prediction scaled by its own least-squares gain (reflectance varies), pixels of
/// structure (over 3 times the scaled prediction within 2 bins) left out. `misfit` is the sum
/// of squared residuals over the sum of squared pixels.
struct SeabedMisfit {
  double residual = 0.0;
  double energy = 0.0;
  double misfit() const { return energy > 0.0 ? residual / energy : 0.0; }
};

/// The misfit of one frame and, where `gradient` is given (one value per node), adds to it the
/// gradient of the frame's misfit with respect to each node's depth: through the ranges at
/// which the rays' interval ends meet the relief (the return's spread over range bins is
/// differentiated exactly; cos(incidence) is held).
SeabedMisfit seabedFieldMisfit(const cv::Mat& pixels, const SeabedSurface& surface,
                               const Eigen::Isometry3d& T_world_sonar, const SonarModel& sonar,
                               std::vector<double>* gradient, ThreadPool* pool = nullptr);

struct SeabedFieldFitParams {
  int passes = 6;            ///< Gauss-Newton steps, each a pass over every frame
  double damping = 0.01;     ///< Levenberg-Marquardt: times each node's own curvature
  double smoothness = 0.01;  ///< membrane between neighbours, times the typical curvature
  double max_step_m = 0.1;   ///< a node moves at most this far in one step
  double max_move_m = 0.5;   ///< and this far from the fused planes' depth
};

struct SeabedFieldFitResult {
  double misfit_before = 0.0;  ///< over every frame, before the first step
  double misfit_after = 0.0;   ///< over every frame, before the last step
  std::size_t steps = 0;
  bool cancelled = false;
};

/// Moves the known nodes of `field` by Gauss-Newton steps (damped, with a membrane prior)
/// on the frames' squared residuals, each frame normalised by its energy. `pixels_of(n)` gives
/// frame n's pixels (empty: the frame is passed over). Reports "seabed relief" progress.
SeabedFieldFitResult fitSeabedField(SeabedHeightfield& field,
                                    const std::vector<SeabedFrame>& frames,
                                    const std::function<cv::Mat(std::size_t)>& pixels_of,
                                    const SonarModel& sonar, const SeabedFieldFitParams& params,
                                    ThreadPool* pool, Progress& progress);

}  // namespace sonarcarve
