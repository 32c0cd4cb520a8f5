// BearingDeblur: undoes the blur of a sonar's beams across bearing.
//
// A real sonar's beams are wider than their spacing (an Oculus M750d or a BlueView: about
// 1 degree wide, 0.2 to 0.25 degree apart), so each row of an image is the scene's returns
// across bearing convolved with the beam's power pattern: a bright structure lights the beams
// beside it, down to its pattern's nulls and side lobes. No view of a vertical track carves
// that halo (every view has the same bearings), and the keep level does not remove it (the
// main lobe's skirt lies within 20 dB of the peak). The blur is known from the beam's width,
// so it is taken out of each row by Richardson-Lucy deconvolution with the sinc^2 pattern,
// which keeps the image non-negative and an extended surface as bright as it was.
//
// Two kinds of frames:
//   exact dark pixels (no noise, no detector): every pixel is data, a dark one included;
//   behind a detector: a dark pixel is unknown (a return under the detection level may lie
//     there), so only lit pixels are fitted and dark ones stay dark. Speckle on the returns
//     is sharpened by each iteration too, so fewer are run (docs/validation.md, "Beams wider
//     than their spacing").
// The pattern is sampled at the table's median beam spacing (non-uniform tables are taken as
// uniform at that spacing). Thread safe: apply() may run concurrently.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "sonar/sonar_model.h"

namespace sonarcarve {

/// The blur across bearing of beams `width_rad` wide (-3 dB, sinc^2) and `spacing_rad` apart:
/// weights from beam -half to +half (half at most `max_half`), each the pattern's mean over
/// that beam's interval, summing to 1.
std::vector<float> bearingBlurKernel(double width_rad, double spacing_rad, int max_half);

class BearingDeblur {
 public:
  /// Richardson-Lucy iterations for frames with exact dark pixels and behind a detector.
  static constexpr int kExactIterations = 30;
  static constexpr int kDetectedIterations = 5;

  explicit BearingDeblur(const SonarModel& sonar);

  /// Whether the sonar's beams blur the image: a declared width whose pattern puts more than
  /// 10 % of a beam's power into its neighbours. Otherwise apply() returns the image as it is.
  bool active() const { return !kernel_.empty(); }
  /// The pattern's weights from beam -half() to +half(), summing to 1 (empty if inactive).
  const std::vector<float>& kernel() const { return kernel_; }
  int half() const { return static_cast<int>(kernel_.size() / 2); }

  /// What it does to a mission's frames, in words for logs and reports.
  std::string describe(bool exact_dark) const;
  /// The CV_32F frame with the blur taken out. `exact_dark`: dark pixels are data (see above).
  cv::Mat apply(const cv::Mat& image, bool exact_dark) const;

 private:
  std::vector<float> kernel_;
  double width_rad_ = 0.0;
  double spacing_rad_ = 0.0;
  // Exact frames: the sonar's whole counts read 0 under half a count (its intensity scale's
  // dark power), so the deconvolution's residue there is dark. Left lit, it let every frame
  // carve to the main lobe's edge (docs/benchmarks.md).
  float dark_power_ = 0.5f;
};

}  // namespace sonarcarve
