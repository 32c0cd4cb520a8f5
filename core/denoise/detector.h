// Detectors that separate returns from noise in a polar frame, before carving:
//   none         the image as it is
//   ztest        the seed paper's per-pixel Z-test against a NoiseModel: a pixel is kept
//                where (I - mean) / stddev > z, else it is empty water; a kept pixel
//                carries its return's estimate: the median of its beam and the two beside
//                it at its range, less the noise's mean (at least 1 count)
//   cfar         cell-averaging CFAR along range, needing no empty-water recording: the
//                power I^2 of a cell is compared with alpha times the mean power of
//                `train` cells on each side beyond `guard` cells; alpha sets the false-alarm
//                rate for exponential (Rayleigh-amplitude) noise: alpha = N (Pfa^(-1/N) - 1)
// Thread safe: apply() may run concurrently.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "common/enum_names.h"
#include "denoise/noise_model.h"

namespace sonarcarve {

/// auto: ztest when a noise model is given, none otherwise.
enum class DetectorMode { Auto, None, ZTest, Cfar };
inline constexpr std::array<EnumName<DetectorMode>, 4> kDetectorModeNames{{
    {DetectorMode::Auto, "auto"},
    {DetectorMode::None, "none"},
    {DetectorMode::ZTest, "ztest"},
    {DetectorMode::Cfar, "cfar"},
}};
constexpr const auto& enumNamesOf(DetectorMode) {
  return kDetectorModeNames;
}

struct DetectorParams {
  // Defaults measured on the noisy riser demo (docs/denoising.md): with a 3 x 3 box filter,
  // z = 2 gave the best F-score; min-carving removes the false alarms a low z lets through
  // (noise must be lit in every view that sees a voxel), while a high z carves real
  // surfaces wherever one view's speckle dips.
  static constexpr double kDefaultZ = 2.0;
  static constexpr int kDefaultSmoothing = 3;
  DetectorMode mode = DetectorMode::Auto;
  double z = kDefaultZ;
  int cfar_guard = 3;      ///< cells on each side of the cell under test, skipped
  int cfar_train = 12;     ///< cells on each side beyond the guard, averaged
  double cfar_pfa = 0.05;  ///< false-alarm probability per cell (min-carving removes them)
  /// Side of the box filter applied before the test (1 = none): it averages the speckle of
  /// returns, so that one dark speckle does not carve a real surface. A noise model must
  /// have been learned with the same smoothing. The smoothing decides; it does not set the kept
  /// pixel's value.
  int smoothing = kDefaultSmoothing;

  bool needsNoiseModel() const { return mode == DetectorMode::ZTest; }
  /// `auto` made concrete for whether a noise model is available.
  DetectorParams resolved(bool have_noise_model) const;
  /// Throws Error on an unknown mode or a value out of range.
  void validate() const;
};

/// Whether a dark pixel of the frames out of this detector means that nothing returned there
/// (no detector ran: the frames' own zeros), rather than a return under the detection level.
inline bool darkPixelsAreExact(const DetectorParams& resolved) {
  return resolved.mode == DetectorMode::None;
}

class Detector {
 public:
  /// `model` is required by ztest (Error otherwise) and checked against
  /// `sonar`'s geometry.
  Detector(DetectorParams params, std::shared_ptr<const NoiseModel> model, const SonarModel& sonar);

  /// CV_32F output of the frame's size: kept intensities (0 = empty water).
  cv::Mat apply(const cv::Mat& image) const;
  const DetectorParams& params() const { return params_; }
  /// The CA-CFAR threshold factor for the parameters' training size and false-alarm rate.
  double cfarAlpha() const;
  /// ztest: the background's standard deviation per pixel before the box filter (the noise
  /// model's, over the filter's averaging: a box of w x w independent pixels divides it by
  /// w), CV_32F of the frame's size; empty for the other detectors.
  cv::Mat backgroundSigma() const;

 private:
  cv::Mat zTest(const cv::Mat& image) const;
  cv::Mat cfar(const cv::Mat& image) const;

  DetectorParams params_;
  std::shared_ptr<const NoiseModel> model_;
  cv::Mat threshold_;  // ztest: mean + z * stddev per pixel
};

}  // namespace sonarcarve
