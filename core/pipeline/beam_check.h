// Whether the frames show the returns the declared elevation beam puts past its -3 dB
// aperture. Beam-aware carving trusts a dark pixel out to the main lobe's first null (+-22.6
// degrees for a 20 degree sinc^2 beam): where the real beam has no energy past its aperture
// (a spec sheet's pattern is a prior, not a fact), every surface seen there is carved away and
// the map comes out empty. The check reads, for points of a first surface carved inside the
// aperture only, each view's pixel at the point against what the declared beam predicts from
// the point's return near the axis, over the tail band between the aperture's edge and the
// first null; it counts only views whose predicted return would stand out of the background.
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/frame_stage.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

struct BeamTailCheck {
  std::size_t points = 0;   ///< surface points with a return near the axis
  std::size_t samples = 0;  ///< (point, view) pairs in the tail band that count
  /// The upper quartile over those pairs of the measured return over the declared beam's
  /// prediction.
  double tail_ratio = 1.0;
  double band_lo_rad = 0.0;  ///< the tail band's elevations
  double band_hi_rad = 0.0;
  /// False when the tails are missing: at least kBeamCheckMinSamples pairs and a ratio under
  /// kMissingTailRatio.
  bool tails_present = true;
};

/// The quantile of the pairs' ratios the check reads: the upper quartile, because the first
/// surface holds ghosts (points no structure stands at, from too few views), whose tails are
/// dark whatever the beam: they pull the median of a beam as declared under -100 dB on the
/// first 12 frames of the riser's descent.
inline constexpr double kTailQuantile = 0.75;
/// The tails count as missing under 0.02 (-17 dB) of the declared beam's power. The upper
/// quartile measured, for a beam as declared: -9.7 dB (the riser's first 12 frames) to +9.1 dB
/// (docs/validation.md: riser, noisy and coherent riser, orbits, jacket node, manifold, seabed);
/// for a beam without tails, -25.5 dB or less. Beam-aware carving carves away a surface whose real
/// beam falls 20 dB (its dynamic range) under the declared one.
inline constexpr double kMissingTailRatio = 0.02;
inline constexpr std::size_t kBeamCheckMinSamples = 200;

/// `points_world`: a first surface; `frames` the views, `excess(i)` frame i's image (power)
/// less the background's mean (nullopt: not read); `floor` per pixel the background's standard
/// deviation (empty: none; the sonar's dark level then).
BeamTailCheck checkBeamTails(const std::vector<Eigen::Vector3f>& points_world,
                             const std::vector<PosedFrame>& frames,
                             const std::function<std::optional<cv::Mat>(std::size_t)>& excess,
                             const SonarModel& sonar, const cv::Mat& floor);

/// The run's choice "elevation beam", from the check.
RunChoice beamTailChoice(const BeamTailCheck& check);

}  // namespace sonarcarve
